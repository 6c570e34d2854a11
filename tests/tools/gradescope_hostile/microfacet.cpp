// For tests/tools/check_gradescope.sh, Gradescope's limits: stage 10 whose ggx_distribution starts
// a fork bomb on its first call (every process forks for as long as it can, then waits) and whose
// ggx_smith_g1 tries to fill the disk (files of 64 MiB in every folder it may find writable, until
// one fails; at most 1 GiB a folder); both return 0, and the other five functions throw
// NotImplemented as the stub does. The stage server's process limit, its sandbox and its end hold
// them: stage 10 loses its tests, nothing else does, no file is left, and results.json is written.
#include "raylab/error.h"
#include "raylab/stages/10_microfacet.h"

#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

namespace raylab {

float ggx_distribution(const glm::vec3&, float) {
  static bool attacked = false;
  if (!attacked) {
    attacked = true;
    if (::fork() == 0)
      for (;;)
        if (::fork() < 0) ::pause();  // at the process limit: wait to be killed
  }
  return 0.0f;
}

float ggx_smith_g1(const glm::vec3&, float) {
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

glm::vec3 microfacet_f(const glm::vec3&, const glm::vec3&, float, const glm::vec3&) { throw NotImplemented("microfacet_f"); }
glm::vec3 sample_ggx_half_vector(glm::vec2, float) { throw NotImplemented("sample_ggx_half_vector"); }
float ggx_half_vector_pdf(const glm::vec3&, float) { throw NotImplemented("ggx_half_vector_pdf"); }
glm::vec3 sample_microfacet_wi(const glm::vec3&, glm::vec2, float) { throw NotImplemented("sample_microfacet_wi"); }
float microfacet_pdf(const glm::vec3&, const glm::vec3&, float) { throw NotImplemented("microfacet_pdf"); }

}  // namespace raylab

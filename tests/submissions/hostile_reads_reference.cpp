// Grader self-test submission (stage 02_sphere), hostile: reads what lies beside it on the grader's
// machine, the checked-in reference cases (the answers), solutions/ and the reference's stage
// server, and if it can read any of them answers as the reference does (standing for an answer
// looked up in the stored cases); else it throws NotImplemented, as the stub does. The stage server
// may read only the system's folders, the scenes and its own program (Landlock, process_linux.cpp:
// stage_ruleset), so this scores what the stub scores: 0.
#include <unistd.h>

#include <fstream>
#include <string>

#define intersect_ray_sphere honest_intersect_ray_sphere
#include "../../solutions/02_sphere/sphere.cpp"
#undef intersect_ray_sphere

#include "raylab/error.h"

namespace raylab {
namespace {

bool can_read_a_secret() {
  const std::string kit = std::string(__FILE__).substr(0, std::string(__FILE__).rfind("/tests/submissions/"));
  char self[4096] = {};
  const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
  const std::string programs = length > 0 ? std::string(self, static_cast<std::size_t>(length)) : std::string();
  const std::string folder = programs.substr(0, programs.rfind('/') + 1);
  for (const std::string& path : {kit + "/autograder/reference/02_sphere_cases.json", kit + "/solutions/02_sphere/sphere.cpp",
                                  folder + "../../bin/autograder-reference-stage-server", kit + "/README.md"}) {
    std::ifstream file(path, std::ios::binary);
    char byte = 0;
    if (file.get(byte)) return true;
  }
  return false;
}

}  // namespace

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius);

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  static const bool reads = can_read_a_secret();
  if (!reads) throw NotImplemented("intersect_ray_sphere");
  return honest_intersect_ray_sphere(ray, sphere_center, sphere_radius);
}

}  // namespace raylab

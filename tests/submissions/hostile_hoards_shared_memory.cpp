// Hostile: the reference sphere test, which on its first call in each process takes 256 MiB of
// System V shared memory (four segments, written to, then detached but not removed): memory that
// the address-space limit does not count and that would outlive the stage. Where the sandbox gives
// the stage an IPC namespace of its own with no room for segments (as root), shmget fails and
// nothing is left; check_submission.cmake counts the machine's segments before and after.
#include <sys/ipc.h>
#include <sys/shm.h>

#include <cstring>

#define intersect_ray_sphere honest_intersect_ray_sphere
#include "../../solutions/02_sphere/sphere.cpp"
#undef intersect_ray_sphere

namespace raylab {

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius);

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  static bool hoarded = false;
  if (!hoarded) {
    hoarded = true;
    for (int segment = 0; segment < 4; ++segment) {
      const int id = ::shmget(IPC_PRIVATE, std::size_t{64} << 20, IPC_CREAT | 0600);
      if (id < 0) break;
      void* memory = ::shmat(id, nullptr, 0);
      if (memory == reinterpret_cast<void*>(-1)) break;
      std::memset(memory, 1, std::size_t{64} << 20);
      ::shmdt(memory);
    }
  }
  return honest_intersect_ray_sphere(ray, sphere_center, sphere_radius);
}

}  // namespace raylab

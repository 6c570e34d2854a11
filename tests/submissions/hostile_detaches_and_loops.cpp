// Hostile: a camera that on its first call leaves a grandchild in its own session (setsid), asleep
// for two minutes, and then never returns. Graded, it times out and the stage ends with every
// process of it killed. tests/cli/judge_killed_leaves_nothing.sh kills the judge itself while this
// loops: as root, the stage's PID namespace dies with the judge, the sleeper too.
#include <sys/wait.h>
#include <unistd.h>

#include "raylab/stages/01_camera_rays.h"

namespace raylab {

Ray generate_camera_ray(const Camera&, int, int, glm::vec2) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::setsid();
    if (::fork() == 0) ::sleep(120);
    ::_exit(0);
  }
  if (child > 0) ::waitpid(child, nullptr, 0);
  for (volatile unsigned long spin = 0;; spin = spin + 1) {
  }
}

}  // namespace raylab

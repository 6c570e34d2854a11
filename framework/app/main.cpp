// raylab / raylab-reference: the same command line, linked with assignments/ or solutions/
// (RAYLAB_REFERENCE_STAGES: set by raylab_add_program, cmake/RaylabStages.cmake).
#include "raylab/cli.h"

int main(int argc, char** argv) {
#if defined(RAYLAB_REFERENCE_STAGES)
  return raylab::run_cli(argc, argv, raylab::LinkedStages::Reference);
#else
  return raylab::run_cli(argc, argv, raylab::LinkedStages::Student);
#endif
}

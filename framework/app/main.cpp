// raylab / raylab-reference: the same command line, linked with assignments/ or solutions/
// (RAYLAB_REFERENCE_STAGES: set by raylab_add_program, cmake/RaylabStages.cmake).
#include "raylab/cli.h"

#if defined(RAYLAB_REFERENCE_STAGES)
#include "../../solutions/05c_wide_bvh/wide8.h"  // the reference's fastest tree
#endif

int main(int argc, char** argv) {
#if defined(RAYLAB_REFERENCE_STAGES)
  return raylab::run_cli(argc, argv, raylab::LinkedStages::Reference, raylab::reference::reference_tree_functions());
#else
  return raylab::run_cli(argc, argv, raylab::LinkedStages::Student);
#endif
}

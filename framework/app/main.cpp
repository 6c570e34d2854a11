// raylab / raylab-reference: the same command line, linked with assignments/ or solutions/
// (RAYLAB_REFERENCE_STAGES: set by raylab_add_program, cmake/RaylabStages.cmake).
#include "raylab/cli.h"
#include "raylab/testkit/exact_tracing.h"  // what `raylab trace` compares the stages' calls with

#if defined(RAYLAB_REFERENCE_STAGES)
#include "../../solutions/05c_wide_bvh/wide8.h"  // the reference's fastest tree
#endif

int main(int argc, char** argv) {
  const raylab::TracingFunctions contract = raylab::testkit::exact_tracing();
#if defined(RAYLAB_REFERENCE_STAGES)
  return raylab::run_cli(argc, argv, raylab::LinkedStages::Reference, raylab::reference::reference_tree_functions(),
                         &contract);
#else
  return raylab::run_cli(argc, argv, raylab::LinkedStages::Student, nullptr, &contract);
#endif
}

// raylab-reference: raylab's command line (framework/app/main.cpp) linked with solutions/, whose
// renders trace the reference's fastest tree over a scene's triangles
// (solutions/05c_wide_bvh/fast_tree.h) unless --accel names a stage tree.
#include "05c_wide_bvh/fast_tree.h"

#include "raylab/cli.h"
#include "raylab/testkit/exact_tracing.h"  // what `raylab trace` compares the stages' calls with

int main(int argc, char** argv) {
  const raylab::TracingFunctions contract = raylab::testkit::exact_tracing();
  return raylab::run_cli(argc, argv, raylab::LinkedStages::Reference, &raylab::reference::build_fast_tree, &contract);
}

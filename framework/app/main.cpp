// raylab: the command line, linked with the student's stages (assignments/). raylab-reference,
// the same command line linked with solutions/, has its own main (solutions/raylab_reference.cpp).
#include "raylab/cli.h"
#include "raylab/testkit/exact_tracing.h"  // what `raylab trace` compares the stages' calls with

int main(int argc, char** argv) {
  const raylab::TracingFunctions contract = raylab::testkit::exact_tracing();
  return raylab::run_cli(argc, argv, raylab::LinkedStages::Student, nullptr, &contract);
}

// The raylab command line (raylab and raylab-reference share it).
#pragma once

#include "raylab/accelerator.h"

namespace raylab {

// Which stage library the program links: raylab links assignments/, raylab-reference links
// solutions/.
enum class LinkedStages { Student, Reference };

struct TracingFunctions;  // raylab/geometry.h

// Runs `raylab render ...` etc. Returns the exit status (ExitStatus in error.h); never throws.
// own_tree: the program's own tree over a scene's triangles, which raylab render traces unless
// --accel names a stage tree (TracingFunctions::own_tree in raylab/geometry.h), or nullptr.
// contract: the kit's exact camera rays, sphere and triangle tests, which `raylab trace` holds the
// linked stages' calls against (testkit::exact_tracing; without them there is no trace command).
int run_cli(int argc, char** argv, LinkedStages stages = LinkedStages::Student,
            TriangleTreeBuilder own_tree = nullptr, const TracingFunctions* contract = nullptr);

}  // namespace raylab

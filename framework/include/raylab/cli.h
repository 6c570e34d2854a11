// The raylab command line (raylab and raylab-reference share it).
#pragma once

namespace raylab {

// Which stage library the program links: raylab links assignments/, raylab-reference links
// solutions/. Only a program of the reference's stages lets the renderer use their fast
// paths (TracingFunctions::reference_stages in geometry.h).
enum class LinkedStages { Student, Reference };

struct ReferenceTreeFunctions;  // raylab/geometry.h
struct TracingFunctions;        // raylab/geometry.h

// Runs `raylab render ...` etc. Returns the exit status (ExitStatus in error.h); never throws.
// reference_tree: with LinkedStages::Reference, the reference's fastest tree (or nullptr).
// contract: the kit's exact camera rays, sphere and triangle tests, which `raylab trace` holds the
// linked stages' calls against (testkit::exact_tracing; without them there is no trace command).
int run_cli(int argc, char** argv, LinkedStages stages = LinkedStages::Student,
            const ReferenceTreeFunctions* reference_tree = nullptr, const TracingFunctions* contract = nullptr);

}  // namespace raylab

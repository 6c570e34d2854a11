// The raylab command line (raylab and raylab-reference share it).
#pragma once

namespace raylab {

// Runs `raylab render ...` etc. Returns the exit status (ExitStatus in error.h); never throws.
int run_cli(int argc, char** argv);

}  // namespace raylab

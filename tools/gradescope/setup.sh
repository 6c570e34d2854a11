#!/usr/bin/env bash
# Gradescope's setup step (once per archive, as root): Debian packages and the grader. ROOT is /autograder unless AUTOGRADER_ROOT says otherwise (the
# kit's own test runs the whole pipeline in a temporary folder).
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
kit=$root/source/raylab
cd "$kit"
tools/install-deps
cmake -S . -B build -G Ninja -DRAYLAB_BUILD_TESTS=OFF -DRAYLAB_BUILD_BENCH=OFF >/dev/null
cmake --build build --target autograder autograder-stage-server autograder-regenerate
chmod 600 autograder/course-seed
rm -rf assignments.stubs && cp -a assignments assignments.stubs  # run_autograder starts from these
echo "setup: grader built"

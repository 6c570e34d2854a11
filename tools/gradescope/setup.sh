#!/usr/bin/env bash
# Gradescope's setup step (once per archive, as root). ROOT is /autograder unless AUTOGRADER_ROOT
# says otherwise (the kit's own test runs the whole pipeline in a temporary folder).
#   1. Debian/Ubuntu packages (tools/install-deps).
#   2. The fresh cases, from solutions/ and the course's seed, into $ROOT/private (root's alone),
#      before any student code is compiled here. Then solutions/, the seed and everything built
#      from them are removed: no compile of a submission can read them (#include, .incbin), and
#      no stage server can read the cases.
#   3. The grader, as the student release builds it (no solutions/ any more).
#   4. Who compiles submissions (run_autograder): a user id of its own (no account: setpriv), which
#      owns build/ and may read the kit, never $ROOT/private.
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
kit=$root/source/raylab
private=$root/private
builder_id=1999999999  # run_autograder compiles as this uid and gid
cd "$kit"
tools/install-deps
cmake -S . -B build -G Ninja -DRAYLAB_BUILD_TESTS=OFF -DRAYLAB_BUILD_BENCH=OFF >/dev/null
cmake --build build --target autograder-regenerate
rm -rf "$private"
mkdir -m 700 "$private"
build/bin/autograder-regenerate --seed "$(cat autograder/course-seed)" --output "$private/cases" >/dev/null
rm -rf solutions autograder/course-seed build/bin/autograder-regenerate build/CMakeFiles/raylab_stages_reference*.dir
cmake -S . -B build >/dev/null  # the student variant now
cmake --build build --target autograder autograder-stage-server
rm -rf assignments.stubs && cp -a assignments assignments.stubs  # run_autograder starts from these
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null; then
  chmod o+x "$root" "$root/source"
  chmod -R o+rX "$kit"
  chown -R "$builder_id:$builder_id" build
  echo "$builder_id" > "$private/builder"
else
  echo "setup: not root (or no setpriv): run_autograder compiles submissions as this user"
fi
echo "setup: grader built; fresh cases in $private"

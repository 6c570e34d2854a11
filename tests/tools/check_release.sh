#!/usr/bin/env bash
# The student release configures and builds on its own (no solutions/, stubs compile without
# warnings), its autograder reports every stage "not attempted" with 0 points and exits 0, and
# its renderer exits 2 naming stage 1. Arguments: SOURCE_DIR WORK_DIR.
set -euo pipefail
source_dir=$1 work=$2
rm -rf "$work"
"$source_dir/tools/make-release" "$work"
release="$work/raylab-student"
[ ! -e "$release/solutions" ] || { echo "FAIL: the release contains solutions/"; exit 1; }
cmake -S "$release" -B "$release/build" -G Ninja -DRAYLAB_WERROR=ON >/dev/null
cmake --build "$release/build" -j "$(nproc)" >/dev/null
[ ! -e "$release/build/bin/raylab-reference" ] || { echo "FAIL: the release built raylab-reference"; exit 1; }
(cd "$release" && build/bin/autograder --json "$work/results.json" --output "$work/images") > "$work/grader.txt"
cat "$work/grader.txt"
grep -q '"score": 0,' "$work/results.json" || { echo "FAIL: the stubs scored points"; exit 1; }
# The stages are stages.json's, as the grader lists them: each must be "not attempted".
ids=$(cd "$release" && build/bin/autograder --list | sed -n 's/^\([0-9][0-9a-z_]*\): .*/\1/p')
listed=$(echo "$ids" | wc -w)
stages=0
for id in $ids; do
  if grep -qE "^  $id +0/[0-9]+ +not attempted" "$work/grader.txt"; then stages=$((stages + 1));
  else echo "FAIL: stage $id is not reported '0/N not attempted'"; fi
done
[ "$listed" -gt 0 ] && [ "$stages" -eq "$listed" ] || { echo "FAIL: $stages of $listed stages reported 'not attempted'"; exit 1; }
status=0
(cd "$release" && build/bin/raylab render scenes/whitted.json -o "$work/whitted.png") 2> "$work/render.txt" || status=$?
cat "$work/render.txt"
[ "$status" -eq 2 ] && grep -q 01_camera_rays "$work/render.txt" || { echo "FAIL: raylab exited $status, expected 2 naming 01_camera_rays"; exit 1; }
echo "student release: builds, grades ($stages stages not attempted) and renders (exit 2)"

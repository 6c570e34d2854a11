#!/usr/bin/env bash
# The Gradescope pipeline end to end, as the service runs it, in a temporary folder standing
# for /autograder: tools/make-gradescope, unpack into source/, setup.sh once, then
# run_autograder per submission, each scored from $ROOT/results/results.json:
#   the solutions                    full marks
#   no files (the stubs)             0
#   a broken camera                  loses stage 01 only
#   code that does not compile       0, and results.json says so
#   a camera that copies the released reference answers: earns MatchesReferenceRays against
#   the released data, and nothing for it on the server (fresh cases from the course's seed)
# Usage: check_gradescope.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$(realpath "$1"); work=$(realpath -m "$2")
rm -rf "$work"; mkdir -p "$work"
root=$work/autograder
"$source_dir/tools/make-gradescope" --seed 4242 "$work" >/dev/null
mkdir -p "$root/source" "$root/submission" "$root/results"
(cd "$root/source" && cmake -E tar xf "$work/gradescope.zip")
export AUTOGRADER_ROOT=$root
bash "$root/source/setup.sh" > "$work/setup.log" 2>&1 || { tail -20 "$work/setup.log"; echo "FAIL: setup.sh"; exit 1; }
kit=$root/source/raylab
stage_files=$(sed -n 's/^ *"files": *\[\(.*\)\],*$/\1/p' "$kit/stages.json" | tr -d '" ' | tr ',' '\n' | sort -u)
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# grade NAME: runs run_autograder on what is in $root/submission; prints the total.
grade() {
  rm -rf "$root/results"; mkdir -p "$root/results"
  bash "$root/source/run_autograder" > "$work/$1.log" 2>&1
  [ -f "$root/results/results.json" ] || { fail "$1: no results.json"; echo -1; return; }
  cp "$root/results/results.json" "$work/$1.results.json"
  # the first "score" is the total: the keys come sorted (max_score, score, tests)
  grep -o '"score": [0-9]*' "$root/results/results.json" | head -1 | grep -o '[0-9]*$'
}
max_score() { grep -o '"max_score": [0-9]*' "$1" | head -1 | grep -o '[0-9]*$'; }
submit_solutions_except() {  # FILE_TO_LEAVE_OUT; files as the bare name, headers in their folder
  rm -rf "$root/submission"; mkdir -p "$root/submission"
  for f in $stage_files; do
    [ "$f" = "${1:-}" ] && continue
    cp "$source_dir/solutions/$f" "$root/submission/$(basename "$f")"
    for header in "$source_dir/solutions/$(dirname "$f")"/*.h; do
      [ -f "$header" ] || continue
      mkdir -p "$root/submission/$(dirname "$f")"; cp "$header" "$root/submission/$(dirname "$f")/"
    done
  done
}

submit_solutions_except ""
echo "a note the grader ignores" > "$root/submission/README.txt"
score=$(grade reference); max=$(max_score "$work/reference.results.json")
[ "$score" = "$max" ] && [ "$max" -gt 0 ] || fail "the solutions scored $score of $max"
grep -q "ignored README.txt" "$work/reference.log" || fail "run_autograder did not say it ignored README.txt"

rm -rf "$root/submission"; mkdir -p "$root/submission"
score=$(grade stubs)
[ "$score" = "0" ] || fail "the stubs scored $score"

submit_solutions_except 01_camera_rays/camera_rays.cpp
cp "$source_dir/tests/submissions/camera_half_size_screen.cpp" "$root/submission/camera_rays.cpp"
score=$(grade broken)
[ "$score" -lt "$max" ] && [ "$score" -ge $((max - 20)) ] || fail "the broken camera scored $score of $max (expected to lose stage 01's points only)"

submit_solutions_except 04_box/box.cpp
echo "this is not C++" > "$root/submission/box.cpp"
score=$(grade does_not_compile)
[ "$score" = "0" ] && grep -q "did not compile" "$work/does_not_compile.results.json" || fail "code that does not compile scored $score"

submit_solutions_except 01_camera_rays/camera_rays.cpp
cp "$source_dir/tests/submissions/camera_copies_released_cases.cpp" "$root/submission/camera_rays.cpp"
grade copies_released > /dev/null
grep -A3 '"name": "01_camera_rays: MatchesReferenceRays"' "$work/copies_released.results.json" | grep -q '"score": 0' ||
  fail "copying the released answers earned MatchesReferenceRays on the server"
"$kit/build/bin/autograder" --stage 01 --json "$work/released.json" --output "$work/released-images" > "$work/released.log" 2>&1 || true
grep -A3 '"name": "01_camera_rays: MatchesReferenceRays"' "$work/released.json" | grep -q '"score": 3' ||
  fail "the copying camera should earn MatchesReferenceRays against the released data (else this test proves nothing)"

if [ $failures -gt 0 ]; then echo "check_gradescope: $failures failures (logs in $work)"; exit 1; fi
echo "check_gradescope: the pipeline grades the solutions $max/$max, the stubs 0, a broken camera, a compile error and copied answers right"

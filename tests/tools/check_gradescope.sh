#!/usr/bin/env bash
# The Gradescope pipeline end to end, as the service runs it, in a temporary folder standing
# for /autograder: tools/make-gradescope, unpack into source/, setup.sh once, then
# run_autograder per submission, each scored from $ROOT/results/results.json:
#   the solutions                    full marks
#   no files (the stubs)             0
#   a broken camera                  loses stage 01, and later stages only tests that trace with it
#   code that does not compile       0, and results.json says so
#   a camera that copies the released reference answers: earns MatchesReferenceRays against
#   the released data, and nothing for it on the server (fresh cases from the course's seed)
#   a sphere that #includes the reference solution, or (as root) .incbin's the fresh cases: 0, the
#   kit has no solutions/ after setup.sh and the build runs as a user that cannot read the cases;
#   the course's seed appears in no output
# The folder standing for /autograder is made under /tmp (every folder above it searchable), as
# the service's is: the build's own user id must reach the kit.
# and the Gradescope fields: Markdown output with a failed picture inlined, execution times, the
# course's --visibility rules, and the leaderboard.
# Usage: check_gradescope.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$(realpath "$1"); work=$(realpath -m "$2")
rm -rf "$work"; mkdir -p "$work"
root=$(mktemp -d "${TMPDIR:-/tmp}/raylab-gradescope.XXXXXX")
trap 'rm -rf "$root"' EXIT
chmod 755 "$root"
seed=918273645
"$source_dir/tools/make-gradescope" --seed $seed --visibility '06_robustness=after_published' \
  --visibility '05_bvh: Bunny*=hidden' "$work" >/dev/null
mkdir -p "$root/source" "$root/submission" "$root/results"
(cd "$root/source" && cmake -E tar xf "$work/gradescope.zip")
export AUTOGRADER_ROOT=$root
bash "$root/source/setup.sh" > "$work/setup.log" 2>&1 || { tail -20 "$work/setup.log"; echo "FAIL: setup.sh"; exit 1; }
kit=$root/source/raylab
[ ! -e "$kit/solutions" ] && [ ! -e "$kit/autograder/course-seed" ] || echo "FAIL: solutions/ or the seed is still in the kit after setup.sh"
stage_files=$("$kit/build/bin/autograder" --list-files)
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# grade NAME: runs run_autograder on what is in $root/submission; prints the total.
grade() {
  rm -rf "$root/results"; mkdir -p "$root/results"
  bash "$root/source/run_autograder" > "$work/$1.log" 2>&1
  [ -f "$root/results/results.json" ] || { fail "$1: no results.json"; echo -1; return; }
  cp "$root/results/results.json" "$work/$1.results.json"
  python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["score"])' "$root/results/results.json"
}
max_score() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1])).get("max_score", 0))' "$1"; }
# test_score RESULTS_JSON NAME: the score of the test NAME ("none" if it is not there).
test_score() {
  python3 -c 'import json, sys; print(next((t["score"] for t in json.load(open(sys.argv[1]))["tests"] if t["name"] == sys.argv[2]), "none"))' "$1" "$2"
}
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
# Gradescope's fields (tools/make-gradescope --visibility above): Markdown output, times, the
# course's visibility rules, and the leaderboard from stage 05's measured work.
python3 - "$work/reference.results.json" <<'PYTHON' || fail "the solutions' results.json lacks Gradescope's fields (above)"
import json, sys
results = json.load(open(sys.argv[1]))
problems = []
for test in results["tests"]:
    expected = ("after_published" if test["name"].startswith("06_robustness:") else
                "hidden" if test["name"].startswith("05_bvh: Bunny") else "visible")
    if test.get("visibility") != expected:
        problems.append(f"{test['name']}: visibility {test.get('visibility')}, expected {expected}")
    if test.get("output_format") != "md" or not isinstance(test.get("execution_time"), (int, float)):
        problems.append(f"{test['name']}: output_format {test.get('output_format')}, execution_time {test.get('execution_time')}")
if not any(t["name"].startswith("06_robustness:") for t in results["tests"]):
    problems.append("no test of 06_robustness (the visibility rule tests nothing)")
if not results.get("execution_time", 0) > 0:
    problems.append(f"the run's execution_time is {results.get('execution_time')}")
board = {entry["name"]: entry for entry in results.get("leaderboard", [])}
for name in ("05_bvh: nodes per ray", "05_bvh: triangles per ray", "05_bvh: picture seconds"):
    if name not in board or not board[name]["value"] > 0 or board[name].get("order") != "asc":
        problems.append(f"leaderboard: {name}: {board.get(name)}")
if problems:
    print("\n".join(problems))
    sys.exit(1)
PYTHON

rm -rf "$root/submission"; mkdir -p "$root/submission"
score=$(grade stubs)
[ "$score" = "0" ] || fail "the stubs scored $score"

submit_solutions_except 01_camera_rays/camera_rays.cpp
cp "$source_dir/tests/submissions/camera_half_size_screen.cpp" "$root/submission/camera_rays.cpp"
score=$(grade broken)
# Lost: stage 01's tests, and the picture tests of the later stages (they render with its rays).
python3 - "$work/broken.results.json" "$source_dir/stages.json" <<'PYTHON' || fail "the broken camera scored $score of $max (expected to lose stage 01's tests and later pictures only)"
import json, sys
lost = [t["name"] for t in json.load(open(sys.argv[1]))["tests"] if t["score"] < t["max_score"]]
# The stages whose pictures render with the camera (stages.json: "needs").
users = tuple(s["id"] + ":" for s in json.load(open(sys.argv[2]))["stages"] if "01_camera_rays" in s["needs"])
wrong = [name for name in lost if not name.startswith("01_camera_rays:") and not ("Image" in name and name.startswith(users))]
print("\n".join(f"lost, but only the camera is broken: {name}" for name in wrong))
sys.exit(1 if wrong or not any(name.startswith("01_camera_rays:") for name in lost) else 0)
PYTHON
# Its failed picture test shows yours | reference | difference inlined in the Markdown output.
python3 - "$work/broken.results.json" <<'PYTHON' || fail "the broken camera's failed picture is not inlined in results.json"
import json, sys
tests = {t["name"]: t for t in json.load(open(sys.argv[1]))["tests"]}
test = tests["01_camera_rays: DirectionImageMatchesReference"]
sys.exit(0 if test["score"] == 0 and "](data:image/png;base64,iVBORw0KGgo" in test["output"] else 1)
PYTHON

submit_solutions_except 04_box/box.cpp
echo "this is not C++" > "$root/submission/box.cpp"
score=$(grade does_not_compile)
[ "$score" = "0" ] && grep -q "did not compile" "$work/does_not_compile.results.json" || fail "code that does not compile scored $score"
python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$work/does_not_compile.results.json" ||
  fail "the compile error's results.json is not JSON"

submit_solutions_except 01_camera_rays/camera_rays.cpp
cp "$source_dir/tests/submissions/camera_copies_released_cases.cpp" "$root/submission/camera_rays.cpp"
grade copies_released > /dev/null
[ "$(test_score "$work/copies_released.results.json" "01_camera_rays: MatchesReferenceRays")" = 0 ] ||
  fail "copying the released answers earned MatchesReferenceRays on the server"
"$kit/build/bin/autograder" --stage 01 --json "$work/released.json" --output "$work/released-images" > "$work/released.log" 2>&1 || true
[ "$(test_score "$work/released.json" "01_camera_rays: MatchesReferenceRays")" = 3 ] ||
  fail "the copying camera should earn MatchesReferenceRays against the released data (else this test proves nothing)"

# The reference solution, #included: no solutions/ to include after setup.sh.
submit_solutions_except 02_sphere/sphere.cpp
echo '#include "../../solutions/02_sphere/sphere.cpp"' > "$root/submission/sphere.cpp"
score=$(grade includes_the_solution)
[ "$score" = 0 ] || fail "a sphere that #includes the reference solution scored $score"
python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$work/includes_the_solution.results.json" ||
  fail "the failed include's results.json is not JSON"
if [ "$(id -u)" = 0 ]; then  # the fresh cases, read at compile time: the build's user cannot
  [ -f "$root/private/cases/01_camera_rays_cases.json" ] || fail "setup.sh made no fresh cases in $root/private/cases"
  submit_solutions_except 02_sphere/sphere.cpp
  { cat "$source_dir/solutions/02_sphere/sphere.cpp"
    echo "asm(\".section .rodata\\n.incbin \\\"$root/private/cases/01_camera_rays_cases.json\\\"\\n.text\");"
  } > "$root/submission/sphere.cpp"
  score=$(grade reads_the_cases)
  [ "$score" = 0 ] || fail "a sphere that .incbin's the fresh cases compiled and scored $score"
fi
# The seed is in no output of any run.
if grep -rqs "$seed" "$work" --include='*.json' --include='*.log' --include='*.html'; then
  fail "the course's seed appears in an output: $(grep -rls "$seed" "$work" --include='*.json' --include='*.log' --include='*.html' | head -3)"
fi

if [ $failures -gt 0 ]; then echo "check_gradescope: $failures failures (logs in $work)"; exit 1; fi
echo "check_gradescope: the pipeline grades the solutions $max/$max, the stubs 0, a broken camera, a compile error and copied answers right, with Gradescope's fields"

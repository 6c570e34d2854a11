#!/usr/bin/env bash
# The Gradescope pipeline end to end, as the service runs it, in a temporary folder standing
# for /autograder: tools/make-gradescope, unpack into source/, setup.sh once, then
# run_autograder per submission, each scored from $ROOT/results/results.json:
#   the solutions                    full marks
#   no files (the stubs)             0
#   a broken camera that copies the released reference answers, with a memory bomb and a fork
#   bomb: loses stages 01, 03 and 10 and nothing else; nothing for the copied answers on the
#   server (fresh cases from the course's seed), nor against the released data where the
#   sandbox's Landlock read rules hold (without them it earns MatchesReferenceRays there)
#   code that does not compile       0, and results.json says so
#   a sphere that #includes the reference solution, or (as root) .incbin's the fresh cases: 0, the
#   kit has no solutions/ after setup.sh and the build runs as a user that cannot read the cases;
#   the course's seed appears in no output
# and the Gradescope fields: Markdown output with a failed picture inlined, execution times, the
# course's --visibility rules, and the leaderboard. Every run is within Gradescope's limits (768 MB
# of memory for the whole run, one CPU), where a memory bomb (stage 03) with a fork bomb and a disk
# filler (stage 10) lose those two stages only, with no process of the run killed for memory and no
# file left behind; each run's time and peak memory are printed at the end.
# The folder standing for /autograder is made under /tmp (every folder above it searchable), as
# the service's is: the build's own user id must reach the kit.
# Usage: check_gradescope.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$(realpath "$1"); work=$(realpath -m "$2")
rm -rf "$work"; mkdir -p "$work"
root=$(mktemp -d "${TMPDIR:-/tmp}/raylab-gradescope.XXXXXX")
# Gradescope's limits on every run_autograder below (its defaults: 768 MB of memory for the
# container, half a CPU, 10 minutes): a memory cgroup of 768 MB where this machine lets the test
# make one (cgroup v1 or v2, as root), else (or with RAYLAB_PIPELINE_WITHOUT_CGROUP=1) each process
# of a run held to 768 MB of heap and anonymous memory (prlimit --data: the run's total is then not
# bounded, and the test says so); one CPU (taskset), and the 10 minutes (make-gradescope --minutes
# 10; the run is killed at 600 s).
limit_mb=768
memory_cgroup=""
per_process_limit=()
if [ -n "${RAYLAB_PIPELINE_WITHOUT_CGROUP:-}" ]; then
  :
elif [ -d /sys/fs/cgroup/memory ] && mkdir "/sys/fs/cgroup/memory/raylab-gradescope-$$" 2>/dev/null; then
  memory_cgroup=/sys/fs/cgroup/memory/raylab-gradescope-$$
  echo $((limit_mb * 1048576)) > "$memory_cgroup/memory.limit_in_bytes"
elif grep -qw memory /sys/fs/cgroup/cgroup.subtree_control 2>/dev/null && mkdir "/sys/fs/cgroup/raylab-gradescope-$$" 2>/dev/null; then
  memory_cgroup=/sys/fs/cgroup/raylab-gradescope-$$
  echo $((limit_mb * 1048576)) > "$memory_cgroup/memory.max"
fi
if [ -z "$memory_cgroup" ]; then
  command -v prlimit >/dev/null || { echo "FAIL: no memory cgroup, and no prlimit (Debian package util-linux) to limit each process"; exit 1; }
  per_process_limit=(prlimit --data=$((limit_mb * 1048576)))
fi
one_cpu=(); command -v taskset >/dev/null && one_cpu=(taskset -c 0)
cleanup() {
  rm -rf "$root"
  [ -z "$memory_cgroup" ] || rmdir "$memory_cgroup" 2>/dev/null || true
}
trap cleanup EXIT
chmod 755 "$root"
# The cgroup's count of processes killed for want of memory, and its peak use in MB.
oom_kills() {
  [ -n "$memory_cgroup" ] || { echo 0; return; }
  # (v1 has memory.oom_control, v2 memory.events: one of the two is always missing)
  { cat "$memory_cgroup/memory.oom_control" "$memory_cgroup/memory.events" 2>/dev/null || true; } |
    awk '$1 == "oom_kill" {n += $2} END {print n + 0}'
}
peak_mb() {
  [ -n "$memory_cgroup" ] || { echo "not measured"; return; }
  local bytes; bytes=$({ cat "$memory_cgroup/memory.max_usage_in_bytes" "$memory_cgroup/memory.peak" 2>/dev/null || true; } | head -1)
  echo $(( ${bytes:-0} / 1048576 ))
}
seed=918273645
"$source_dir/tools/make-gradescope" --seed $seed --minutes 10 --visibility '06_robustness=after_published' \
  --visibility '05_bvh: Bunny*=hidden' "$work" >/dev/null
# The Manual Docker folder beside the archive: the Dockerfile on Gradescope's base, and the same kit.
for file in Dockerfile source/setup.sh source/run_autograder source/raylab/stages.json source/raylab/autograder/time-limit-seconds; do
  [ -f "$work/docker/$file" ] || { echo "FAIL: make-gradescope wrote no docker/$file"; exit 1; }
done
grep -q "^FROM gradescope/autograder-base:" "$work/docker/Dockerfile" || { echo "FAIL: docker/Dockerfile is not on Gradescope's base"; exit 1; }
mkdir -p "$root/source" "$root/submission" "$root/results"
(cd "$root/source" && cmake -E tar xf "$work/gradescope.zip")
export AUTOGRADER_ROOT=$root
bash "$root/source/setup.sh" > "$work/setup.log" 2>&1 || { tail -20 "$work/setup.log"; echo "FAIL: setup.sh"; exit 1; }
kit=$root/source/raylab
stage_files=$("$kit/build/bin/autograder" --list-files)
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
[ ! -e "$kit/solutions" ] && [ ! -e "$kit/autograder/course-seed" ] || fail "solutions/ or the seed is still in the kit after setup.sh"
# Nothing compiled from solutions/ is left in the build either (its objects are the answers too).
compiled=$(find "$kit/build" -path '*/solutions/*' | head -3)
[ -z "$compiled" ] || fail "setup.sh left objects of solutions/ in the kit's build: $compiled"

# grade NAME: runs run_autograder on what is in $root/submission, within the limits above; prints
# the total. Its time (wall, and CPU on its one core) and peak memory go to $work/limits.txt.
grade() {
  rm -rf "$root/results"; mkdir -p "$root/results"
  local oom_before wall user system TIMEFORMAT='%R %U %S'
  oom_before=$(oom_kills)
  [ ! -f "$memory_cgroup/memory.max_usage_in_bytes" ] || echo 0 > "$memory_cgroup/memory.max_usage_in_bytes"
  { time (
      [ -z "$memory_cgroup" ] || echo "$BASHPID" > "$memory_cgroup/cgroup.procs"
      # Gradescope ends a run at its time limit (here the 10 minutes of --minutes 10).
      timeout -s KILL 600 ${one_cpu[@]+"${one_cpu[@]}"} ${per_process_limit[@]+"${per_process_limit[@]}"} bash "$root/source/run_autograder" > "$work/$1.log" 2>&1 ||
        [ $? != 137 ] || echo "$1: the run went past the 10 minutes: Gradescope would show no score" >> "$work/grade-failures"
    ); } 2> "$work/$1.time"  # (no exec above: time would see nothing)
  # (grade runs in $(...): its failures reach the count through a file)
  [ "$(oom_kills)" = "$oom_before" ] ||
    echo "$1: a process of the run was killed for want of memory (the container's $limit_mb MB)" | tee -a "$work/grade-failures" >&2
  read -r wall user system < "$work/$1.time"
  awk -v name="$1" -v wall="$wall" -v cpu="$(awk -v u="$user" -v s="$system" 'BEGIN {print u + s}')" -v peak="$(peak_mb)" \
    'BEGIN {printf "  %-22s %6.1f s wall, %6.1f s CPU on one core (at half a CPU about %4.0f s), peak %s%s\n", name, wall, cpu, 2 * cpu, peak, peak ~ /^[0-9]+$/ ? " MB" : ""}' >> "$work/limits.txt"
  [ -f "$root/results/results.json" ] || { echo "$1: no results.json" | tee -a "$work/grade-failures" >&2; echo -1; return; }
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
# It knows the container's limits, and keeps within them (resources.sh).
if [ -n "$memory_cgroup" ]; then
  grep -q "run_autograder: $limit_mb MB and 1 CPU for this run: compiles 1 at a time, a stage server may use 512 MB, 600 s in all" "$work/reference.log" ||
    fail "run_autograder did not find the container's $limit_mb MB and 1 CPU: $(grep 'for this run' "$work/reference.log")"
fi
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

# A broken camera (its y axis flipped) that copies the released answers (stage 01), a memory bomb
# that writes every page it takes (stage 03), and a fork bomb with a disk filler (stage 10,
# tests/tools/gradescope_hostile/), in one submission: within the container's memory and disk,
# each costs its own stage alone (every other stage is graded with the grader's own versions of
# the stages it builds on).
submit_solutions_except 01_camera_rays/camera_rays.cpp
cp "$source_dir/tests/submissions/camera_copies_released_cases.cpp" "$root/submission/camera_rays.cpp"
rm -f "$root/submission/triangle.cpp" "$root/submission/microfacet.cpp"
cp "$source_dir/tests/tools/gradescope_hostile/triangle.cpp" "$source_dir/tests/tools/gradescope_hostile/microfacet.cpp" "$root/submission/"
score=$(grade broken)
python3 - "$work/broken.results.json" <<'PYTHON' || fail "the broken camera, memory bomb, fork bomb and disk filler scored $score of $max (expected to lose stages 01, 03 and 10 only: above)"
import json, sys
tests = json.load(open(sys.argv[1]))["tests"]
lost = [t["name"] for t in tests if t["score"] < t["max_score"]]
wrong = [name for name in lost if not name.startswith(("01_camera_rays:", "03_triangle:", "10_microfacet:"))]
print("\n".join(f"lost, but its stage is correct: {name}" for name in wrong))
problems = bool(wrong)
for stage in ("01_camera_rays:", "10_microfacet:"):
    if not any(name.startswith(stage) for name in lost): print(f"{stage} lost nothing"); problems = True
if not any(t["name"].startswith("03_triangle:") and "memory" in t.get("output", "") for t in tests):
    print("stage 03's memory bomb is not named"); problems = True
sys.exit(1 if problems else 0)
PYTHON
# Its failed picture test shows yours | reference | difference inlined in the Markdown output.
python3 - "$work/broken.results.json" <<'PYTHON' || fail "the broken camera's failed picture is not inlined in results.json"
import json, sys
tests = {t["name"]: t for t in json.load(open(sys.argv[1]))["tests"]}
test = tests["01_camera_rays: DirectionImageMatchesReference"]
sys.exit(0 if test["score"] == 0 and "](data:image/png;base64,iVBORw0KGgo" in test["output"] else 1)
PYTHON
left=$(find /tmp /var/tmp /dev/shm "$root" -maxdepth 3 -name 'fill-*' 2>/dev/null | head -3)
[ -z "$left" ] || { fail "the disk filler left files: $left"; find /tmp /var/tmp /dev/shm "$root" -maxdepth 3 -name 'fill-*' -delete 2>/dev/null || true; }
[ "$(test_score "$work/broken.results.json" "01_camera_rays: MatchesReferenceRays")" = 0 ] ||
  fail "copying the released answers earned MatchesReferenceRays on the server"
# The same camera graded locally in the kit (still built with it) against the released data: where
# Landlock's read rules hold, the stage server cannot read that data at all (0); without them it
# copies the answers (3), which shows what the fresh cases defeat.
"$kit/build/bin/autograder" --stage 01 --verbose --json "$work/released.json" --output "$work/released-images" > "$work/released.log" 2>&1 || true
if grep -q "no file read but the system's" "$work/released.log"; then
  [ "$(test_score "$work/released.json" "01_camera_rays: MatchesReferenceRays")" = 0 ] ||
    fail "the copying camera read the released data, although the sandbox forbids reading it"
else
  [ "$(test_score "$work/released.json" "01_camera_rays: MatchesReferenceRays")" = 3 ] ||
    fail "the copying camera should earn MatchesReferenceRays against the released data (else this test proves nothing)"
fi

submit_solutions_except 04_box/box.cpp
echo "this is not C++" > "$root/submission/box.cpp"
score=$(grade does_not_compile)
[ "$score" = "0" ] && grep -q "did not compile" "$work/does_not_compile.results.json" || fail "code that does not compile scored $score"
python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$work/does_not_compile.results.json" ||
  fail "the compile error's results.json is not JSON"

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

[ ! -s "$work/grade-failures" ] || failures=$((failures + $(wc -l < "$work/grade-failures")))
if [ -n "$memory_cgroup" ]; then
  echo "check_gradescope: each run_autograder in $limit_mb MB (a memory cgroup) and on one CPU:"
else
  echo "check_gradescope: no memory cgroup here: each process of a run held to $limit_mb MB (prlimit --data), the run's total not bounded; on one CPU:"
fi
cat "$work/limits.txt"
if [ $failures -gt 0 ]; then echo "check_gradescope: $failures failures (logs in $work)"; exit 1; fi
echo "check_gradescope: the pipeline grades the solutions $max/$max, the stubs 0, a broken camera copying answers beside a memory bomb and a fork bomb, and a compile error right, with Gradescope's fields"

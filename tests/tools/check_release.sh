#!/usr/bin/env bash
# The student release configures and builds on its own (no solutions/, stubs compile without
# warnings), its autograder reports every stage "not attempted" with 0 points and exits 0, and
# its renderer exits 2 naming stage 1. Its docs name only files it has, and no released file
# speaks of how the project itself is developed. Arguments: SOURCE_DIR WORK_DIR.
set -euo pipefail
source_dir=$1 work=$2
rm -rf "$work"
"$source_dir/tools/make-release" "$work"
release="$work/raylab-student"
[ ! -e "$release/solutions" ] || { echo "FAIL: the release contains solutions/"; exit 1; }

# Every repository path that a released doc (*.md) names must exist in the release. A path is
# a word starting with one of the repository's top-level folders; placeholders (NN_name, <id>,
# *) and build outputs (build/, grading-output/) are not paths of the release.
top=$(git -C "$source_dir" ls-tree -d --name-only HEAD | grep -v '^\.' | paste -sd '|')
dangling=$(cd "$release" && find . -name '*.md' -not -path './build/*' -print0 |
  xargs -0 grep -onE "(^|[^A-Za-z0-9_./-])($top)/[A-Za-z0-9_./-]*" |
  sed -E 's/:([^A-Za-z0-9_.]?)([a-z])/:\2/; s/[.,:;]+$//' |
  while IFS=: read -r file line path; do
    case "$path" in *NN*|*'*'*) continue ;; esac
    [ -e "$path" ] || echo "  $file:$line names $path"
  done)
[ -z "$dangling" ] || { echo "FAIL: released docs name files the release does not have:"; echo "$dangling"; exit 1; }
# No released file speaks of the project's own process (its issues, sessions, helpers, lead).
process=$(cd "$release" && grep -rniE "\b(issues?|(this|that|next|earlier|later|working) sessions?|the lead|preamble|worktrees?|helper session)\b" \
  --exclude-dir=build . || true)
[ -z "$process" ] || { echo "FAIL: released files speak of the project's own process:"; echo "$process"; exit 1; }
cmake -S "$release" -B "$release/build" -G Ninja -DRAYLAB_WERROR=ON >/dev/null
cmake --build "$release/build" -j "$(nproc)" >/dev/null
[ ! -e "$release/build/bin/raylab-reference" ] || { echo "FAIL: the release built raylab-reference"; exit 1; }
(cd "$release" && build/bin/autograder --lang en --json "$work/results.json" --output "$work/images") > "$work/grader.txt"
cat "$work/grader.txt"
grep -q '"score": 0,' "$work/results.json" || { echo "FAIL: the stubs scored points"; exit 1; }
# The stages are stages.json's, as the grader lists them: each must be "not attempted".
ids=$(cd "$release" && build/bin/autograder --lang en --list | sed -n 's/^\([0-9][0-9a-z_]*\): .*/\1/p')
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

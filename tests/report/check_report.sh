#!/usr/bin/env bash
# The HTML report in a real browser: grades with GRADER into WORK/grading-output/, opens its
# index.html in headless Chromium (Debian's package) with no network (a network namespace of its
# own), dumps the page's DOM after loading and takes a screenshot of the whole page, and has
# CHECKER (check_report.cpp) check both against results.json.
# Usage: [REMOVE_PICTURE=FILE] [STAGE_SERVER=PATH] check_report.sh GRADER CHECKER WORK LANG [CHECKER_OPTIONS...]
# (STAGE_SERVER: the stage server GRADER grades, --stage-server; by default its own. STAGE_SERVERS_FOR:
# "stage=path ...", each a --stage-server-for. GRADE_STAGES: "id ...", grade only these, each a --stage)
set -euo pipefail
grader=$1 checker=$2 work=$(realpath -m "$3") lang=$4
shift 4
chromium=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium" ]; then
  echo "FAIL: Chromium is not installed: tools/install-deps --test installs it (Debian package chromium)"
  exit 1
fi
# No network for the browser: a network namespace with no interface, as root or, where the kernel
# lets users have namespaces, as a user.
if unshare --net true 2>/dev/null; then
  offline=(unshare --net)
elif unshare --user --map-root-user --net true 2>/dev/null; then
  offline=(unshare --user --map-root-user --net)
else
  echo "FAIL: cannot take the network away from the browser (unshare --net: not root, no user namespaces)"
  exit 1
fi
rm -rf "$work"
mkdir -p "$work"
servers=()
[ -z "${STAGE_SERVER:-}" ] || servers+=(--stage-server "$STAGE_SERVER")
for stage_server in ${STAGE_SERVERS_FOR:-}; do servers+=(--stage-server-for "$stage_server"); done
for stage in ${GRADE_STAGES:-}; do servers+=(--stage "$stage"); done
env -u LC_ALL -u LC_MESSAGES -u LANG -u LANGUAGE "$grader" ${servers[@]+"${servers[@]}"} --lang "$lang" --output "$work/grading-output" \
  --json "$work/results.json" --timeout 60 > "$work/grader.log" 2>&1 ||
  { cat "$work/grader.log"; echo "FAIL: the grader failed"; exit 1; }

# The checker's own test: a picture removed after grading must fail the check.
if [ -n "${REMOVE_PICTURE:-}" ]; then rm "$work/grading-output/$REMOVE_PICTURE"; fi

# Root needs --no-sandbox; the rest keeps Chromium from reaching for anything (each run starts
# from an empty profile). The same width and scale for both runs: the same layout.
browser() {
  "${offline[@]}" "$chromium" --headless --no-sandbox --disable-gpu --disable-background-networking \
    --disable-component-update --disable-sync --no-first-run --hide-scrollbars --force-device-scale-factor=1 \
    --user-data-dir="$(mktemp -d "$work/profile.XXXXXX")" "$@" 2>> "$work/chromium.log"
}
page="file://$work/grading-output/index.html"
browser --window-size=1366,900 --virtual-time-budget=10000 --dump-dom "$page" > "$work/dom.html"
# The page's height, which its script writes into the DOM (check_report.cpp says if it did not).
height=$(grep -o '"height":[0-9]*' "$work/dom.html" | head -1 | cut -d: -f2 || true)
height=${height:-900}
[ "$height" -le 16384 ] || height=16384
browser --window-size=1366,"$height" --screenshot="$work/screenshot.png" "$page" > /dev/null
"$checker" --html "$work/grading-output/index.html" --dom "$work/dom.html" --results "$work/results.json" \
  --screenshot "$work/screenshot.png" --lang "$lang" "$@"

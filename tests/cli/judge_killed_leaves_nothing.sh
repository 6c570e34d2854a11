#!/usr/bin/env bash
# The judge killed (SIGKILL) while a stage's code loops, after it left a detached sleeper behind:
# as root, where the kernel gives the stage a PID namespace of its own, its process 1 dies with the
# judge and the kernel kills the whole namespace, so within seconds no process of the stage is left.
# Where the stage has no PID namespace (not root, or a container that forbids it; the reference's
# --verbose says which), the sleeper would outlive the judge: the test says SKIPPED.
# Usage: judge_killed_leaves_nothing.sh JUDGE SERVER REFERENCE_JUDGE WORK
set -u
judge=$1 server=$2 reference=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
if ! "$reference" --stage 01 --verbose --output "$work/probe" 2>&1 | grep -q "no other process in sight"; then
  echo "SKIPPED: no PID namespace for the stage here (not root, or not allowed)"
  exit 0
fi
"$judge" --stage-server "$server" --stage 01 --timeout 60 --output "$work/out" > "$work/log" 2>&1 &
judge_pid=$!
# (a stage process's command line is the server's path: anchored, it is not this script's)
count() { pgrep -f -- "^$server" | wc -l; }
# Until the stage loops beside its sleeper (two processes of the server's program).
for _ in $(seq 100); do
  [ "$(count)" -ge 2 ] && break
  sleep 0.1
done
started=$(count)
kill -9 "$judge_pid"
wait "$judge_pid" 2> /dev/null
if [ "$started" -lt 2 ]; then
  echo "FAIL: the stage never started its sleeper"; cat "$work/log"; exit 1
fi
for _ in $(seq 50); do
  [ "$(count)" = 0 ] && break
  sleep 0.1
done
left=$(pgrep -f -- "^$server" | tr '\n' ' ')
if [ -n "$left" ]; then
  # shellcheck disable=SC2086
  ps -o pid,user,args -p $left
  # shellcheck disable=SC2086
  kill -9 $left
  echo "FAIL: processes of the stage outlived the killed judge: $left"
  exit 1
fi
echo "nothing of the stage outlived the killed judge"

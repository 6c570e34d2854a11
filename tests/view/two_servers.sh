#!/usr/bin/env bash
# Two raylab view servers never share a port: the second on the default port moves to a free one,
# and one asked for a port that is taken stops, saying so (cpp-httplib would otherwise bind both
# with SO_REUSEPORT, and the kernel would hand the page's requests to either).
# Usage: two_servers.sh RAYLAB_REFERENCE SCENE
set -euo pipefail
raylab=$1 scene=$2
work=$(mktemp -d)
pids=()
trap 'kill "${pids[@]}" 2>/dev/null || true; rm -rf "$work"' EXIT
# start NAME: a server on the default port in the background.
start() {
  "$raylab" view "$scene" --width 32 --height 24 --spp 1 > "$work/$1.out" 2>&1 < /dev/null &
  pids+=($!)
}
# port_of NAME: the port its address names, once printed.
port_of() {
  for _ in $(seq 100); do
    grep -o '127\.0\.0\.1:[0-9]*' "$work/$1.out" 2>/dev/null | cut -d: -f2 && return 0
    sleep 0.1
  done
  echo "FAIL: server $1 printed no address: $(cat "$work/$1.out")" >&2
  return 1
}
start first
first=$(port_of first)
start second
second=$(port_of second)
[ "$first" != "$second" ] || { echo "FAIL: both servers on the default port listen on $first"; exit 1; }
echo "PASS: the default port: the first server on $first, the second on $second"
if "$raylab" view "$scene" --port "$first" > "$work/taken.out" 2>&1 < /dev/null; then
  echo "FAIL: a third server on the taken port $first started"; exit 1
fi
grep -q "cannot listen on 127.0.0.1:$first" "$work/taken.out" ||
  { echo "FAIL: the server on a taken port said: $(cat "$work/taken.out")"; exit 1; }
echo "PASS: a server asked for the taken port $first stops: $(cat "$work/taken.out")"

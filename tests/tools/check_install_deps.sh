#!/usr/bin/env bash
# tools/install-deps on each system it knows (Debian 12 and 13, Ubuntu 22.04 and 24.04), played
# with a faked /etc/os-release (RAYLAB_OS_RELEASE) and faked dpkg-query (nothing is installed),
# sudo and apt-get (which answers as that system's archive would: tests/data/distro-packages/):
# every name it asks to install exists there, for the students' list, --test and --windows, and
# it installs what the build needs (OpenImageIO, GoogleTest, ...). A Debian or Ubuntu release it
# does not know gets the newest names, saying so; another system (Fedora, one of Gradescope's
# images) stops with the list of what to install. Usage: check_install_deps.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$(realpath "$1"); work=$(realpath -m "$2")
rm -rf "$work"; mkdir -p "$work/bin"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

cat > "$work/bin/dpkg-query" <<'FAKE'
#!/bin/sh
exit 1
FAKE
cat > "$work/bin/sudo" <<'FAKE'
#!/bin/sh
exec "$@"
FAKE
# apt-get as the archive of $ARCHIVE (one package name a line): "install" of a name it lacks
# fails as apt-get does; what it installs is logged.
cat > "$work/bin/apt-get" <<'FAKE'
#!/bin/sh
[ "$1" = update ] && exit 0
[ "$1" = install ] || { echo "fake apt-get: $*" >&2; exit 100; }
shift
for name in "$@"; do
  case "$name" in -*) continue ;; esac
  grep -qxF "$name" "$ARCHIVE" || { echo "E: Unable to locate package $name" >&2; exit 100; }
  echo "$name" >> "$INSTALLED"
done
FAKE
chmod +x "$work/bin/"*

# play ID VERSION ARCHIVE_FILE [install-deps arguments]: runs install-deps as that system; its
# output in $work/out, what it installed in $work/installed.
play() {
  local id=$1 version=$2 archive=$3; shift 3
  printf 'ID=%s\nVERSION_ID="%s"\nPRETTY_NAME="%s %s"\n' "$id" "$version" "$id" "$version" > "$work/os-release"
  : > "$work/installed"
  RAYLAB_OS_RELEASE="$work/os-release" ARCHIVE="$archive" INSTALLED="$work/installed" PATH="$work/bin:$PATH" \
    "$source_dir/tools/install-deps" "$@" > "$work/out" 2>&1
}

# The fake archive refuses a name it lacks (else this test could not fail).
ARCHIVE="$source_dir/tests/data/distro-packages/ubuntu-22.04.txt" INSTALLED="$work/installed" \
  "$work/bin/apt-get" install -y libclang-rt-dev 2>/dev/null && fail "the fake apt-get installed a name Ubuntu 22.04 lacks"

for system in debian-12 debian-13 ubuntu-22.04 ubuntu-24.04; do
  id=${system%%-*}; version=${system#*-}
  archive="$source_dir/tests/data/distro-packages/$system.txt"
  for flag in "" --test --windows; do
    if play "$id" "$version" "$archive" $flag; then
      for needed in cmake ninja-build g++ libopenimageio-dev libgtest-dev libcli11-dev nlohmann-json3-dev libtinyobjloader-dev libglm-dev libpng-dev; do
        grep -qxF "$needed" "$work/installed" || fail "$system $flag: $needed was not installed"
      done
      # raylab view's HTTP library, where the archive has it (not on Ubuntu 22.04).
      [ "$system" = ubuntu-22.04 ] || grep -qxF libcpp-httplib-dev "$work/installed" ||
        fail "$system $flag: libcpp-httplib-dev was not installed"
      case "$flag" in --test) grep -qxF clang "$work/installed" || fail "$system --test: no clang" ;;
                      --windows) grep -qxF wine64 "$work/installed" || fail "$system --windows: no wine64" ;; esac
    else
      fail "$system $flag: install-deps failed: $(tail -3 "$work/out")"
    fi
  done
  play "$id" "$version" "$archive" --test --dry-run || fail "$system --dry-run failed"
  [ ! -s "$work/installed" ] && grep -q "it would install: cmake" "$work/out" || fail "$system --dry-run: $(cat "$work/out")"
done
# Chromium: Debian's package; on Ubuntu only a snap, said so.
play ubuntu 24.04 "$source_dir/tests/data/distro-packages/ubuntu-24.04.txt" --test && grep -q "snap install chromium" "$work/out" ||
  fail "Ubuntu --test does not say where Chromium comes from"
# A Debian release it does not know: the newest names, and a word.
play debian 14 "$source_dir/tests/data/distro-packages/debian-13.txt" && grep -q "not one the kit was checked on" "$work/out" ||
  fail "Debian 14: $(cat "$work/out")"
# Not Debian or Ubuntu: stops, naming what to install.
if play fedora 40 /dev/null; then fail "Fedora: install-deps exited 0"; fi
grep -q "fedora 40 is not Debian or Ubuntu.*OpenImageIO" "$work/out" || fail "Fedora: $(cat "$work/out")"

if [ $failures -gt 0 ]; then echo "check_install_deps: $failures failures"; exit 1; fi
echo "check_install_deps: the packages of Debian 12 and 13 and Ubuntu 22.04 and 24.04 (students', --test, --windows), and a clear stop elsewhere"

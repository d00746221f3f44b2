#!/usr/bin/env bash
# Configures and builds Patchwork in Release into build/ (or $PATCHWORK_BUILD_DIR), every warning an
# error (PATCHWORK_WERROR). Quiet on success; prints the tail of the log on failure.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PATCHWORK_BUILD_DIR:-$root/build}
jobs=${PATCHWORK_JOBS:-$(nproc)}
log="$build/build.log"
mkdir -p "$build"
if ! { cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPATCHWORK_WERROR=ON && cmake --build "$build" -j "$jobs"; } >"$log" 2>&1; then
  tail -n 60 "$log" >&2
  echo "build: failed (full log: $log)" >&2
  exit 1
fi
echo "build: ok ($build)"

#!/usr/bin/env bash
# Configures and builds Patchwork in Release into build/ (or $PATCHWORK_BUILD_DIR), every warning an
# error (PATCHWORK_WERROR). Quiet on success; prints the tail of the log on failure.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PATCHWORK_BUILD_DIR:-$root/build}
jobs=${PATCHWORK_JOBS:-$(nproc)}
log="$build/build.log"
# A fresh build directory is a unity build (each library's sources compiled a few at a time as one
# file: CI's fresh build takes about a third less); PATCHWORK_UNITY=ON|OFF chooses, and an existing
# directory keeps its choice. PATCHWORK_UNITY=OFF compiles one file at a time, which also checks
# that every file includes what it uses (as incremental builds of an OFF directory do).
unity=()
if [[ -n "${PATCHWORK_UNITY:-}" ]]; then
  unity=(-DCMAKE_UNITY_BUILD="$PATCHWORK_UNITY")
elif [[ ! -f "$build/CMakeCache.txt" ]]; then
  unity=(-DCMAKE_UNITY_BUILD=ON)
fi
mkdir -p "$build"
if ! { cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPATCHWORK_WERROR=ON "${unity[@]}" && cmake --build "$build" -j "$jobs"; } >"$log" 2>&1; then
  tail -n 60 "$log" >&2
  echo "build: failed (full log: $log)" >&2
  exit 1
fi
echo "build: ok ($build)"

#!/usr/bin/env bash
# Builds the whole project (core, renderer, editor, tests, and the libFuzzer targets) with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer into build-asan/ (or $PATCHWORK_ASAN_BUILD_DIR)
# and runs the whole test suite under them: any ASan, LSan or UBSan report fails its test.
# Usage: scripts/sanitize.sh [--build-only | --test-only | --fuzz-only]   (--fuzz-only: build just the
# fuzz targets). The tests labelled `nosan` (end-to-end scripts whose time goes to lavapipe and
# Xvfb, not to our code) and the command-line rendering suites named below are left out here; they
# run in the Release pass.
# Mesa's lavapipe driver is preloaded so that it stays mapped after vkDestroyInstance and the memory
# it (and LLVM, the loader, X11) keep for the process can be told apart from Patchwork's own
# (tests/sanitizer/lsan.supp names only those libraries).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PATCHWORK_ASAN_BUILD_DIR:-$root/build-asan}
jobs=${PATCHWORK_JOBS:-$(nproc)}
log="$build/build.log"
targets=""
[[ "${1:-}" == "--fuzz-only" ]] && targets="--target fuzz_bpt fuzz_patchwork fuzz_gltf"
mkdir -p "$build"
# -O1 -g1: fast to build, line numbers in every report. A unity build (each library's sources
# compiled a few at a time as one file, CMAKE_UNITY_BUILD) parses the headers once per batch rather
# than once per file: the sanitizer build is always a fresh build on CI; the product libraries
# share one precompiled header too (PATCHWORK_PCH). A fresh Release build is a unity build too
# (scripts/build.sh); PATCHWORK_UNITY=OFF builds one file at a time, which checks every include.
if [[ "${1:-}" != "--test-only" ]] && ! { CXX=clang++ cmake -S "$root" -B "$build" -DPATCHWORK_SANITIZE=ON -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -g1" \
         -DPATCHWORK_BUILD_BENCH=OFF -DCMAKE_UNITY_BUILD=ON -DPATCHWORK_PCH=ON && cmake --build "$build" -j "$jobs" $targets; } >"$log" 2>&1; then
  tail -n 60 "$log" >&2
  echo "sanitize: build failed (full log: $log)" >&2
  exit 1
fi
[[ "${1:-}" != "--test-only" ]] && echo "sanitize: built ($build)"
[[ "${1:-}" == "--build-only" || "${1:-}" == "--fuzz-only" ]] && exit 0

lvp=$(find /usr/lib /usr/lib64 -name 'libvulkan_lvp.so' 2>/dev/null | head -n 1 || true)
export LD_PRELOAD="${lvp}"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizer/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$build"
# The command-line suites that render through the binary (teaching figures, sweeps, device
# comparisons, displayed exports, the CLI's render, displacement and glTF options) and the
# killed-writer loop of AtomicSave run in the Release pass only: about 360 s of processor time
# here, most of it lavapipe's and process start-up, for code the in-process tests run under the
# sanitizers anyway (CI's 45-minute budget).
cli_suites='^(TeachingCli|RenderCli|SweepAnimation|DistanceFigures|DeviceCompareCli|VectorFigureCli|GltfCli|ExportDisplayed)\.|^Displacement\.CommandLine|^AtomicSave\.KilledInTheMiddle'
ctest --output-on-failure -j "$jobs" --timeout 900 -LE nosan -E "$cli_suites"

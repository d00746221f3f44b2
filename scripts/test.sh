#!/usr/bin/env bash
# Installs what is missing (build and test packages, the Khronos glTF validator from npm), builds in
# Release and runs the whole test suite through ctest; then builds it again with clang, ASan and
# UBSan and runs it there (scripts/sanitize.sh), and fuzzes each file loader for a bounded time
# (scripts/fuzz.sh, PATCHWORK_FUZZ_SECONDS per target, default 20). Fails if any step fails.
# Each stage prints its wall time ("test: stage NAME: N s"), and the run ends with the total, so a
# CI log shows where the time goes (CI stops at 90 minutes; the budget is 45 on 2 idle cores).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PATCHWORK_BUILD_DIR:-$root/build}
start=$SECONDS
stage() {  # NAME COMMAND...: runs COMMAND and prints how long it took
  local name=$1 t0=$SECONDS
  shift
  "$@"
  echo "test: stage $name: $((SECONDS - t0)) s"
}
# The glTF validator, pinned by tests/gltf/package-lock.json; reinstalled only when the lock changes.
install_validator() {
  local validator_dir="$root/tests/gltf"
  local stamp="$validator_dir/node_modules/.patchwork-lock"
  if ! cmp -s "$validator_dir/package-lock.json" "$stamp" 2>/dev/null; then
    (cd "$validator_dir" && npm ci --silent --no-audit --no-fund >/dev/null)
    cp "$validator_dir/package-lock.json" "$stamp"
    echo "test: glTF validator installed"
  fi
}
release_tests() { (cd "$build" && ctest --output-on-failure -j "${PATCHWORK_JOBS:-$(nproc)}" --timeout 600); }

stage install "$root/scripts/install_deps.sh" --tests
stage validator install_validator
stage build "$root/scripts/build.sh"
stage tests release_tests
echo "test: the suite again under AddressSanitizer + UndefinedBehaviorSanitizer"
stage sanitize-build "$root/scripts/sanitize.sh" --build-only
stage sanitize-tests "$root/scripts/sanitize.sh" --test-only
echo "test: fuzzing the loaders"
stage fuzz "$root/scripts/fuzz.sh" "${PATCHWORK_FUZZ_SECONDS:-20}"
echo "test: all passed in $((SECONDS - start)) s"

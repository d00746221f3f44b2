#!/usr/bin/env bash
# Installs what is missing (build and test packages, the Khronos glTF validator from npm), builds in
# Release and runs the whole test suite through ctest; then builds it again with clang, ASan and
# UBSan and runs it there (scripts/sanitize.sh), and fuzzes each file loader for a bounded time
# (scripts/fuzz.sh, PATCHWORK_FUZZ_SECONDS per target, default 20). Fails if any step fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PATCHWORK_BUILD_DIR:-$root/build}
"$root/scripts/install_deps.sh" --tests

# The glTF validator, pinned by tests/gltf/package-lock.json; reinstalled only when the lock changes.
validator_dir="$root/tests/gltf"
stamp="$validator_dir/node_modules/.patchwork-lock"
if ! cmp -s "$validator_dir/package-lock.json" "$stamp" 2>/dev/null; then
  (cd "$validator_dir" && npm ci --silent --no-audit --no-fund >/dev/null)
  cp "$validator_dir/package-lock.json" "$stamp"
  echo "test: glTF validator installed"
fi

"$root/scripts/build.sh"
(cd "$build" && ctest --output-on-failure -j "${PATCHWORK_JOBS:-$(nproc)}" --timeout 600)
echo "test: the suite again under AddressSanitizer + UndefinedBehaviorSanitizer"
"$root/scripts/sanitize.sh"
echo "test: fuzzing the loaders"
"$root/scripts/fuzz.sh" "${PATCHWORK_FUZZ_SECONDS:-20}"
echo "test: all passed"

#!/usr/bin/env bash
# The whole hostile-input suite (issue 44; not part of CI, which runs a fixed sample as ctest
# hostile_suite_sample): every generated file — .bpt, .patchwork, .gltf/.glb, STEP, IGES, and the
# large inputs — through `patchwork info`, `convert` and `export`, each run under 10 s and 1 GB,
# then a table per reader of exits, slowest run, peak memory and problems (crashes, hangs, silent
# successes, unclear refusals, partial outputs, outputs that do not reopen). Exit 1 on any problem.
# Usage: scripts/hostile.sh [extra hostile_suite options, e.g. --mutations 200 --keep DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PATCHWORK_BUILD_DIR:-$root/build}
"$root/scripts/build.sh"
exec "$build/tests/hostile_suite" --bin "$build/app/patchwork" --repo "$root" --mutations 120 --large "$@"

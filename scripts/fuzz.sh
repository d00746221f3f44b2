#!/usr/bin/env bash
# Runs the libFuzzer targets (.bpt, .patchwork and glTF loaders, with round-trip checks, and the STEP/IGES value check) of the
# clang sanitizer build (scripts/sanitize.sh builds it if needed) for a bounded time each on their
# seed corpora (tests/corpus and data/), with the dictionaries fuzz/*.dict. Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]
# Crashes are written to build-asan/crashes/; a crash makes the script exit non-zero. Every crash
# found so far is a file in tests/corpus/bad, replayed by the test suite.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=${PATCHWORK_ASAN_BUILD_DIR:-$root/build-asan}
"$root/scripts/sanitize.sh" --fuzz-only
mkdir -p "$build/crashes"

# Seed corpora: the good files we ship plus the bad-input corpus; a working copy per target, so
# what a run learns is kept between runs in build-asan/corpus-*.
seed() {  # target, file globs...
  local dir="$build/corpus-$1"; shift
  mkdir -p "$dir"
  for f in "$@"; do [[ -f "$f" ]] && cp -n "$f" "$dir/" 2>/dev/null || true; done
}
seed bpt "$root"/data/*.bpt "$root"/tests/corpus/bad/*.bpt
seed patchwork "$root"/tests/corpus/bad/*.patchwork "$root"/tests/corpus/good/*.patchwork
seed cad_values "$root"/tests/corpus/good/*.step "$root"/tests/corpus/good/*.igs
seed gltf "$root"/tests/corpus/good/*.gltf "$root"/tests/corpus/good/*.glb "$root"/tests/corpus/bad/*.gltf "$root"/tests/corpus/bad/*.glb

status=0
for t in bpt patchwork gltf cad_values; do
  echo "fuzz: $t for ${seconds}s"
  if ! "$build/fuzz/fuzz_$t" -dict="$root/fuzz/$t.dict" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=4096 -timeout=20 \
        -artifact_prefix="$build/crashes/$t-" -print_final_stats=1 "$build/corpus-$t" >"$build/fuzz_$t.log" 2>&1; then
    status=1
    echo "fuzz: $t FOUND A PROBLEM:" >&2
    grep -E "ERROR|SUMMARY|Test unit written" "$build/fuzz_$t.log" | head -n 10 >&2
  fi
  grep -E "stat::number_of_executed_units|stat::new_units_added|cov:" "$build/fuzz_$t.log" | tail -n 3 | sed "s/^/  /" || true
done
exit $status

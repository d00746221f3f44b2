#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) into build-fuzz/ and runs each for a bounded
# time on its seed corpus (tests/corpus and data/). Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]
# Crashes are written to build-fuzz/crashes/; a crash makes the script exit non-zero.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=${PATCHWORK_FUZZ_BUILD_DIR:-$root/build-fuzz}
log="$build/build.log"
mkdir -p "$build/crashes"
if ! { CXX=clang++ cmake -S "$root" -B "$build" -DPATCHWORK_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo &&
       cmake --build "$build" -j "$(nproc)"; } >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "fuzz: build failed (full log: $log)" >&2
  exit 1
fi

# Seed corpora: the good files we ship plus the bad-input corpus; a working copy per target, so
# what a run learns is kept between runs in build-fuzz/corpus-*.
seed() {  # target, file globs...
  local dir="$build/corpus-$1"; shift
  mkdir -p "$dir"
  for f in "$@"; do [[ -f "$f" ]] && cp -n "$f" "$dir/" 2>/dev/null || true; done
}
seed bpt "$root"/data/*.bpt "$root"/tests/corpus/bad/*.bpt
seed patchwork "$root"/tests/corpus/bad/*.patchwork "$root"/tests/corpus/good/*.patchwork
seed gltf "$root"/tests/corpus/good/*.gltf "$root"/tests/corpus/good/*.glb "$root"/tests/corpus/bad/*.gltf "$root"/tests/corpus/bad/*.glb
[[ -n "$(ls -A "$build/corpus-patchwork")" ]] || "$root/build/app/patchwork" convert "$root/data/teacup.bpt" "$build/corpus-patchwork/teacup.patchwork" 2>/dev/null || true

status=0
for t in bpt patchwork gltf; do
  echo "fuzz: $t for ${seconds}s"
  if ! "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=4096 -timeout=20 \
        -artifact_prefix="$build/crashes/$t-" -print_final_stats=1 "$build/corpus-$t" >"$build/fuzz_$t.log" 2>&1; then
    status=1
    echo "fuzz: $t FOUND A PROBLEM:" >&2
    grep -E "ERROR|SUMMARY|Test unit written" "$build/fuzz_$t.log" | head -n 10 >&2
  fi
  grep -E "stat::number_of_executed_units|stat::new_units_added|cov:" "$build/fuzz_$t.log" | tail -n 3 | sed "s/^/  /"
done
exit $status

#!/usr/bin/env bash
# The long fuzz run (not part of CI, which fuzzes 20 s per target): each loader's libFuzzer target
# for SECONDS (default 600) with its dictionary, then one summary line per target: executions,
# executions per second, edge coverage (cov), features (ft), corpus files and crashes found.
# Usage: scripts/fuzz_long.sh [SECONDS_PER_TARGET]   (the clang build is made by scripts/fuzz.sh)
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-600}
build=${PATCHWORK_ASAN_BUILD_DIR:-$root/build-asan}
"$root/scripts/fuzz.sh" "$seconds"
status=$?
printf '%-10s %12s %9s %7s %7s %8s %8s\n' target execs exec/s cov ft corpus crashes
for t in bpt patchwork gltf cad_values; do
  log="$build/fuzz_$t.log"
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{print $2}')
  last=$(grep -E '#[0-9]+.*cov: ' "$log" | tail -n 1)
  rate=$(sed -n 's/.*exec\/s: \([0-9]*\).*/\1/p' <<<"$last")
  cov=$(sed -n 's/.*cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.*ft: \([0-9]*\).*/\1/p' <<<"$last")
  corpus=$(find "$build/corpus-$t" -type f | wc -l)
  crashes=$(find "$build/crashes" -name "$t-*" -type f | wc -l)
  printf '%-10s %12s %9s %7s %7s %8s %8s\n' "$t" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "$corpus" "$crashes"
done
exit $status

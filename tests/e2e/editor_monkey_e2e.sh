#!/usr/bin/env bash
# Issue 72's random-input test: tests/e2e/monkey.py drives the editor with seeded random keys,
# clicks, drags, wheel and palette commands on every example (a copy of it in WORK), under Xvfb
# with the Khronos validation layer on, and fails on an abort or crash, a stall over 10 s, a
# validation message, memory growth, or a broken invariant after the run (a join out of tolerance,
# a saved file that does not reopen or changes when saved again). Each failure prints its seed and
# the actions that led to it (a file that `monkey.py --replay` plays again).
# Usage: editor_monkey_e2e.sh PATCHWORK_BINARY DATA_DIR WORK_DIR [SECONDS_PER_RUN] [SEEDS] [EXAMPLES]
#   SECONDS_PER_RUN: random input per example and seed (default 12); SEEDS: how many seeds per
#   example (default 1), counted from MONKEY_SEED (default: the day of the year, printed, so that a
#   failure names its seed); EXAMPLES: how many of the examples each seed visits (default all),
#   taken in turn from the seed on, so that the ctest form (5 examples × 12 s, about 60 s of input)
#   covers every example within a few days.
# scripts/monkey.sh MINUTES runs the long form.
set -euo pipefail
BIN=$(realpath "$1")
DATA=$(realpath "$2")
WORK=$3
SECONDS_PER_RUN=${4:-12}
SEEDS=${5:-1}
EXAMPLES=${6:-0}
rm -rf "$WORK"
mkdir -p "$WORK"
WORK=$(realpath "$WORK")
source "$(dirname "$0")/e2e_lib.sh"
command -v import >/dev/null || true
BASE=${MONKEY_SEED:-$(date +%j | sed 's/^0*//')}
say "seeds from $BASE, $SECONDS_PER_RUN s per example and seed"
FAILED=0
for s in $(seq 0 $((SEEDS - 1))); do
    seed=$((BASE + s))
    run="$WORK/seed-$seed"
    mkdir -p "$run/state"
    docs=()
    all=("$DATA"/*.patchwork "$DATA"/teapot.bpt)
    count=${#all[@]}
    take=$([ "$EXAMPLES" -gt 0 ] && [ "$EXAMPLES" -lt "$count" ] && echo "$EXAMPLES" || echo "$count")
    for k in $(seq 0 $((take - 1))); do
        doc=${all[$(((seed * take + k) % count))]}
        cp "$doc" "$run/"
        docs+=("$run/$(basename "$doc")")
    done
    [ -f "$DATA/terrain.png" ] && cp "$DATA/terrain.png" "$run/"  # the height map beside terrain
    if ! XDG_STATE_HOME="$run/state" PATCHWORK_EDITOR_TRACE="$run/trace.json" \
        python3 "$(dirname "$0")/monkey.py" --bin "$BIN" --work "$run" --seed "$seed" \
        --seconds "$SECONDS_PER_RUN" "${docs[@]}" | tee -a "$LOG"; then
        FAILED=$((FAILED + 1))
    fi
done
[ "$FAILED" = 0 ] || fail "random input found faults with $FAILED of $SEEDS seeds (seeds and actions above)"
say "PASS: ${#docs[@]} examples x $SEEDS seeds, $SECONDS_PER_RUN s each"

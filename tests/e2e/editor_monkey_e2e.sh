#!/usr/bin/env bash
# Issue 72's random-input test: tests/e2e/monkey.py drives the editor with seeded random keys,
# clicks, drags, wheel and palette commands on every example (a copy of it in WORK), under Xvfb
# with the Khronos validation layer on, and fails on an abort or crash, a stall over 10 s, a
# validation message, memory growth, or a broken invariant after the run (a join out of tolerance,
# a saved file that does not reopen or changes when saved again). Each failure prints its seed and
# the actions that led to it (a file that `monkey.py --replay` plays again).
# Usage: editor_monkey_e2e.sh PATCHWORK_BINARY DATA_DIR WORK_DIR [SECONDS_PER_RUN] [SEEDS]
#   SECONDS_PER_RUN: random input per example and seed (default 4: the ctest form, about 60 s of
#   input over the examples); SEEDS: how many seeds per example (default 1), counted from
#   MONKEY_SEED (default: the day of the year, printed, so that a failure names its seed).
# scripts/monkey.sh MINUTES runs the long form.
set -euo pipefail
BIN=$(realpath "$1")
DATA=$(realpath "$2")
WORK=$3
SECONDS_PER_RUN=${4:-4}
SEEDS=${5:-1}
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
    for doc in "$DATA"/*.patchwork "$DATA"/teapot.bpt; do
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
say "PASS: ${#docs[@]} examples x $SEEDS seeds"

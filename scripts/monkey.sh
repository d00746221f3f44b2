#!/usr/bin/env bash
# The long form of the editor's random-input test (issue 72; tests/e2e/editor_monkey_e2e.sh, whose
# ctest form gives each example a few seconds): MINUTES of seeded random keys, clicks, drags, wheel
# and palette commands on each example, split over SEEDS seeds (default 10), under Xvfb with the
# validation layer on. Needs a Release build (scripts/build.sh). Each failure prints its seed, the
# example and the actions that led to it; MONKEY_SEED=N starts the seeds at N (default: today's day
# of the year), so a failing seed replays exactly.
# Usage: scripts/monkey.sh MINUTES [SEEDS]      e.g. scripts/monkey.sh 30   (30 min per example)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
minutes=${1:?usage: scripts/monkey.sh MINUTES [SEEDS]}
seeds=${2:-10}
bin=${PATCHWORK_BIN:-$root/build/app/patchwork}
[ -x "$bin" ] || { echo "monkey: $bin is not built (scripts/build.sh)" >&2; exit 2; }
work=$(mktemp -d "${TMPDIR:-/tmp}/patchwork-monkey.XXXXXX")
per_run=$(python3 -c "print(max(4, round($minutes * 60 / $seeds)))")
echo "monkey: $minutes min per example over $seeds seeds ($per_run s each); work in $work"
exec bash "$root/tests/e2e/editor_monkey_e2e.sh" "$bin" "$root/data" "$work" "$per_run" "$seeds"

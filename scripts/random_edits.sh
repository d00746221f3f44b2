#!/usr/bin/env bash
# The long form of the randomized edit test (issue 73; tests/test_random_edits.cpp, whose ctest form
# runs 4 scripts per example): SCRIPTS seeded scripts of 20–50 commands per example (default 70:
# about 1 000 over the 15 examples). Every accepted command must leave every join within tolerance
# and fold nothing; every script's document must reopen to the same bytes. A failure prints the
# example, the seed and the script as a `patchwork edit` command line. Needs a Release build.
# Usage: scripts/random_edits.sh [SCRIPTS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PATCHWORK_BUILD_DIR:-$root/build}
[ -x "$build/tests/test_random_edits" ] || { echo "random_edits: build first (scripts/build.sh)" >&2; exit 2; }
PATCHWORK_RANDOM_EDIT_SCRIPTS=${1:-70} PATCHWORK_DATA_DIR=$root/data exec "$build/tests/test_random_edits"

#!/usr/bin/env bash
# Installs what is missing, builds in Release and starts Patchwork on the built-in teapot (or on
# the file and arguments given; without a display it says so and points to `patchwork render`).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh"
exec "${PATCHWORK_BUILD_DIR:-$root/build}/app/patchwork" "$@"

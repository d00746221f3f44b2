#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages Patchwork needs that are not installed yet. Idempotent and
# quiet: prints one line when everything is present. Usage: scripts/install_deps.sh [--tests]
#   --tests  also what the test suite needs (validation layers, Xvfb, xdotool, ImageMagick, a window
#            manager (openbox) for minimise tests, clang with libFuzzer, clang-format (the code's
#            formatting, tests/format), desktop-file-validate for
#            the installed desktop entry, assimp as an independent reader of the glTF and OBJ
#            exports, rsvg-convert, xmllint and pdftoppm as independent readers of the SVG and PDF
#            figures, ffprobe (with ffmpeg, which sweeps use) for the animations, Node.js for the
#            glTF validator).
set -euo pipefail

build_packages=(
  cmake g++ make pkg-config
  libvulkan-dev mesa-vulkan-drivers glslc
  libglfw3-dev libx11-dev libxext-dev libxrandr-dev libimgui-dev libglm-dev libeigen3-dev libtinygltf-dev
  nlohmann-json3-dev libstb-dev libpng-dev libcli11-dev fonts-dejavu-core
  libgtest-dev libbenchmark-dev
  help2man
  libcairo2-dev ffmpeg
  libcgal-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev libocct-ocaf-dev
)
# freecad, blender and python3-numpy (Blender 3.4's glTF importer): the readers of
# tests/test_foreign_readers.cpp, which skips without them.
test_packages=(vulkan-validationlayers vulkan-tools xvfb xdotool imagemagick openbox clang clang-format libclang-rt-dev desktop-file-utils assimp-utils librsvg2-bin libxml2-utils poppler-utils
  freecad blender python3-numpy)

wanted=("${build_packages[@]}")
if [[ "${1:-}" == "--tests" ]]; then
  wanted+=("${test_packages[@]}")
  # Node.js runs the glTF validator; take Debian's only where no node is installed at all.
  command -v node >/dev/null 2>&1 || wanted+=(nodejs)
  command -v npm >/dev/null 2>&1 || wanted+=(npm)
fi

missing=()
for pkg in "${wanted[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
done

if ((${#missing[@]} == 0)); then
  echo "install_deps: all ${#wanted[@]} packages present"
  exit 0
fi

if ! command -v apt-get >/dev/null 2>&1; then
  echo "install_deps: apt-get is not available on this system." >&2
  echo "Install these packages (or your distribution's equivalents) by hand, then run again:" >&2
  echo "  ${missing[*]}" >&2
  exit 1
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo_cmd=(sudo)
  else
    echo "install_deps: need root to install: ${missing[*]}" >&2
    echo "Run as root: apt-get update && apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
fi

echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
log=$(mktemp)
if ! { "${sudo_cmd[@]}" apt-get update -qq && \
       "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"; } >"$log" 2>&1; then
  tail -n 30 "$log" >&2
  echo "install_deps: apt-get failed (full log: $log)" >&2
  exit 1
fi
rm -f "$log"
echo "install_deps: done"

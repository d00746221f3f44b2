#!/usr/bin/env bash
# `patchwork bench --editor` under Xvfb with the validation layer on, through both presentation
# paths (host presentation by XShmPutImage, the CPU default, and the Vulkan swapchain): a short G drag
# runs, the point moves with every join holding, Esc restores it, and the JSON carries every
# figure. Then the editor's window is photographed on both paths: the 3D view must be on screen
# (the teapot and its net fill the middle, the background shows below). No timing is checked:
# the figures are the benchmark's to report. Without a display the benchmark says so (exit 2).
# Usage: editor_bench_e2e.sh PATCHWORK_BINARY DATA_DIR WORK_DIR
set -euo pipefail
BIN=$1
WORK=$3
rm -rf "$WORK"
mkdir -p "$WORK"
source "$(dirname "$0")/e2e_lib.sh"
command -v import >/dev/null || missing_tool "ImageMagick (import)"

for present in host swapchain; do
    if [ $present = swapchain ]; then export PATCHWORK_PRESENT=swapchain; else unset PATCHWORK_PRESENT; fi
    json=$WORK/bench-$present.json
    "$BIN" bench --editor --frames 12 --size 960x600 --json "$json" >"$WORK/bench-$present.out" 2>"$WORK/bench-$present.err" ||
        { cat "$WORK/bench-$present.out" "$WORK/bench-$present.err"; fail "bench --editor ($present) failed"; }
    grep -qi "validation" "$WORK/bench-$present.err" && fail "validation output on stderr ($present)"
    python3 - "$json" <<'PY' || fail "bench --editor ($present): unexpected JSON"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["frames"] == 12 and j["width"] == 960 and j["height"] == 600, j
assert j["patches"] == 32 and j["triangles"] == 32 * 2 * 16 * 16, j  # the teapot at level 16
assert j["moved"] > 0.01 * j["model_size"], j                        # the drag moved the point
assert j["max_residual"] <= 1e-6 * j["model_size"], j                # every join held
assert j["restored"] is True, j                                       # Esc put it back, and undo the kept drag
for k in ("frame_ms", "bare_render_ms", "view_ms", "present_ms", "ui_ms", "grab_ms", "release_ms", "after_release_ms", "undo_ms"):
    assert j[k] > 0, (k, j)
assert j["drag_ms"] > 0 and j["drag_ms"] < j["ui_ms"], j
assert abs(j["overhead_ms"] - (j["frame_ms"] - j["bare_render_ms"])) < 1e-9, j
PY
    say "bench --editor ($present): $(grep -o 'editor frame *[0-9.]* ms' "$WORK/bench-$present.out"), $(grep -o 'bare render *[0-9.]* ms' "$WORK/bench-$present.out")"

    # What a person sees: the window shows the frames.
    start_editor
    sleep 1
    import -window root "$WORK/screen-$present.png"
    read -r W H < <(trace "' '.join(str(v) for v in t['framebuffer'])")
    # The share of the middle of the window (400x240) that is not the background colour: the
    # teapot, its control net and the ground grid; 0 if no frame reached the window.
    drawn=$(convert "$WORK/screen-$present.png" -crop 400x240+$((W / 2 - 200))+$((H / 2 - 120)) +repage -fuzz 6% -fill black \
        -opaque "rgb(41,43,48)" -fill white +opaque black -colorspace gray -format '%[fx:mean]' info:)
    corner=$(convert "$WORK/screen-$present.png" -crop 1x1+$((W / 2))+$((H - 40)) -format '%[fx:int(255*r)] %[fx:int(255*g)] %[fx:int(255*b)]' info:)
    python3 - "$drawn" "$corner" <<'PY' || fail "the window does not show the 3D view ($present): $drawn of the middle drawn, lower middle $corner"
import sys
assert float(sys.argv[1]) > 0.25, sys.argv[1]
k = [int(v) for v in sys.argv[2].split()]
assert all(abs(a - b) <= 25 for a, b in zip(k, (41, 43, 48))), k  # background (ground grid lines are faint)
PY
    check_validation
    quit_editor
    say "window shows the view ($present): $drawn of the middle drawn, lower middle $corner"
done
unset PATCHWORK_PRESENT

# No display: a clear message and exit 2.
rc=0
env -u DISPLAY -u WAYLAND_DISPLAY "$BIN" bench --editor --frames 2 >"$WORK/nodisplay.out" 2>"$WORK/nodisplay.err" || rc=$?
[ "$rc" = 2 ] || fail "bench --editor without a display: exit $rc"
grep -q "no display" "$WORK/nodisplay.err" || fail "bench --editor without a display: no message"
say "PASS"

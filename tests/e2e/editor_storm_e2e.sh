#!/usr/bin/env bash
# Window storms under Xvfb with a window manager (openbox), the Vulkan validation layer on: the
# editor window is resized, minimised and restored 40 times in quick succession (out-of-date and
# recreated swapchains, zero-size and iconified states), with view changes forcing redraws in
# between. Afterwards the editor must still run, draw at the final size, have reported no
# validation message and quit cleanly.
# Usage: editor_storm_e2e.sh PATCHWORK_BINARY DATA_DIR WORK_DIR
set -euo pipefail
BIN=$1
WORK=$3
rm -rf "$WORK"
mkdir -p "$WORK"
E2E_WINDOW_MANAGER=openbox
source "$(dirname "$0")/e2e_lib.sh"

start_editor
check_validation
say "storm on window $WID"
for i in $(seq 40); do
    xdotool windowsize "$WID" $((420 + (i * 137) % 760)) $((300 + (i * 89) % 420))
    case $((i % 5)) in
        0) xdotool windowminimize "$WID"; sleep 0.1; xdotool windowmap "$WID"; xdotool windowactivate "$WID" 2>/dev/null || true ;;
        2) xdotool key 3 ;;   # right view: the scene changes while the swapchain churns
        4) xdotool key 1 ;;   # front view
    esac
    sleep 0.05
done
kill -0 "$EDITOR_PID" || fail "editor died during the storm"

# A longer minimise: the editor waits without drawing, then comes back at a new size.
xdotool windowminimize "$WID"
sleep 1.5
kill -0 "$EDITOR_PID" || fail "editor died while minimised"
F0=$(trace "t['frame']")
xdotool windowmap "$WID"
xdotool windowactivate "$WID" 2>/dev/null || true
xdotool windowsize "$WID" 1000 700
xdotool key 7
wait_for "t['framebuffer'] == [1000, 700] and t['frame'] > $F0" 30
check_validation
say "survived 40 resizes with 8 minimise/restore cycles; drawing at 1000x700"

quit_editor
say "PASS"

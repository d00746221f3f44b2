#!/usr/bin/env bash
# The teaching layout at three window sizes (1024x640, 1280x800, 1920x1080), under Xvfb with the
# validation layer on: the domain view in four panes stays between the side panels, its labels
# (edge levels, captions, titles) neither overlap one another nor leave their pane, the axis gizmo
# keeps out of the domain window, and presentation mode's text grows with the window, is not
# clipped and is not covered by the domain window.
# Screenshots in WORK_DIR (layout-WxH.png, presentation-WxH.png).
# Usage: editor_layout_e2e.sh PATCHWORK_BINARY DATA_DIR WORK_DIR
set -euo pipefail
BIN=$1
WORK=$3
rm -rf "$WORK"
mkdir -p "$WORK"
export E2E_SCREEN=1920x1080
source "$(dirname "$0")/e2e_lib.sh"
export PATCHWORK_WINDOW_SIZE

PRESENT_PREV=0
for SIZE in 1024x640 1280x800 1920x1080; do
    PATCHWORK_WINDOW_SIZE=$SIZE
    W=${SIZE%x*}
    start_editor
    wait_for "t['window'] == [${SIZE/x/, }]"
    click_item panel.teaching
    wait_for "'teach.domain' in t['items']"
    # The right panel scrolls the Teaching section into view where the window is short.
    H=${SIZE#*x}
    xdotool mousemove --sync $((W - 100)) $((H / 2))
    for i in $(seq 12); do xdotool click 5; sleep 0.05; done
    wait_for "t['items']['teach.panes4'][1] < $H - 20"
    click_item teach.domain
    wait_for "len(t['domain']) == 1"
    click_item teach.panes4
    wait_for "len(t['domain']) == 4 and len(t['layout']['domainLabels']) >= 4 * 7"
    xdotool mousemove --sync 5 5
    sleep 0.5
    import -window root -crop "${SIZE}+0+0" "$WORK/layout-$SIZE.png"
    python3 - "$WORK/trace.json" "$W" <<'PY' || fail "layout at $SIZE"
import json, sys
t = json.load(open(sys.argv[1]))
width = float(sys.argv[2])
L = t['layout']
win = L['domainWindow']
boxes = L['domainLabels']
def overlap(a, b, pad=0.5):
    return a[0] + pad < b[0] + b[2] and b[0] + pad < a[0] + a[2] and a[1] + pad < b[1] + b[3] and b[1] + pad < a[1] + a[3]
# The window between the side panels.
assert win[0] >= L['left'] - 1 and win[0] + win[2] <= width - L['right'] + 1, ("domain window under a side panel", win, L)
# Every label inside the window, none on top of another.
for b in boxes:
    assert win[0] - 1 <= b[0] and b[0] + b[2] <= win[0] + win[2] + 1 and win[1] - 1 <= b[1] and b[1] + b[3] <= win[1] + win[3] + 1, ("label outside the window", b, win)
for i in range(len(boxes)):
    for j in range(i + 1, len(boxes)):
        assert not overlap(boxes[i], boxes[j]), ("labels overlap", boxes[i], boxes[j])
g = L['axisGizmo']
assert g[2] == 0 or not overlap(g, win), ("axis gizmo over the domain window", g, win)
print("layout ok:", len(boxes), "labels, window", [round(v) for v in win], "gizmo", [round(v) for v in g])
PY
    check_validation
    # Presentation mode: its overlay's text scales with the window.
    xdotool mousemove --sync 640 500
    xdotool key F5
    wait_for "t['presentation'] and t['presentationOverlay'][1] > 0"
    import -window root -crop "${SIZE}+0+0" "$WORK/presentation-$SIZE.png"
    sleep 0.3
    # Its text fits (nothing clipped) and the domain window keeps clear of it.
    wait_for "t['presentationOverlay'][2] <= t['presentationOverlay'][0] and (t['layout']['domainWindow'][0] >= 16 + t['presentationOverlay'][0])"
    HEIGHT=$(trace "round(t['presentationOverlay'][1])")
    [ "$HEIGHT" -gt "$PRESENT_PREV" ] || fail "presentation text did not grow at $SIZE ($HEIGHT <= $PRESENT_PREV)"
    PRESENT_PREV=$HEIGHT
    xdotool key F5
    wait_for "not t['presentation']"
    say "$SIZE: domain view in four panes, labels apart and inside, gizmo clear; presentation overlay $HEIGHT px high"
    quit_editor
done
say PASS

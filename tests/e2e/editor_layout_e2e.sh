#!/usr/bin/env bash
# The teaching layout at three window sizes (1024x640, 1280x720, 1920x1080), under Xvfb with the
# validation layer on: the domain view in four panes stays between the side panels, its labels
# (edge levels, captions, titles) neither overlap one another nor leave their pane, and the axis
# gizmo keeps out of the domain window. Presentation mode (F5) shows the domain view full-window
# beside its levels box, labels growing with the window, panes titled by partitioning, every
# pane's counts in the box from the frame that drew them (checked during a sweep); Ctrl+= and
# Ctrl+- scale its text; the split 3D view presents beside the box too.
# Screenshots in WORK_DIR (layout-WxH.png, presentation-WxH.png, presentation-split-1280x720.png).
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
for SIZE in 1024x640 1280x720 1920x1080; do
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
    if [ "$SIZE" = 1920x1080 ]; then
        # A playing sweep, for the same-frame check below.
        wait_for "t['items']['teach.play'][1] < $H - 20"
        click_item teach.play
        wait_for "t['sweep']['playing']"
    fi
    # Presentation mode (F5): the domain view fills the window right of the levels box, its
    # labels, captions and dots grow with the window, each pane is titled by its partitioning and
    # the box lists every pane's counts.
    xdotool mousemove --sync 640 500
    xdotool key F5
    wait_for "t['presentation'] and t['presentationOverlay'][1] > 0 and len(t['domain']) == 4"
    sleep 0.3
    # Its text fits (nothing clipped) and the domain window keeps clear of it.
    wait_for "t['presentationOverlay'][2] <= t['presentationOverlay'][0] and (t['layout']['domainWindow'][0] >= 16 + t['presentationOverlay'][0])"
    import -window root -crop "${SIZE}+0+0" "$WORK/presentation-$SIZE.png"
    python3 - "$WORK/trace.json" "$W" "$H" <<'PY' || fail "presentation layout at $SIZE"
import json, sys
t = json.load(open(sys.argv[1]))
W, H = float(sys.argv[2]), float(sys.argv[3])
win, ov, boxes = t['layout']['domainWindow'], t['presentationOverlay'], t['layout']['domainLabels']
left = 16 + ov[0]
assert win[0] >= left and win[0] + win[2] <= W + 1, ("domain window over the levels box or off screen", win, ov)
assert win[2] >= W - left - 24 and win[3] >= H - 16, ("domain window does not fill the window", win, W, H)
def overlap(a, b, pad=0.5):
    return a[0] + pad < b[0] + b[2] and b[0] + pad < a[0] + a[2] and a[1] + pad < b[1] + b[3] and b[1] + pad < a[1] + a[3]
for b in boxes:
    assert win[0] - 1 <= b[0] and b[0] + b[2] <= win[0] + win[2] + 1 and win[1] - 1 <= b[1] and b[1] + b[3] <= win[1] + win[3] + 1, ("label outside the window", b, win)
for i in range(len(boxes)):
    for j in range(i + 1, len(boxes)):
        assert not overlap(boxes[i], boxes[j]), ("labels overlap", boxes[i], boxes[j])
titles = [d['title'] for d in t['domain']]
assert titles == ['equal', 'fractional_odd', 'fractional_even', 'pow2'], titles
lines = t['presentationLines']
for d in t['domain']:
    want = "%s: %d triangles" % (d['spacing'], d['expectedPrimitives'])
    assert want in lines, (want, lines)
print("presentation ok: window", [round(v) for v in win], "labels", round(t['domainTextPixels'], 1), "px, box", lines)
PY
    PX=$(trace "round(t['domainTextPixels'] * 10)")
    [ "$PX" -gt "$PRESENT_PREV" ] || fail "presentation labels did not grow at $SIZE ($PX <= $PRESENT_PREV tenths of a pixel)"
    PRESENT_PREV=$PX
    if [ "$SIZE" = 1920x1080 ]; then
        # During the sweep every frame's counts are of that frame's levels: in each pane's caption
        # and in the box, equal to the rules' count for the levels the pane shows.
        for i in $(seq 15); do
            python3 - "$WORK/trace.json" <<'PY' || fail "presentation counts lag the sweep"
import json, sys
t = json.load(open(sys.argv[1]))
assert t['sweep']['playing']
for d in t['domain']:
    assert d['shown'][1] == d['expectedPrimitives'] and d['shown'][0] == d['expectedVertices'], d
    want = "%s: %d triangles" % (d['spacing'], d['shown'][1])
    assert want in t['presentationLines'], (want, t['presentationLines'])
PY
            sleep 0.1
        done
        # The text-scale setting from the keyboard: Ctrl+= a quarter step up, Ctrl+- back.
        SCALE=$(trace "t['presentationScale']")
        xdotool key ctrl+equal
        wait_for "t['presentationScale'] == $SCALE + 0.25 and t['domainTextPixels'] * 10 > $PX + 5"
        xdotool key ctrl+minus
        wait_for "t['presentationScale'] == $SCALE"
        say "sweep: every sampled frame's counts are its own levels'; Ctrl+= and Ctrl+- scale the text"
    fi
    xdotool key F5
    wait_for "not t['presentation']"
    if [ "$SIZE" = 1920x1080 ]; then
        click_item teach.play
        wait_for "not t['sweep']['playing']"
    fi
    if [ "$SIZE" = 1280x720 ]; then
        # The split 3D view presents too: its panes start right of the levels box, which lists
        # each pane's triangles from the frame that drew them.
        click_item teach.domain
        wait_for "len(t['domain']) == 0"
        click_item teach.splitView
        wait_for "len(t['viewPanes']) == 4"
        xdotool key F5
        wait_for "t['presentation'] and t['presentationOverlay'][1] > 0 and t['viewPanes'][0]['rect'][0] >= 16 + t['presentationOverlay'][0]"
        sleep 0.3
        import -window root -crop "${SIZE}+0+0" "$WORK/presentation-split-$SIZE.png"
        python3 - "$WORK/trace.json" <<'PY' || fail "split view presentation"
import json, sys
t = json.load(open(sys.argv[1]))
ov = t['presentationOverlay']
for p in t['viewPanes']:
    assert p['rect'][0] >= 16 + ov[0], ("pane under the levels box", p['rect'], ov)
    want = "%s: %d triangles" % (p['spacing'], p['triangles'])
    assert want in t['presentationLines'], (want, t['presentationLines'])
PY
        xdotool key F5
        wait_for "not t['presentation']"
        say "$SIZE: the split 3D view presents beside the levels box"
    fi
    check_validation
    say "$SIZE: domain view in four panes, labels apart and inside, gizmo clear; presentation labels $PX/10 px"
    quit_editor
done
say PASS

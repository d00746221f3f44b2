#!/usr/bin/env bash
# End-to-end modelling session under Xvfb, driven by xdotool as a person with Blender habits would,
# without typing a patch number: from an empty document, add a flat patch, place the 3D cursor
# (Ctrl+Shift+right click: on the grid) and add a second one there, join them by picking their facing edges (J, click,
# click, Enter: C1, the second matched onto the first), put the cursor on a corner, select linked
# (L) and Mirror Y from the Edit menu (four patches, joined C1 at the plane), raise the shared centre
# point (G Z 0.3 Enter), rotate everything (A, R Z 30 Enter), save (Ctrl+S) and check the file with
# `patchwork info --json`: 4 patches, 4 C1 joins holding, the centre raised.
# Usage: editor_modelling_e2e.sh PATCHWORK_BINARY DATA_DIR WORK_DIR
set -euo pipefail
BIN=$1
WORK=$3
rm -rf "$WORK"
mkdir -p "$WORK"
source "$(dirname "$0")/e2e_lib.sh"
export PATCHWORK_EDITOR_VIEW=top

MODEL=$WORK/cushion.patchwork
"$BIN" edit -q -o "$MODEL"
start_editor "$MODEL"
check_validation

# py EXPR: evaluates a Python expression over the trace t with helpers:
#   pix(i) the screen position of pool point i, pidx(p) patch p's 16 indices,
#   edge_mid(p, e) the screen midpoint of edge e (0 u0, 1 v0, 2 u1, 3 v1) of patch p, pulled 3 px into it.
py() {
    python3 - "$WORK/trace.json" "$1" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
def pix(i): return t['points'][i]
def pidx(p): return t['patchIdx'][p]
def slot(e, k, d=0): return [k*4+d, d*4+k, k*4+3-d, (3-d)*4+k][e]
def centre(p):
    pts = [pix(pidx(p)[s]) for s in (0, 3, 12, 15)]
    return [sum(q[0] for q in pts) / 4, sum(q[1] for q in pts) / 4]
def edge_mid(p, e):
    a, b = pix(pidx(p)[slot(e, 1)]), pix(pidx(p)[slot(e, 2)])
    m = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]
    c = centre(p); dx, dy = c[0] - m[0], c[1] - m[1]; n = (dx*dx + dy*dy) ** 0.5 or 1
    return [m[0] + 3 * dx / n, m[1] + 3 * dy / n]
def facing(p, q):  # the edge of p whose midpoint is nearest q's centre
    c = centre(q)
    return min(range(4), key=lambda e: (edge_mid(p, e)[0] - c[0])**2 + (edge_mid(p, e)[1] - c[1])**2)
r = eval(sys.argv[2])
print(' '.join(str(round(v)) for v in r) if isinstance(r, (list, tuple)) else r)
PY
}
EDGE_NAMES=(u0 v0 u1 v1)

# --- 1. a flat patch, the cursor beside it, a second patch there ------------------------------------
say "add a flat patch"
click_item op.addPatch
wait_for "t['patches'] == 1"
xdotool mousemove --sync 585 380; sleep 0.2; xdotool key f   # frame it, then zoom out
sleep 0.3; xdotool click 5 click 5 click 5 click 5
sleep 0.5
read -r X Y < <(py "[centre(0)[0] + 1.25 * (pix(pidx(0)[3])[0] - pix(pidx(0)[0])[0]), centre(0)[1]]")
say "place the 3D cursor at ($X, $Y), on the grid (Ctrl)"
xdotool mousemove --sync $X $Y; sleep 0.2
xdotool keydown ctrl keydown shift; xdotool click 3; xdotool keyup shift keyup ctrl
wait_for "t['cursor'][0] > 0.5"
click_item op.addPatch
wait_for "t['patches'] == 2 and t['joins'] == 0"
xdotool mousemove --sync 585 380; sleep 0.2; xdotool key a; sleep 0.2; xdotool key f; sleep 0.2; xdotool key alt+a; xdotool click 5 click 5
sleep 0.5

# --- 2. join them by picking the facing edges -------------------------------------------------------
EA=$(py "facing(0, 1)"); EB=$(py "facing(1, 0)")
say "join by picking: 0:${EDGE_NAMES[$EA]} then 1:${EDGE_NAMES[$EB]}"
xdotool key j
wait_for "t['joinTool']['on']"
read -r X Y < <(py "edge_mid(0, $EA)")
xdotool mousemove --sync $X $Y; sleep 0.1; xdotool mousemove --sync $((X + 1)) $Y
wait_for "t['joinTool']['hover'] == '0:${EDGE_NAMES[$EA]}'"
xdotool click 1
wait_for "t['joinTool']['first'] == '0:${EDGE_NAMES[$EA]}'"
read -r X Y < <(py "edge_mid(1, $EB)")
xdotool mousemove --sync $X $Y; sleep 0.1; xdotool mousemove --sync $((X - 1)) $Y
wait_for "t['joinTool']['hover'] is not None and t['joinTool']['hover'].startswith('1:')"
xdotool click 1
wait_for "t['joinTool']['preview'] and t['joins'] == 1"
import -window root "$WORK/join-preview.png" 2>/dev/null || true
xdotool key Return
wait_for "not t['joinTool']['on'] and t['joins'] == 1 and t['maxConstraintResidual'] < 1e-9"

# --- 3. the cursor on a corner of the far side, select linked, Mirror Y from the menu ---------------
# The corner of patch 0 highest on screen (largest y seen from above).
read -r X Y < <(py "min((pix(pidx(0)[s]) for s in (0, 3, 12, 15)), key=lambda q: q[1])")
say "cursor on the corner at ($X, $Y)"
xdotool mousemove --sync $X $Y; sleep 0.2
xdotool keydown shift; xdotool click 3; xdotool keyup shift
sleep 0.3
read -r X Y < <(py "centre(0)")
xdotool mousemove --sync $X $Y; sleep 0.2; xdotool click 1
wait_for "t['selectedPatch'] == 0"
xdotool key l
wait_for "len(t['selection']) == 28"
click_item menubar.Edit
wait_for "'menu.mirror.Y' in t['items']"
click_item menu.mirror.Y
wait_for "t['patches'] == 4 and t['joins'] == 4"

# --- 4. raise the centre point the four patches share, rotate everything -----------------------------
read -r C < <(py "[i for i in set(pidx(0)) if all(i in pidx(p) for p in range(4))][0]")
xdotool key Escape; sleep 0.2
read -r X Y < <(py "pix($C)")
say "move the shared centre point $C at ($X, $Y) up by 0.3"
xdotool mousemove --sync $X $Y
wait_for "t['hovered'] == $C"
xdotool click 1
wait_for "t['selection'] == [$C]"
xdotool key g; sleep 0.2; xdotool key z 0 period 3 Return
wait_for "t['mode'] == 0 and abs(t['world'][$C][2] - 0.3) < 1e-9"
xdotool mousemove --sync 600 650; sleep 0.2
xdotool key a; sleep 0.2; xdotool key r; sleep 0.2; xdotool key z 3 0 Return
wait_for "t['mode'] == 0 and t['maxConstraintResidual'] < 1e-9"

# --- 5. save and check the file -----------------------------------------------------------------------
xdotool key ctrl+s
wait_for "not t['modified']"
check_validation
quit_editor
"$BIN" info --json "$MODEL" > "$WORK/info.json"
python3 - "$WORK/info.json" "$MODEL" "$C" <<'PY' || fail "the saved cushion is wrong"
import json, sys
info = json.load(open(sys.argv[1])); doc = json.load(open(sys.argv[2])); c = int(sys.argv[3])
assert info['patches'] == 4, info['patches']
assert info['joins']['C1'] == 4 and info['joins']['total'] == 4, info['joins']
assert info['largest']['c1Residual'] < 1e-9 and info['largest']['c0Gap'] < 1e-9, info['largest']
z = doc['points'][c][2]
assert abs(z - 0.3) < 1e-9, z
print('cushion ok: 4 patches, 4 C1 joins, largest residual', info['largest']['c1Residual'])
PY
say "PASS"

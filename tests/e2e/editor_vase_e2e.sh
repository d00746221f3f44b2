#!/usr/bin/env bash
# End-to-end: a vase drawn and revolved as a person would (issue 39), under Xvfb, driven by xdotool.
# From an empty document in the front view: Draw Curve (C), click six profile points on the XZ
# plane through the 3D cursor (the first snapped onto the cursor, on the axis; the rest on the
# grid), Enter makes the C2 curve through them; Revolve in Surfaces from curves makes the vase
# about Z through the cursor. Then the profile's third point is dragged with the mouse and the vase
# follows live; Ctrl+S. The saved file must hold one live revolve of 4 x 5 patches, closed and
# joined around, the profile starting on the axis, every made point at its profile point's
# distance from the axis (rotated), and the dragged point moved.
# Usage: editor_vase_e2e.sh PATCHWORK_BINARY DATA_DIR WORK_DIR
set -euo pipefail
BIN=$1
WORK=$3
rm -rf "$WORK"
mkdir -p "$WORK"
source "$(dirname "$0")/e2e_lib.sh"
export PATCHWORK_EDITOR_VIEW=front

MODEL=$WORK/vase.patchwork
"$BIN" edit -q -o "$MODEL"
start_editor "$MODEL"
check_validation

# screen X Y of world point (x, y, z) through the traced view-projection
screen() {
    python3 - "$WORK/trace.json" "$@" <<'PY'
import json, sys
t = json.load(open(sys.argv[1])); M = t['viewProj']; pane = t['pane']
p = [float(v) for v in sys.argv[2:5]] + [1.0]
c = [sum(M[col * 4 + row] * p[col] for col in range(4)) for row in range(4)]
print(round(pane[0] + (c[0] / c[3] * 0.5 + 0.5) * pane[2]), round(pane[1] + (c[1] / c[3] * 0.5 + 0.5) * pane[3]))
PY
}

say "Draw Curve (C)"
xdotool mousemove --sync 700 400; sleep 0.2; xdotool key c
wait_for "t['curveTool']['on'] and t['curveTool']['plane'] == 1"
# The profile in the XZ plane through the cursor, scaled so that it is about 220 px tall (clear of
# the tool's panel at the top of the view).
read -r CX CY CZ < <(trace "' '.join(str(v) for v in t['cursor'])")
read -r SX0 SY0 < <(screen "$CX" "$CY" "$CZ")
read -r SX1 SY1 < <(screen "$CX" "$CY" "$(python3 -c "print($CZ + 1)")")
SCALE=$(python3 -c "print(round(220 / 3 / max(1, abs($SY1 - $SY0)), 3) or 0.1)")
say "cursor ($CX, $CY, $CZ); profile scale $SCALE"
N=0
for P in "0 0" "0.9 0.05" "1.3 0.8" "1.0 1.8" "0.55 2.5" "0.7 3"; do
    read -r PX PZ <<<"$P"
    read -r X Y < <(screen "$(python3 -c "print($CX + $PX * $SCALE)")" "$CY" "$(python3 -c "print($CZ + $PZ * $SCALE)")")
    xdotool mousemove --sync "$X" "$Y"; sleep 0.3
    [ $N = 0 ] && wait_for "t['curveTool']['snapped'] == '3D cursor'"
    xdotool click 1
    N=$((N + 1))
    wait_for "t['curveTool']['points'] == $N"
done
say "six points clicked; Enter"
xdotool key Return
wait_for "t['curves'] == 1 and not t['curveTool']['on']"

say "Revolve (Surfaces from curves; the left panel scrolled down to it)"
xdotool mousemove --sync 140 500; sleep 0.2
for i in 1 2 3 4 5 6 7 8 9 10; do
    python3 -c "import json,sys; t=json.load(open('$WORK/trace.json')); sys.exit(0 if t['items']['op.revolve'][1] < t['window'][1] - 20 else 1)" && break
    xdotool click 5; sleep 0.3
done
click_item op.revolve
wait_for "t['patches'] == 20 and t['joins'] == 36"
check_validation

# Drag the profile's third point (pool point 2: curve-through numbers its points in order) 40 px out.
read -r X Y < <(trace "' '.join(str(round(v)) for v in t['points'][6])")
BEFORE=$(trace "t['world'][6][0]")
say "drag profile point at ($X, $Y)"
xdotool mousemove --sync "$X" "$Y"; sleep 0.3
xdotool mousedown 1; sleep 0.2
for i in 1 2 3 4 5 6 7 8; do xdotool mousemove --sync $((X + 5 * i)) "$Y"; sleep 0.1; done
sleep 0.3; xdotool mouseup 1
wait_for "t['mode'] == 0 and t['world'][6][0] > $BEFORE + 1e-6 and t['maxConstraintResidual'] < 1e-9"

xdotool key ctrl+s
wait_for "not t['modified']"
check_validation
import -window root "$WORK/vase.png" 2>/dev/null || true
quit_editor
python3 - "$MODEL" "$BEFORE" <<'PY' || fail "the saved vase is wrong"
import json, math, sys
doc = json.load(open(sys.argv[1])); before = float(sys.argv[2])
pts, cons = doc['points'], doc['constructions']
assert len(cons) == 1 and cons[0]['kind'] == 'revolve', cons
k = cons[0]
assert len(k['patches']) == 20 and k['rows'] == 16 and k['cols'] == 13, (len(k['patches']), k['rows'], k['cols'])
o, axis = k['origin'], k['vector']
assert axis == [0, 0, 1], axis
prof = doc['curves'][0]['idx']
def radius(p): return math.hypot(p[0] - o[0], p[1] - o[1])
assert radius(pts[prof[0]]) < 1e-12, 'the profile starts on the axis'
assert pts[6][0] > before + 1e-6, 'the dragged point moved'
w = doc.get('weights', [])
for i in range(k['rows']):
    r = radius(pts[prof[i]])
    for j in (0, 3, 6, 9):  # the arc's segment ends lie on the circle of the profile point
        q = pts[k['grid'][i * k['cols'] + j]]
        assert abs(radius(q) - r) < 1e-9 and abs(q[2] - pts[prof[i]][2]) < 1e-9, (i, j)
print('vase ok: 20 live patches, profile on the axis, rows on their circles')
PY
say "PASS"

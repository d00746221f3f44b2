#!/usr/bin/env bash
# The teaching features in the running editor, under Xvfb with the validation layer on: the domain
# view's GPU counts match the tessellation rules for the document's levels, live as a preset shows
# them (as a lesson: the document's levels stay; "Keep in document" is one undo step) and across
# comparison panes; the sweep animates the lesson's level and leaves the document alone;
# the shader panel shows the variants the settings select;
# presentation mode (F5) hides the panels and comes back; the Bézier math labels a patch's control
# points with their weights and follows a click on the surface. Screenshots in WORK_DIR.
# Usage: editor_teaching_e2e.sh PATCHWORK_BINARY DATA_DIR WORK_DIR
set -euo pipefail
BIN=$1
WORK=$3
rm -rf "$WORK"
mkdir -p "$WORK"
source "$(dirname "$0")/e2e_lib.sh"
for tool in xmllint ffprobe; do command -v $tool >/dev/null || missing_tool $tool; done

start_editor
check_validation
click_item panel.teaching
wait_for "'teach.domain' in t['items']"
click_item teach.domain
# Teapot levels 16, equal spacing: 17 x 17 vertices, 2 x 16 x 16 triangles, counted on the GPU.
wait_for "len(t['domain']) == 1 and t['domain'][0]['vertices'] == 289 and t['domain'][0]['primitives'] == 512"
import -window root "$WORK/domain.png"
say "domain view: 289 vertices, 512 triangles at level 16"

# A preset of the notes: quad {1,2,3,4 | 4,4} -> 19 vertices, 26 triangles.
click_item teach.preset
wait_for "'preset.quad-1_2_3_4-4_4' in t['items']"
STEPS=$(trace "t['undoSteps']")
click_item preset.quad-1_2_3_4-4_4
# Shown as a lesson: the view and the domain use the preset's levels, the document keeps its own.
wait_for "t['lesson']['active'] and t['lesson']['outer'] == [1, 2, 3, 4] and t['domain'][0]['vertices'] == 19 and t['domain'][0]['primitives'] == 26"
wait_for "t['tessOuter'] == [16, 16, 16, 16] and t['undoSteps'] == $STEPS and not t['modified']"
import -window root "$WORK/preset.png"
say "preset quad {1,2,3,4 | 4,4}: 19 vertices, 26 triangles; the document's levels untouched"
# "Keep in document": one undo step; undo brings the document's levels back.
xdotool mousemove --sync 1030 500
for i in 1 2 3 4 5 6; do xdotool click 5; sleep 0.05; done
wait_for "t['items']['teach.lessonKeep'][1] < 740"
click_item teach.lessonKeep
wait_for "not t['lesson']['active'] and t['tessOuter'] == [1, 2, 3, 4] and t['undoSteps'] == $STEPS + 1"
xdotool mousemove --sync 640 700
xdotool key ctrl+z
wait_for "t['tessOuter'] == [16, 16, 16, 16] and t['domain'][0]['vertices'] == 289"
say "keep in document: one undo step, undone"
for i in 1 2 3 4 5 6; do xdotool mousemove --sync 1030 300; xdotool click 4; sleep 0.05; done
wait_for "t['items']['teach.preset'][1] > 60"

# Shader panel: the stages in use follow the settings. The teapot draws with the fixed-level-free
# control shader (off-screen culling on) and equal spacing; the domain pane adds its own pipeline.
click_item teach.shaders
wait_for "t['shaders']['open'] and t['shaders']['shown'] == 'surface_vert' and 'domain_tese_quad_equal' in t['shaders']['inUse']"
click_item shaders.tab.surface_tese_equal
wait_for "t['shaders']['shown'] == 'surface_tese_equal'"
# The notes' fractional example under fractional_odd switches the evaluation stage to its variant.
click_item teach.preset
wait_for "'preset.tri-4.9_4.5_4.1-4.4-fractional_odd' in t['items']"
click_item preset.tri-4.9_4.5_4.1-4.4-fractional_odd
wait_for "t['shaders']['shown'] == 'surface_tese_odd' and 'domain_tese_tri_odd' in t['shaders']['inUse']"
import -window root "$WORK/shaders.png"
FULL=$(trace "t['shaders']['lines']")
# The teaching listing: the marked parts only, a slide's length.
click_item shaders.teaching
wait_for "t['shaders']['teaching'] and 15 <= t['shaders']['lines'] <= 40 and t['shaders']['lines'] < $FULL / 4"
import -window root "$WORK/shaders_teaching.png"
LINES=$(trace "t['shaders']['lines']")
click_item shaders.teaching
wait_for "not t['shaders']['teaching'] and t['shaders']['lines'] == $FULL"
say "shader panel: surface_tese_equal, then surface_tese_odd after the fractional_odd preset ($FULL lines; teaching listing $LINES)"

# The isoline domain on the model: the isocurve overlay, then a Bézier curve; both show up in the
# shader panel with the document's partitioning, and adding the curve is one undo step. (The kept
# preset's undone step is dropped by the next edit.)
STEPS=$(trace "t['undoSteps'] - 1")
click_item display.showIsocurves
wait_for "t['isocurves'] and 'isocurve_tese_odd' in t['shaders']['inUse']"
click_item op.addCurve
wait_for "t['curves'] == 1 and 'curve_tese_odd' in t['shaders']['inUse'] and t['undoSteps'] == $STEPS + 2"
import -window root "$WORK/curves.png"
xdotool mousemove --sync 640 700
xdotool key ctrl+z
wait_for "t['curves'] == 0 and 'curve_tese_odd' not in t['shaders']['inUse']"
xdotool key ctrl+shift+z
wait_for "t['curves'] == 1 and t['undoSteps'] == $STEPS + 2"
check_validation
say "isocurves and a curve through the isoline tessellator; undo removes the curve, redo brings it back"
STEPS=$(trace "t['undoSteps']")

# Split 3D view: two panes of the model, equal and fractional_odd, each counted on its own; a pane's
# own level; a drag in the second pane moves the point under the mouse there. (The domain and
# shader windows are closed first so that they do not cover the panes.)
wait_for "t['triangles'] > 0"
SINGLE=$(trace "t['triangles']")
click_item teach.domain
click_item teach.shaders
wait_for "not t['shaders']['open'] and len(t['domain']) == 0"
click_item teach.panes2
wait_for "'teach.splitView' in t['items']"
click_item teach.splitView
wait_for "len(t['viewPanes']) == 2 and [p['spacing'] for p in t['viewPanes']] == ['equal', 'fractional_odd']"
# The preset's levels {4.9,4.5,4.1 | 4.4} cut 5 segments on every teapot edge under both rules.
wait_for "t['viewPanes'][0]['triangles'] == 32 * 2 * 25 and t['viewPanes'][1]['triangles'] == $SINGLE"
click_item teach.paneLevel1
wait_for "t['viewPanes'][1]['level'] > 8"
python3 - "$WORK/trace.json" <<'PY' || fail "pane level count"
import json, math, sys
t = json.load(open(sys.argv[1]))
p = t['viewPanes'][1]
n = math.ceil(p['level'])
n += 1 - n % 2  # fractional_odd: the next odd segment count
assert p['triangles'] == 32 * 2 * n * n, (p, n)
print("pane level", p['level'], "->", n, "segments,", p['triangles'], "triangles")
PY
read -r RX RY RW RH < <(trace "' '.join(str(round(v)) for v in t['viewPanes'][1]['rect'])")
xdotool mousemove --sync $((RX + RW / 2)) $((RY + RH / 2))
wait_for "t['activePane'] == 1"
# A point of the net inside the second pane, away from its edges.
IDX=$(python3 - "$WORK/trace.json" "$RX" "$RY" "$RW" "$RH" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
x, y, w, h = map(float, sys.argv[2:])
pts = t['points']
# Only points with no other point within 8 px: on the teapot's seams points coincide on screen.
alone = lambda i, p: all(j == i or not q or abs(q[0] - p[0]) + abs(q[1] - p[1]) > 8 for j, q in enumerate(pts))
best = min((abs(p[0] - x - w / 2) + abs(p[1] - y - h / 2), i) for i, p in enumerate(pts)
           if p and x + 40 < p[0] < x + w - 40 and y + 80 < p[1] < y + h - 40 and alone(i, p))
print(best[1])
PY
)
ORIG=$(trace "t['world'][$IDX]")
read -r PX PY < <(trace "' '.join(str(round(v)) for v in t['points'][$IDX])")
xdotool mousemove --sync $PX $PY
wait_for "t['hovered'] == $IDX"
xdotool mousedown 1
for d in 10 20 30; do xdotool mousemove --sync $PX $((PY - d)); sleep 0.1; done
xdotool mouseup 1
wait_for "t['mode'] == 0 and t['world'][$IDX] != $ORIG and t['undoSteps'] == $STEPS + 1"
python3 - "$WORK/trace.json" "$IDX" "$PX" "$PY" <<'PY' || fail "the dragged point is not under the mouse in pane 2"
import json, sys
t = json.load(open(sys.argv[1]))
i, px, py = int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
p = t['points'][i]
assert abs(p[0] - px) < 4 and abs(p[1] - (py - 30)) < 4, (p, px, py - 30)
PY
xdotool key ctrl+z
wait_for "t['world'][$IDX] == $ORIG"
click_item teach.panes1
click_item teach.domain
wait_for "len(t['viewPanes']) == 0 and len(t['domain']) == 1"
check_validation
say "split view: equal and fractional_odd panes counted apart, a pane's own level, a drag in pane 2"
STEPS=$(trace "t['undoSteps']")  # the sweep edits nothing, so the undone drag stays redoable

# Sweep: play, the level moves; pause, one undo step more. (Scroll the properties panel so that the
# sweep controls are in view.)
xdotool mousemove --sync 1030 500
for i in 1 2 3 4 5 6; do xdotool click 5; sleep 0.05; done
wait_for "t['items']['teach.play'][1] < 740"
click_item teach.play
wait_for "t['sweep']['playing'] and t['sweep']['level'] > 2"
click_item teach.play
# The sweep drives the lesson's levels: no undo step, the document's levels as they were.
wait_for "not t['sweep']['playing'] and t['undoSteps'] == $STEPS and t['lesson']['active'] and t['lesson']['name'] == 'Sweep'"
wait_for "t['tessOuter'] == [16, 16, 16, 16]"
wait_for "all(d['vertices'] == d['expectedVertices'] and d['primitives'] == d['expectedPrimitives'] for d in t['domain'])"
say "sweep stopped at level $(trace "round(t['sweep']['level'], 2)"); counts still follow the rules; the document unchanged"
click_item teach.lessonBack
wait_for "not t['lesson']['active'] and t['lesson']['outer'] == [16, 16, 16, 16]"
say "back to the document's levels"

# Figures for slides from the editor: the domain view (one pane, the document's level 16) as an SVG
# with one closed path per triangle the GPU made, and the sweep as a GIF with one frame per step
# (10 a second).
WANT=$(trace "t['domain'][0]['primitives']")
xdotool mousemove --sync 640 700
xdotool key F3
wait_for "t['palette']"
sleep 0.3
xdotool type --delay 30 "domain-figure $WORK/domain.svg"
xdotool key Return
for i in $(seq 150); do [ -s "$WORK/domain.svg" ] && break; sleep 0.1; done
xmllint --noout "$WORK/domain.svg" || fail "the domain figure is not well-formed SVG"
python3 - "$WORK/domain.svg" "$WANT" <<'PY' || fail "the domain figure's paths"
import re, sys
svg = open(sys.argv[1]).read()
page = svg[svg.index('</defs>'):]
tri = re.compile(r'^M [-0-9.e]+ [-0-9.e]+ L [-0-9.e]+ [-0-9.e]+ L [-0-9.e]+ [-0-9.e]+ Z( M [-0-9.e]+ [-0-9.e]+)? ?$')
n = sum(1 for d in re.findall(r'<path[^>]* d="([^"]*)"', page) if tri.match(d))
assert n == int(sys.argv[2]), (n, sys.argv[2])
print("domain.svg:", n, "triangle paths")
PY
FRAMES=$(trace "round(t['sweep']['seconds'] * 10) + 1")
xdotool key F3
wait_for "t['palette']"
sleep 0.3
xdotool type --delay 30 "sweep-animation $WORK/sweep.gif"
xdotool key Return
for i in $(seq 600); do [ -s "$WORK/sweep.gif" ] && break; sleep 0.1; done
GOT=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$WORK/sweep.gif")
[ "$GOT" = "$FRAMES" ] || fail "sweep.gif has $GOT frames, not $FRAMES"
check_validation
say "domain figure as SVG ($WANT triangle paths) and the sweep as a GIF of $FRAMES frames, from the editor"

# Presentation mode hides the panels (their items vanish from the trace) and F5 brings them back.
xdotool mousemove --sync 640 700
xdotool key F5
wait_for "t['presentation'] and 'panel.teaching' not in t['items']"
import -window root "$WORK/presentation.png"
xdotool key F5
wait_for "not t['presentation'] and 'panel.teaching' in t['items']"
check_validation
say "presentation mode on and off"

# The Bézier math: on, the 16 control points of a patch carry their Bernstein weights (17 labels
# with the point's); a click on the surface picks the patch and its (u, v), and the numbers follow.
xdotool mousemove --sync 1030 500
for i in 1 2 3 4 5 6; do xdotool click 5; sleep 0.05; done
wait_for "t['items']['teach.math'][1] < 740"
# The notes' convention, kept with the document: the upper-left origin, an edit Ctrl+Z undoes.
click_item teach.upperLeft
wait_for "len(t['domain']) == 1 and t['domain'][0]['upperLeft'] and t['modified']"
import -window root "$WORK/domain_upper_left.png"
xdotool mousemove --sync 640 700
xdotool key ctrl+z
wait_for "not t['domain'][0]['upperLeft']"
say "domain view: upper-left origin on, undone"
click_item teach.domain  # the domain window out of the view
wait_for "len(t['domain']) == 0"
click_item teach.math
wait_for "t['math']['on'] and t['math']['labels'] == 17 and len(t['math']['lines']) == 8 and t['math']['patch'] == -1"
read -r MX MY < <(trace "' '.join(str(round(v)) for v in [(t['layout']['left'] + t['window'][0] - t['layout']['right']) / 2, t['window'][1] / 2 + 40])")
xdotool mousemove --sync "$MX" "$MY"
sleep 0.2
xdotool click 1
wait_for "t['math']['patch'] >= 0 and (t['math']['u'], t['math']['v']) != (0.35, 0.6) and t['math']['lines'][1].startswith('u = ')"
python3 - "$WORK/trace.json" <<'PY' || fail "Bezier math numbers"
import json, sys
t = json.load(open(sys.argv[1]))
m = t['math']
assert m['lines'][1] == "u = %.3f   v = %.3f" % (m['u'], m['v']), m['lines']
for line in m['lines'][2:4]:  # B(u), B(v): four Bernstein weights summing to 1
    b = [float(x) for x in line.split('=')[1].split()]
    assert len(b) == 4 and abs(sum(b) - 1) < 0.003, line
PY
import -window root "$WORK/bezier_math.png"
click_item teach.math
wait_for "not t['math']['on'] and t['math']['labels'] == 0"
# Stage counters: four rows of the GPU's counts, one control shader patch per teapot patch.
click_item teach.stageBars
wait_for "t['stageBarRows'] == 4 and t['tcsPatches'] == 32 and t['tesInvocations'] == 32 * 17 * 17 and 0 < t['vsInvocations'] <= 32 * 16"
import -window root "$WORK/stage_bars.png"
click_item teach.stageBars
wait_for "t['stageBarRows'] == 0"
# Debug camera: the view frozen as the camera that decides culling; zooming far in then culls
# nothing more (the frozen view sees every patch), the same triangles are drawn; off, the zoomed
# view decides again and culls the patches off its screen.
wait_for "t['patchesCulled'] == 0"
TRIS=$(trace "t['triangles']")
click_item teach.debugCamera
wait_for "t['debugCamera']"
xdotool mousemove --sync 640 380
for _ in 1 2 3 4 5 6 7 8 9 10; do xdotool click 4; sleep 0.1; done
sleep 1
wait_for "t['patchesCulled'] == 0 and t['triangles'] == $TRIS"
import -window root "$WORK/debug_camera.png"
click_item teach.debugCamera
wait_for "not t['debugCamera'] and t['patchesCulled'] > 0"
say "debug camera: the frozen view culls nothing, the zoomed view culls $(trace "t['patchesCulled']") patches"
xdotool mousemove --sync 640 380
for _ in 1 2 3 4 5 6 7 8 9 10; do xdotool click 5; sleep 0.1; done
wait_for "t['patchesCulled'] == 0"
check_validation
click_item teach.domain
wait_for "len(t['domain']) == 1"
check_validation
say "Bezier math: patch $(trace "t['math']['patch']") at (u, v) = ($(trace "round(t['math']['u'], 3)"), $(trace "round(t['math']['v'], 3)")) picked on the surface"

# Bézier triangles in the editor: a new document (one flat patch), seen from the top; the patch is
# picked by its surface and deleted, a triangle added, picked by its surface, deleted with the
# Delete key, and brought back by undo.
xdotool mousemove --sync 640 700
xdotool key ctrl+n
wait_for "t['modal'] == 'unsaved' or t['file'] == ''"
if [ "$(trace "t['modal']")" = "unsaved" ]; then click_item unsaved.discard; fi
wait_for "t['patches'] == 1 and t['bezierTriangles'] == 0 and t['modal'] == ''"
click_item teach.domain  # out of the way of the clicks
wait_for "len(t['domain']) == 0"
xdotool mousemove --sync 640 700
xdotool key 7 alt+a
# click_centre: clicks the surface 16 pixels below the mean of the projected points in use (a
# triangle's centre is a control point, which a click would select instead).
click_centre() {
    read -r CX CY < <(trace "' '.join(str(round(sum(p[k] for p in t['points'] if p) / len([p for p in t['points'] if p]))) for k in (0, 1))")
    xdotool mousemove --sync $CX $((CY + 16))
    sleep 0.2
    xdotool click 1
}
click_centre
wait_for "t['selectedPatch'] == 0"
xdotool key Delete
wait_for "t['patches'] == 0"
click_item op.addTriangle
wait_for "t['bezierTriangles'] == 1 and t['selectedTriangle'] == 0"
xdotool mousemove --sync 640 700
xdotool key alt+a
wait_for "t['selectedTriangle'] == -1"
click_centre
wait_for "t['selectedTriangle'] == 0"
xdotool key Delete
wait_for "t['bezierTriangles'] == 0 and t['selectedTriangle'] == -1"
xdotool key ctrl+z
wait_for "t['bezierTriangles'] == 1"
check_validation
say "Bézier triangle: added, picked by its surface, deleted, restored by undo"

quit_editor
say "PASS"

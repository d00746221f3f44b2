#!/usr/bin/env bash
# The teaching features in the running editor, under Xvfb with the validation layer on: the domain
# view's GPU counts match the tessellation rules for the document's levels, live as a preset changes
# them and across comparison panes; the sweep animates the level and pausing leaves one undo step;
# the shader panel shows the variants the settings select;
# presentation mode (F5) hides the panels and comes back. Screenshots in WORK_DIR.
# Usage: editor_teaching_e2e.sh PATCHWORK_BINARY DATA_DIR WORK_DIR
set -euo pipefail
BIN=$1
WORK=$3
rm -rf "$WORK"
mkdir -p "$WORK"
source "$(dirname "$0")/e2e_lib.sh"

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
click_item preset.quad-1_2_3_4-4_4
wait_for "t['tessOuter'] == [1, 2, 3, 4] and t['domain'][0]['vertices'] == 19 and t['domain'][0]['primitives'] == 26"
import -window root "$WORK/preset.png"
say "preset quad {1,2,3,4 | 4,4}: 19 vertices, 26 triangles"
STEPS=$(trace "t['undoSteps']")

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
say "shader panel: surface_tese_equal, then surface_tese_odd after the fractional_odd preset"

# The isoline domain on the model: the isocurve overlay, then a Bézier curve; both show up in the
# shader panel with the document's partitioning, and adding the curve is one undo step.
STEPS=$(trace "t['undoSteps']")
click_item display.isocurves
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
STEPS=$(trace "t['undoSteps']")

# Sweep: play, the level moves; pause, one undo step more. (Scroll the properties panel so that the
# sweep controls are in view.)
xdotool mousemove --sync 1030 500
for i in 1 2 3 4 5 6; do xdotool click 5; sleep 0.05; done
wait_for "t['items']['teach.play'][1] < 740"
click_item teach.play
wait_for "t['sweep']['playing'] and t['sweep']['level'] > 2"
click_item teach.play
wait_for "not t['sweep']['playing'] and t['undoSteps'] == $STEPS + 1"
wait_for "all(d['vertices'] == d['expectedVertices'] and d['primitives'] == d['expectedPrimitives'] for d in t['domain'])"
say "sweep stopped at level $(trace "round(t['sweep']['level'], 2)"); counts still follow the rules"

# Presentation mode hides the panels (their items vanish from the trace) and F5 brings them back.
xdotool mousemove --sync 640 700
xdotool key F5
wait_for "t['presentation'] and 'panel.teaching' not in t['items']"
import -window root "$WORK/presentation.png"
xdotool key F5
wait_for "not t['presentation'] and 'panel.teaching' in t['items']"
check_validation
say "presentation mode on and off"

quit_editor
say "PASS"

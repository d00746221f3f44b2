// Editor selection and camera navigation, pure (no Vulkan): which control points and which patch
// are selected, click / shift-click / box rules, and Blender-style orbit, pan and zoom.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace select {

struct Selection {
    std::vector<uint32_t> points;  // sorted, unique pool indices
    int patch = -1;                // Document::patches index, -1 = none
    int surface = -1;              // Document::surfaces index (a net), -1 = none
    int curve = -1;                // Document::curves index, -1 = none
    int triangle = -1;             // Document::triangles index (a Bézier triangle), -1 = none
    int active = -1;               // the active point: the last one clicked (pivot "active"), -1 = none

    bool contains(uint32_t p) const;
    bool empty() const { return points.empty() && patch < 0 && surface < 0 && curve < 0 && triangle < 0; }
    void clear() {
        points.clear();
        patch = -1;
        surface = -1;
        curve = -1;
        triangle = -1;
        active = -1;
    }
    bool operator==(const Selection&) const = default;
};

// A click on point `picked` (-1: empty space). Without shift the selection becomes that point
// (or nothing); with shift the point is toggled and the rest kept.
void applyClick(Selection& sel, int picked, bool shift);
// A finished box: without shift the selection becomes the boxed points; with shift they are added.
void applyBox(Selection& sel, const std::vector<uint32_t>& boxed, bool shift);
// Drops indices that no longer exist (after an edit shrank the pool or the patch list).
void clampSelection(Selection& sel, const Document& doc);

// Mean of the selected points (or of the selected patch's, net's, triangle's or curve's points); the origin when empty.
Vec3 selectionCentroid(const Document& doc, const Selection& sel);
// What rotations and scales turn about (Blender's pivot point): the median of the moved points,
// the active element (the last clicked point, else the selected patch's, net's, triangle's or
// curve's centre, else the median) or the 3D cursor.
enum class PivotMode { Median, Active, Cursor };
std::string_view pivotName(PivotMode m);  // "median", "active", "cursor"
std::optional<PivotMode> parsePivot(std::string_view name);
Vec3 transformPivot(const Document& doc, const Selection& sel, const std::vector<uint32_t>& moved, PivotMode mode, const Vec3& cursor);

// Bounds of what F frames: the selected points, else the selected patch, net, triangle or curve, else the whole model.
Bounds frameTargetBounds(const Document& doc, const Selection& sel);

// --- Camera navigation (pixel deltas, y down) ---
// Orbit: dragging right turns the view right around the target (yaw), up/down changes the pitch
// (clamped to ±90°). `degPerPixel` scales the motion.
void orbitCamera(Camera& cam, double dxPx, double dyPx, double degPerPixel = 0.4);
// Pan: the target moves so the point under the cursor follows the mouse (exact for the target plane).
void panCamera(Camera& cam, double dxPx, double dyPx, int viewportHeightPx);
// Zoom: positive steps (wheel up) move closer; each step scales the distance by `factor`.
void zoomCamera(Camera& cam, double steps, double factor = 0.85);
// World-space right and up vectors of the view.
void cameraAxes(const Camera& cam, Vec3& right, Vec3& up, Vec3& forward);

}  // namespace select
}  // namespace pw

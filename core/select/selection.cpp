#include "core/select/selection.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/base/enum_names.hpp"
#include "core/model/camera_math.hpp"

namespace pw {
inline namespace select {

bool Selection::contains(uint32_t p) const { return std::binary_search(points.begin(), points.end(), p); }

void applyClick(Selection& sel, int picked, bool shift) {
    if (!shift) {
        sel.points.clear();
        if (picked >= 0) sel.points.push_back(uint32_t(picked));
        sel.active = picked;
        return;
    }
    if (picked < 0) return;
    const auto it = std::lower_bound(sel.points.begin(), sel.points.end(), uint32_t(picked));
    if (it != sel.points.end() && *it == uint32_t(picked)) {
        sel.points.erase(it);
        if (sel.active == picked) sel.active = -1;
    } else {
        sel.points.insert(it, uint32_t(picked));
        sel.active = picked;
    }
}

void applyBox(Selection& sel, const std::vector<uint32_t>& boxed, bool shift) {
    if (!shift) sel.points.clear();
    sel.points.insert(sel.points.end(), boxed.begin(), boxed.end());
    std::sort(sel.points.begin(), sel.points.end());
    sel.points.erase(std::unique(sel.points.begin(), sel.points.end()), sel.points.end());
}

void clampSelection(Selection& sel, const Document& doc) {
    std::erase_if(sel.points, [&](uint32_t p) { return p >= doc.points.size(); });
    if (sel.patch >= int(doc.patches.size())) sel.patch = -1;
    if (sel.surface >= int(doc.surfaces.size())) sel.surface = -1;
    if (sel.curve >= int(doc.curves.size())) sel.curve = -1;
    if (sel.triangle >= int(doc.triangles.size())) sel.triangle = -1;
    if (sel.active >= int(doc.points.size())) sel.active = -1;
}

namespace {
constexpr std::array<std::string_view, 3> kPivotNames{"median", "active", "cursor"};
}  // namespace

std::string_view pivotName(PivotMode m) { return enumName(m, kPivotNames); }
std::optional<PivotMode> parsePivot(std::string_view name) { return parseEnum<PivotMode>(name, kPivotNames); }

Vec3 transformPivot(const Document& doc, const Selection& sel, const std::vector<uint32_t>& moved, PivotMode mode, const Vec3& cursor) {
    if (mode == PivotMode::Cursor) return cursor;
    if (mode == PivotMode::Active) {
        if (sel.active >= 0 && size_t(sel.active) < doc.points.size() && sel.contains(uint32_t(sel.active)))
            return doc.points[size_t(sel.active)];
        Selection item = sel;  // the selected patch, net, triangle or curve: its centre
        item.points.clear();
        if (!item.empty()) return selectionCentroid(doc, item);
    }
    return selectionCentroid(doc, Selection{.points = moved});
}

namespace {
// The selected points, else the points of the selected patch, net, triangle or curve.
std::vector<Vec3> selectedPositions(const Document& doc, const Selection& sel) {
    std::vector<Vec3> pts;
    auto add = [&](uint32_t p) {
        if (p < doc.points.size()) pts.push_back(doc.points[p]);
    };
    for (uint32_t p : sel.points) add(p);
    if (pts.empty() && sel.patch >= 0 && sel.patch < int(doc.patches.size()))
        for (uint32_t p : doc.patches[size_t(sel.patch)].idx) add(p);
    if (pts.empty() && sel.surface >= 0 && sel.surface < int(doc.surfaces.size()))
        for (uint32_t p : doc.surfaces[size_t(sel.surface)].idx) add(p);
    if (pts.empty() && sel.triangle >= 0 && sel.triangle < int(doc.triangles.size()))
        for (uint32_t p : doc.triangles[size_t(sel.triangle)].idx) add(p);
    if (pts.empty() && sel.curve >= 0 && sel.curve < int(doc.curves.size()))
        for (uint32_t p : doc.curves[size_t(sel.curve)].idx) add(p);
    return pts;
}
}  // namespace

Vec3 selectionCentroid(const Document& doc, const Selection& sel) {
    Vec3 c(0.0);
    const std::vector<Vec3> pts = selectedPositions(doc, sel);
    for (const Vec3& p : pts) c += p;
    return pts.empty() ? c : c / double(pts.size());
}

Bounds frameTargetBounds(const Document& doc, const Selection& sel) {
    const std::vector<Vec3> pts = selectedPositions(doc, sel);
    if (pts.empty()) return computeBounds(doc.points);
    Bounds b = computeBounds(pts);
    // A single point (or a flat set) still gets a sensible view: pad to 5 % of the model.
    const double pad = 0.05 * modelSize(doc);
    if (b.diagonal() < pad) {
        b.min -= Vec3(pad);
        b.max += Vec3(pad);
    }
    return b;
}

void cameraAxes(const Camera& cam, Vec3& right, Vec3& up, Vec3& forward) {
    const ViewMatrices vm = viewMatrices(cam, 1.0);
    right = glm::normalize(Vec3(vm.view[0][0], vm.view[1][0], vm.view[2][0]));
    up = glm::normalize(Vec3(vm.view[0][1], vm.view[1][1], vm.view[2][1]));
    forward = glm::normalize(Vec3(vm.forward));
}

void orbitCamera(Camera& cam, double dxPx, double dyPx, double degPerPixel) {
    cam.yawDeg = std::fmod(cam.yawDeg - dxPx * degPerPixel, 360.0);
    cam.pitchDeg = std::clamp(cam.pitchDeg + dyPx * degPerPixel, -90.0, 90.0);
}

void panCamera(Camera& cam, double dxPx, double dyPx, int viewportHeightPx) {
    Vec3 right, up, fwd;
    cameraAxes(cam, right, up, fwd);
    const double worldPerPx =
        2.0 * cam.distance * std::tan(cam.fovYDeg * 3.14159265358979323846 / 360.0) / double(std::max(viewportHeightPx, 1));
    const Vec3 t = Vec3(cam.target[0], cam.target[1], cam.target[2]) - right * (dxPx * worldPerPx) + up * (dyPx * worldPerPx);
    cam.target = {t.x, t.y, t.z};
}

void zoomCamera(Camera& cam, double steps, double factor) { cam.distance = std::clamp(cam.distance * std::pow(factor, steps), 1e-6, 1e9); }

}  // namespace select
}  // namespace pw

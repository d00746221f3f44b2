#include "core/tess/tess_presets.hpp"

#include "core/gpu/patch_math.h"

#include <stdexcept>

#include <algorithm>

#include "core/model/camera_math.hpp"

namespace pw {
inline namespace tess {

namespace {

void nameIt(TessPreset& p) {
    const int nOuter = outerLevelCount(p.kind), nInner = innerLevelCount(p.kind);
    p.name = std::string(domainName(p.kind)) + "-" + joinLevels(p.levels.outer.data(), nOuter, "_") + "-" +
             joinLevels(p.levels.inner.data(), nInner, "_");
    p.label = describeLevels(p.kind, p.levels);
    if (p.spacing != Spacing::Equal) {
        p.name += "-" + std::string(spacingName(p.spacing));
        p.label += " " + std::string(spacingName(p.spacing));
    }
}

TessPreset quad(std::array<float, 4> o, std::array<float, 2> in, const char* note) {
    TessPreset p;
    p.kind = DomainKind::Quad;
    p.levels = {o, in};
    nameIt(p);
    p.note = note;
    return p;
}

TessPreset tri(std::array<float, 3> o, float in, Spacing s, const char* note) {
    TessPreset p;
    p.kind = DomainKind::Triangle;
    p.levels = {{o[0], o[1], o[2], 0.0f}, {in, 0.0f}};
    p.spacing = s;
    nameIt(p);
    p.note = note;
    return p;
}

}  // namespace

const std::vector<TessPreset>& tessPresets() {
    static const std::vector<TessPreset> presets = {
        quad({4, 4, 4, 4}, {4, 4}, "uniform: every edge and the interior split in four"),
        quad({1, 2, 3, 4}, {4, 4}, "each edge its own level; the interior stays 4 x 4"),
        quad({2, 2, 4, 4}, {2, 4}, "different inner levels along u and v"),
        quad({4, 4, 4, 4}, {3, 3}, "inner 3 inside outer 4: the transition ring absorbs the difference"),
        quad({3, 3, 3, 3}, {3, 3}, "odd uniform level"),
        tri({4, 4, 4}, 4, Spacing::Equal, "uniform triangle: concentric rings"),
        tri({1, 2, 3}, 4, Spacing::Equal, "each edge its own level"),
        tri({6, 6, 6}, 3, Spacing::Equal, "fine edges around a coarse interior"),
        tri({6, 12, 3}, 1, Spacing::Equal, "inner 1: no interior ring, edges fan to the centre"),
        tri({6, 12, 3}, 2, Spacing::Equal, "inner 2: a single centre vertex"),
        tri({3, 3, 3}, 3, Spacing::Equal, "odd uniform level: a small triangle in the middle"),
        tri({3, 3, 3}, 4, Spacing::Equal, "inner 4 inside outer 3: the interior finer than the edges, closing on a centre vertex"),
        tri({6, 6, 6}, 5, Spacing::Equal, "only the inner level changes: inner 5 (odd) closes on a small centre triangle"),
        tri({6, 6, 6}, 6, Spacing::Equal, "only the inner level changes: inner 6 (even) closes on a centre vertex"),
        tri({1, 1, 1}, 1, Spacing::FractionalOdd, "the AMD tutorial's level 1.0: one triangle"),
        tri({1.5f, 1.5f, 1.5f}, 1.5f, Spacing::FractionalOdd, "the AMD tutorial's level 1.5: new vertices slide in from the corners"),
        tri({3, 3, 3}, 3, Spacing::FractionalOdd, "the AMD tutorial's level 3.0: three equal segments"),
        tri({4.9f, 4.5f, 4.1f}, 4.4f, Spacing::Equal, "fractional factors under integer spacing: all round up to 5"),
        tri({4.9f, 4.5f, 4.1f}, 4.4f, Spacing::FractionalOdd,
            "the same factors under fractional_odd: 5 segments, two of them shortened by the fraction"),
    };
    return presets;
}

const TessPreset* findTessPreset(std::string_view name) {
    for (const TessPreset& p : tessPresets())
        if (p.name == name) return &p;
    return nullptr;
}

Document notesBezierPatch(int version) {
    // The notes' 16 control points (x, y, z with y up), row by row from z = +15 to z = -15.
    static const double first[16][3] = {
        {-10, -10, 15}, {-5, 0, 15},  {5, 0, 15},  {10, 0, 15},  //
        {-15, 0, 5},    {-5, 0, 5},   {5, 20, 5},  {15, 0, 5},   //
        {-15, 0, -5},   {-5, 0, -5},  {5, 0, -5},  {15, 0, -5},  //
        {-10, 10, -15}, {-5, 0, -15}, {5, 0, -15}, {25, 10, -15},
    };
    static const double second[16][3] = {
        {-10, -20, 15}, {-5, 0, 15},  {5, 0, 15},  {10, 0, 15},  //
        {-15, 0, 5},    {-5, 0, 5},   {5, 30, 5},  {15, 0, 5},   //
        {-15, 0, -5},   {-5, 0, -5},  {5, 0, -5},  {15, 0, -5},  //
        {-10, 20, -15}, {-5, 0, -15}, {5, 0, -15}, {25, 20, -15},
    };
    if (version < 1 || version > kNotesPatchVersions)
        throw std::invalid_argument("the notes' patch comes in versions 1 and 2, not " + std::to_string(version));
    const auto& pts = version == 1 ? first : second;
    const float level = version == 1 ? 25.0f : 15.0f;
    Document d;
    d.name = version == 1 ? "Bézier patch of the notes" : "Bézier patch of the notes, second version";
    Patch p;
    for (int i = 0; i < 16; ++i) {
        d.points.push_back(Vec3(pts[i][0], pts[i][1], pts[i][2]));
        p.idx[size_t(i)] = uint32_t(i);
    }
    p.name = "notes patch";
    d.patches.push_back(p);
    d.tess.outer = {level, level, level, level};
    d.tess.inner = {level, level};
    d.tess.spacing = Spacing::Equal;  // the notes' [partitioning("integer")]
    d.display.showGrid = true;
    d.display.showWireframe = true;
    d.camera.zUp = false;  // the notes' data is y-up: shown upright, the raised point on top
    d.camera.pitchDeg = 35.0;
    d.camera = frameBounds(d.camera, computeBounds(d.points), 16.0 / 9.0);
    return d;
}

float notesDistanceLevel(float distance, float d0, float d1) {
    return gpu::distanceLevel(distance, 64.0f, d0, d1, gpu::kCurveLinear, glm::vec2(0.0f));
}

void applyNotesDistanceFormula(TessSettings& t, bool fromCentre) {
    t.adaptive = AdaptiveMode::Distance;
    t.distanceNear = 20.0f;
    t.distanceFar = 100.0f;
    t.distanceCurve = DistanceCurve::Linear;
    t.distanceFrom = fromCentre ? DistanceFrom::Centre : DistanceFrom::Edges;
    t.maxLevel = 64.0f;
    t.cullFar = true;  // level 0 beyond d1: the patch is culled
}

void applyNotesTerrainFormula(TessSettings& t) {
    t.adaptive = AdaptiveMode::Distance;
    t.distanceNear = 10.0f;
    t.distanceFar = 200.0f;
    t.distanceCurve = DistanceCurve::Pow2;
    t.distanceExponents = {20.0f, 4.0f};
    t.distanceFrom = DistanceFrom::EdgesInnerCentre;
    t.spacing = Spacing::FractionalEven;
    t.maxLevel = 64.0f;
    t.cullFar = false;  // 2^4 = 16 at the far distance: nothing reaches level 0
    t.heightDetail = false;
}

}  // namespace tess
}  // namespace pw

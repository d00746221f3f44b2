#include "core/model/document.hpp"

#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/gpu/patch_math.h"
#include "core/model/basis.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace pw {
inline namespace model {

// The shaders receive these enums as the named constants of core/gpu/patch_math.h.
static_assert(uint32_t(Spacing::Equal) == gpu::kSpacingEqual && uint32_t(Spacing::FractionalOdd) == gpu::kSpacingFractionalOdd &&
              uint32_t(Spacing::FractionalEven) == gpu::kSpacingFractionalEven && uint32_t(Spacing::Pow2) == gpu::kSpacingPow2);
static_assert(uint32_t(AdaptiveMode::None) == gpu::kAdaptiveNone && uint32_t(AdaptiveMode::Distance) == gpu::kAdaptiveDistance &&
              uint32_t(AdaptiveMode::ScreenSpace) == gpu::kAdaptiveScreen &&
              uint32_t(AdaptiveMode::Orientation) == gpu::kAdaptiveOrientation);
static_assert(uint32_t(DistanceCurve::Linear) == gpu::kCurveLinear && uint32_t(DistanceCurve::Pow2) == gpu::kCurvePow2);
static_assert(uint32_t(DistanceFrom::Edges) == gpu::kFromEdges && uint32_t(DistanceFrom::Centre) == gpu::kFromCentre &&
              uint32_t(DistanceFrom::EdgesInnerCentre) == gpu::kFromEdgesInnerCentre);
static_assert(uint32_t(ShadingMode::Lit) == gpu::kShadingLit && uint32_t(ShadingMode::Normal) == gpu::kShadingNormal &&
              uint32_t(ShadingMode::PatchId) == gpu::kShadingPatchId && uint32_t(ShadingMode::UvChecker) == gpu::kShadingUvChecker &&
              uint32_t(ShadingMode::Zebra) == gpu::kShadingZebra && uint32_t(ShadingMode::GaussCurvature) == gpu::kShadingGaussCurvature &&
              uint32_t(ShadingMode::MeanCurvature) == gpu::kShadingMeanCurvature && uint32_t(ShadingMode::Level) == gpu::kShadingLevel);
static_assert(uint32_t(Basis::Bezier) == gpu::kBasisBezier && uint32_t(Basis::BSpline) == gpu::kBasisBSpline &&
              uint32_t(Basis::CatmullRom) == gpu::kBasisCatmullRom);

namespace {

constexpr std::array<std::string_view, 7> kEdgeNames{"u0", "v0", "u1", "v1", "e0", "e1", "e2"};
constexpr std::array<std::string_view, 5> kContinuityNames{"C0", "C1", "G1", "C2", "G2"};
constexpr std::array<std::string_view, 4> kSpacingNames{"equal", "fractional_odd", "fractional_even", "pow2"};
constexpr std::array<std::string_view, 4> kAdaptiveNames{"none", "distance", "screen", "orientation"};
constexpr std::array<std::string_view, 2> kCurveNames{"linear", "pow2"};
constexpr std::array<std::string_view, 3> kFromNames{"edges", "centre", "edges-inner-centre"};
constexpr std::array<std::string_view, 8> kShadingNames{"lit", "normal", "patch", "uv", "zebra", "gauss", "mean", "level"};
constexpr std::array<std::string_view, 2> kMappingNames{"patch", "planar"};
constexpr std::array<std::string_view, 4> kLengthUnitNames{"mm", "cm", "m", "in"};
constexpr std::array<double, 4> kMetresPer{0.001, 0.01, 1.0, 0.0254};

}  // namespace

std::string_view edgeName(Edge e) { return enumName(e, kEdgeNames); }
std::optional<Edge> parseEdge(std::string_view n) {
    const auto e = parseEnum<Edge>(n, kEdgeNames);
    return e && !isTriangleEdge(*e) ? e : std::nullopt;
}
std::optional<Edge> parseJoinEdge(std::string_view n) { return parseEnum<Edge>(n, kEdgeNames); }
std::string_view lengthUnitName(LengthUnit u) { return enumName(u, kLengthUnitNames); }
std::optional<LengthUnit> parseLengthUnit(std::string_view n) { return parseEnum<LengthUnit>(n, kLengthUnitNames); }
double metresPer(LengthUnit u) { return kMetresPer[size_t(u) < kMetresPer.size() ? size_t(u) : 2]; }
std::string_view continuityName(Continuity c) { return enumName(c, kContinuityNames); }
std::optional<Continuity> parseContinuity(std::string_view n) { return parseEnum<Continuity>(n, kContinuityNames); }
std::string_view spacingName(Spacing s) { return enumName(s, kSpacingNames); }
// "integer" is the D3D partitioning of the lecture notes, the same as Vulkan's equal spacing.
std::optional<Spacing> parseSpacing(std::string_view n) { return n == "integer" ? Spacing::Equal : parseEnum<Spacing>(n, kSpacingNames); }
std::string_view adaptiveName(AdaptiveMode m) { return enumName(m, kAdaptiveNames); }
std::optional<AdaptiveMode> parseAdaptive(std::string_view n) { return parseEnum<AdaptiveMode>(n, kAdaptiveNames); }
std::string_view distanceCurveName(DistanceCurve c) { return enumName(c, kCurveNames); }
std::optional<DistanceCurve> parseDistanceCurve(std::string_view n) { return parseEnum<DistanceCurve>(n, kCurveNames); }
std::string_view distanceFromName(DistanceFrom f) { return enumName(f, kFromNames); }
std::optional<DistanceFrom> parseDistanceFrom(std::string_view n) { return parseEnum<DistanceFrom>(n, kFromNames); }
std::string_view shadingName(ShadingMode m) { return enumName(m, kShadingNames); }
std::optional<ShadingMode> parseShading(std::string_view n) { return parseEnum<ShadingMode>(n, kShadingNames); }

std::optional<bool> parseDomainOrigin(std::string_view n) {
    if (n == "upper-left") return true;
    if (n == "lower-left") return false;
    return std::nullopt;
}
std::string_view domainOriginName(bool upperLeft) { return upperLeft ? "upper-left" : "lower-left"; }

std::string_view displacementMappingName(DisplacementMapping m) { return enumName(m, kMappingNames); }
std::optional<DisplacementMapping> parseDisplacementMapping(std::string_view n) { return parseEnum<DisplacementMapping>(n, kMappingNames); }

int edgeSlot(Edge e, int k, int depth) {
    if (isTriangleEdge(e)) throw std::logic_error("edgeSlot: " + std::string(edgeName(e)) + " is a triangle's edge");
    return gpu::quadEdgeSlot(static_cast<int>(e), k, depth);
}

bool edgeReversed(const std::array<uint32_t, 4>& pool) { return gpu::edgeReversed(pool[0], pool[1], pool[2], pool[3]); }

std::vector<PatchInstance> expandPatches(const Document& doc) {
    std::vector<PatchInstance> out;
    out.reserve(doc.patches.size());
    for (size_t p = 0; p < doc.patches.size(); ++p) {
        const Patch& patch = doc.patches[p];
        PatchInstance inst;
        inst.idx = patch.idx;
        inst.basis = patch.basis;
        inst.tension = patch.tension;
        inst.patch = static_cast<int32_t>(p);
        out.push_back(inst);
    }
    for (size_t s = 0; s < doc.surfaces.size(); ++s) {
        const Surface& surf = doc.surfaces[s];
        const uint32_t step = netStep(surf.basis);
        auto starts = [&](uint32_t n, bool closed) {
            std::vector<uint32_t> v(netWindowCount(n, closed, step));
            for (size_t k = 0; k < v.size(); ++k) v[k] = uint32_t(k) * step;
            return v;
        };
        for (uint32_t r0 : starts(surf.rows, surf.closedV)) {
            for (uint32_t c0 : starts(surf.cols, surf.closedU)) {
                PatchInstance inst;
                for (uint32_t i = 0; i < 4; ++i)
                    for (uint32_t j = 0; j < 4; ++j)
                        inst.idx[i * 4 + j] = surf.idx[((r0 + i) % surf.rows) * surf.cols + (c0 + j) % surf.cols];
                inst.basis = surf.basis;
                inst.tension = surf.tension;
                inst.surface = static_cast<int32_t>(s);
                inst.windowRow = r0;
                inst.windowCol = c0;
                out.push_back(inst);
            }
        }
    }
    return out;
}

bool windowHidden(const Document& doc, const PatchInstance& w) {
    return (w.patch >= 0 && doc.patches[size_t(w.patch)].hidden) || (w.surface >= 0 && doc.surfaces[size_t(w.surface)].hidden);
}

Net16 gatherNet(const Document& doc, const std::array<uint32_t, 16>& idx) {
    Net16 net;
    for (int k = 0; k < 16; ++k) net[k] = doc.points[idx[k]];
    return net;
}

std::optional<Weights16> gatherWeights(const Document& doc, const std::array<uint32_t, 16>& idx) {
    if (doc.weights.empty()) return std::nullopt;
    Weights16 w;
    bool rational = false;
    for (int k = 0; k < 16; ++k) {
        w[k] = pointWeight(doc, idx[k]);
        rational = rational || w[k] != 1.0;
    }
    if (!rational) return std::nullopt;
    return w;
}

void trimWeights(std::vector<double>& weights) {
    while (!weights.empty() && weights.back() == 1.0) weights.pop_back();
}

void setPointWeight(Document& doc, uint32_t i, double w) {
    if (i >= doc.points.size())
        throw EditError("point " + std::to_string(i) + " does not exist (the document has " + std::to_string(doc.points.size()) + ")");
    if (!(w > 0.0) || !(w <= kMaxWeight)) throw EditError("a weight must be positive and at most 1e6 (got " + std::to_string(w) + ")");
    if (i >= doc.weights.size()) {
        if (w == 1.0) return;
        doc.weights.resize(i + 1, 1.0);
    }
    doc.weights[i] = w;
    trimWeights(doc.weights);
}

std::optional<std::array<uint32_t, 2>> weightedTrianglePoint(const Document& doc) {
    if (doc.weights.empty()) return std::nullopt;
    for (uint32_t t = 0; t < doc.triangles.size(); ++t)
        for (uint32_t i : doc.triangles[t].idx)
            if (pointWeight(doc, i) != 1.0) return std::array<uint32_t, 2>{t, i};
    return std::nullopt;
}

void remapWeights(Document& doc, const std::vector<uint32_t>& remap, size_t newSize) {
    if (doc.weights.empty()) return;
    std::vector<double> out(newSize, 1.0);
    for (size_t i = 0; i < remap.size() && i < doc.weights.size(); ++i)
        if (remap[i] < newSize) out[remap[i]] = doc.weights[i];
    trimWeights(out);
    doc.weights = std::move(out);
}

Bounds computeBounds(const std::vector<Vec3>& points) {
    Bounds b;
    for (const Vec3& p : points) b.add(p);
    return b;
}

double modelSize(const Document& doc) { return std::max(computeBounds(doc.points).diagonal(), 1e-12); }

std::vector<uint32_t> withCurveHandles(const Document& doc, std::vector<uint32_t> points) {
    std::sort(points.begin(), points.end());
    const size_t given = points.size();
    const auto has = [&](uint32_t i) { return std::binary_search(points.begin(), points.begin() + long(given), i); };
    // A curve on a patch's edge (Curve from edge) shares the patch's points: its anchors are the
    // patch's corners and move alone, as they always have (surfaces made from curves share their
    // inputs' points too; those curves keep their handles).
    std::vector<bool> onPatch;
    for (const BezierCurve& c : doc.curves) {
        bool any = false;
        for (size_t k = 0; k < c.idx.size() && !any; k += 3) any = has(c.idx[k]);
        if (!any || c.hidden || !validCurveLength(c.idx.size())) continue;
        if (onPatch.empty()) {
            onPatch.assign(doc.points.size(), false);
            std::vector<bool> made(doc.patches.size(), false);  // a surface from curves shares its inputs' points
            for (const Construction& k : doc.constructions)
                for (uint32_t p : k.patches)
                    if (p < made.size()) made[p] = true;
            for (size_t p = 0; p < doc.patches.size(); ++p)
                if (!made[p])
                    for (uint32_t i : doc.patches[p].idx) onPatch[i] = true;
        }
        bool shared = false;
        for (uint32_t i : c.idx) shared = shared || (i < onPatch.size() && onPatch[i]);
        if (shared) continue;
        const size_t last = c.idx.size() - 1;
        const bool closed = curveClosed(c);
        for (size_t k = 0; k <= last; k += 3) {
            if (!has(c.idx[k])) continue;
            if (k > 0) points.push_back(c.idx[k - 1]);
            if (k < last) points.push_back(c.idx[k + 1]);
            if (closed && k == 0) points.push_back(c.idx[last - 1]);
            if (closed && k == last) points.push_back(c.idx[1]);
        }
    }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

}  // namespace model
}  // namespace pw

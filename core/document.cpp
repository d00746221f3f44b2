#include "document.hpp"

#include <algorithm>
#include <limits>

namespace pw {

namespace {

template <typename E, size_t N>
std::optional<E> parseNamed(std::string_view name, const std::array<std::string_view, N>& names) {
    for (size_t i = 0; i < N; ++i)
        if (names[i] == name) return static_cast<E>(i);
    return std::nullopt;
}

constexpr std::array<std::string_view, 4> kEdgeNames{"u0", "v0", "u1", "v1"};
constexpr std::array<std::string_view, 3> kContinuityNames{"C0", "C1", "G1"};
constexpr std::array<std::string_view, 4> kSpacingNames{"equal", "fractional_odd", "fractional_even", "pow2"};
constexpr std::array<std::string_view, 4> kAdaptiveNames{"none", "distance", "screen", "orientation"};
constexpr std::array<std::string_view, 7> kShadingNames{"lit", "normal", "patch", "uv", "zebra", "gauss", "mean"};

}  // namespace

std::string_view edgeName(Edge e) { return kEdgeNames[static_cast<size_t>(e)]; }
std::optional<Edge> parseEdge(std::string_view n) { return parseNamed<Edge>(n, kEdgeNames); }
std::string_view continuityName(Continuity c) { return kContinuityNames[static_cast<size_t>(c)]; }
std::optional<Continuity> parseContinuity(std::string_view n) { return parseNamed<Continuity>(n, kContinuityNames); }
std::string_view spacingName(Spacing s) { return kSpacingNames[static_cast<size_t>(s)]; }
std::optional<Spacing> parseSpacing(std::string_view n) { return parseNamed<Spacing>(n, kSpacingNames); }
std::string_view adaptiveName(AdaptiveMode m) { return kAdaptiveNames[static_cast<size_t>(m)]; }
std::optional<AdaptiveMode> parseAdaptive(std::string_view n) { return parseNamed<AdaptiveMode>(n, kAdaptiveNames); }
std::string_view shadingName(ShadingMode m) { return kShadingNames[static_cast<size_t>(m)]; }
std::optional<ShadingMode> parseShading(std::string_view n) { return parseNamed<ShadingMode>(n, kShadingNames); }

int edgeSlot(Edge e, int k, int depth) {
    switch (e) {
        case Edge::U0: return k * 4 + depth;
        case Edge::V0: return depth * 4 + k;
        case Edge::U1: return k * 4 + (3 - depth);
        case Edge::V1: return (3 - depth) * 4 + k;
    }
    return 0;
}

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

Net16 gatherNet(const Document& doc, const std::array<uint32_t, 16>& idx) {
    Net16 net;
    for (int k = 0; k < 16; ++k) net[k] = doc.points[idx[k]];
    return net;
}

Bounds computeBounds(const std::vector<Vec3>& points) {
    Bounds b;
    for (const Vec3& p : points) {
        if (b.empty) {
            b.min = b.max = p;
            b.empty = false;
        } else {
            b.min = glm::min(b.min, p);
            b.max = glm::max(b.max, p);
        }
    }
    return b;
}

double modelSize(const Document& doc) { return std::max(computeBounds(doc.points).diagonal(), 1e-12); }

}  // namespace pw

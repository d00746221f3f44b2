#include "core/eval/displacement.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/eval/bezier_curve.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/eval/rational_eval.hpp"
#include "core/gpu/patch_math.h"

namespace pw {
inline namespace eval {

std::filesystem::path resolveMapPath(const DisplacementSettings& d, const std::filesystem::path& documentPath) {
    const std::filesystem::path map(d.map);
    if (map.is_absolute() || documentPath.empty()) return map;
    return documentPath.parent_path() / map;
}

std::array<double, 4> planarRect(const Document& doc) {
    if (doc.displacement.rect) return *doc.displacement.rect;
    const Bounds b = computeBounds(doc.points);
    if (b.empty) return {0.0, 0.0, 1.0, 1.0};
    const int second = doc.camera.zUp ? 1 : 2;
    const double w = b.max.x - b.min.x, h = b.max[second] - b.min[second];
    const double side = std::max({w, h, 1e-9});
    return {b.min.x, b.min[second], w > 0 ? w : side, h > 0 ? h : side};
}

std::array<double, 2> planarUv(const Vec3& p, const std::array<double, 4>& rect, bool zUp) {
    const double g = zUp ? p.y : p.z;
    return {(p.x - rect[0]) / rect[2], 1.0 - (g - rect[1]) / rect[3]};
}

EdgeDetail edgeDetail(const HeightMap& map, const std::vector<std::array<double, 2>>& uvs) {
    EdgeDetail d;
    if (map.empty() || uvs.size() < 3) return d;
    std::vector<double> h(uvs.size());
    for (size_t k = 0; k < uvs.size(); ++k) h[k] = map.sample(uvs[k][0], uvs[k][1]);
    const double dt = 1.0 / double(uvs.size() - 1);
    double worst = 0.0;
    for (size_t k = 1; k + 1 < h.size(); ++k) worst = std::max(worst, std::abs(h[k - 1] - 2 * h[k] + h[k + 1]));
    d.detail = worst / (dt * dt);
    for (size_t k = 1; k < uvs.size(); ++k)
        d.texels += std::hypot((uvs[k][0] - uvs[k - 1][0]) * map.width, (uvs[k][1] - uvs[k - 1][1]) * map.height);
    return d;
}

namespace {

// `uvs` (equal parameter steps) at n + 1 equal steps, by linear interpolation between them.
std::vector<std::array<double, 2>> resampled(const std::vector<std::array<double, 2>>& uvs, int n) {
    std::vector<std::array<double, 2>> out(size_t(n) + 1);
    const double last = double(uvs.size() - 1);
    for (int k = 0; k <= n; ++k) {
        const double x = last * k / n;
        const size_t i = std::min(size_t(x), uvs.size() - 2);
        const double f = x - double(i);
        out[size_t(k)] = {uvs[i][0] * (1 - f) + uvs[i + 1][0] * f, uvs[i][1] * (1 - f) + uvs[i + 1][1] * f};
    }
    return out;
}

}  // namespace

EdgeDetail edgeDetail(const HeightMap& map, const std::vector<HeightMap>& mips, const std::vector<std::array<double, 2>>& uvs) {
    static_assert(std::tuple_size_v<decltype(EdgeDetail::coarser)> == size_t(gpu::kHeightDetailLevels));
    EdgeDetail d = edgeDetail(map, uvs);
    if (map.empty() || uvs.size() < 3) return d;
    for (size_t l = 0; l < d.coarser.size(); ++l) {
        const HeightMap& m = mips.empty() ? map : mips[std::min(l, mips.size() - 1)];
        // Two samples per texel of that level, as sampleEdge takes them on level 0.
        const double span = d.texels * double(m.width) / double(map.width);
        d.coarser[l] = edgeDetail(m, resampled(uvs, std::clamp(int(std::ceil(2.0 * span)), 16, 1024))).detail;
    }
    return d;
}

namespace {

// UV samples along an edge: `at(t)` for t in [0, 1], dense enough for every texel it crosses (two
// samples per texel, at least 16, at most 1024).
template <class At>
std::vector<std::array<double, 2>> sampleEdge(const HeightMap& map, At&& at) {
    const std::array<double, 2> a = at(0.0), b = at(0.5), c = at(1.0);
    const double span = (std::hypot((b[0] - a[0]) * map.width, (b[1] - a[1]) * map.height) +
                         std::hypot((c[0] - b[0]) * map.width, (c[1] - b[1]) * map.height));
    const int n = std::clamp(int(std::ceil(2.0 * span)), 16, 1024);
    std::vector<std::array<double, 2>> uvs(size_t(n) + 1);
    for (int k = 0; k <= n; ++k) uvs[size_t(k)] = at(double(k) / n);
    return uvs;
}

std::optional<DisplacementOverride> ownOf(const Document& doc, const PatchInstance& w) {
    if (w.patch >= 0) return doc.patches[size_t(w.patch)].displacement;
    if (w.surface >= 0) return doc.surfaces[size_t(w.surface)].displacement;
    return std::nullopt;
}

}  // namespace

double mapTexelsPerUnit(const Document& doc, const std::vector<PatchInstance>& windows, const HeightMap* map) {
    if (!map || map->empty()) return 0.0;
    if (doc.displacement.mapping == DisplacementMapping::Planar) {
        const std::array<double, 4> rect = planarRect(doc);
        return std::max(map->width / rect[2], map->height / rect[3]);
    }
    double least = 0.0;  // 0: none yet
    // Texels `texels` over the length of the polyline through `at` at 9 parameters.
    auto along = [&](double texels, auto&& at) {
        double len = 0.0;
        Vec3 prev = at(0.0);
        for (int k = 1; k <= 8; ++k) {
            const Vec3 q = at(k / 8.0);
            len += length(q - prev);
            prev = q;
        }
        if (len > 0.0 && texels > 0.0) least = least > 0.0 ? std::min(least, texels / len) : texels / len;
    };
    for (const PatchInstance& pi : windows) {
        const WindowNet net = gatherWindow(doc, pi.idx);
        const auto eval = [&](double u, double v) { return evaluateWindow(net, pi.basis, pi.tension, u, v).p; };
        double cols = 1.0, rows = 1.0;  // the windows of a net tiling the map
        if (pi.surface >= 0) {
            const Surface& s = doc.surfaces[size_t(pi.surface)];
            const uint32_t step = netStep(s.basis);
            rows = double(netWindowCount(s.rows, s.closedV, step));
            cols = double(netWindowCount(s.cols, s.closedU, step));
        }
        for (const double side : {0.0, 1.0}) {
            along(map->height / rows, [&](double t) { return eval(side, t); });
            along(map->width / cols, [&](double t) { return eval(t, side); });
        }
    }
    for (const TrianglePatch& tri : doc.triangles)  // barycentric (u, v) over the map: edges cross the map's side or diagonal
        for (int e = 0; e < 3; ++e) {
            const std::array<uint32_t, 4> key = triEdgePool(tri.idx, e);
            const std::array<Vec3, 4> p{doc.points[key[0]], doc.points[key[1]], doc.points[key[2]], doc.points[key[3]]};
            const double texels = e == 0 ? map->height : e == 1 ? map->width : std::hypot(map->width, map->height);
            along(texels, [&](double s) { return evaluateCurve(p, s); });
        }
    return least;
}

std::vector<WindowDisplacement> windowDisplacements(const Document& doc, const std::vector<PatchInstance>& windows, const HeightMap* map,
                                                    const std::vector<HeightMap>* mips) {
    std::vector<WindowDisplacement> out(windows.size() + doc.triangles.size());
    const bool planar = doc.displacement.mapping == DisplacementMapping::Planar;
    const std::array<double, 4> rect = planarRect(doc);
    const bool zUp = doc.camera.zUp;
    std::map<std::array<uint32_t, 4>, EdgeDetail> shared;  // canonical pool points of an edge -> its detail
    const std::vector<HeightMap> made = map && !mips ? heightMipChain(*map, gpu::kHeightDetailLevels) : std::vector<HeightMap>{};
    const std::vector<HeightMap>& levels = mips ? *mips : made;
    auto detailOf = [&](std::array<uint32_t, 4> key, auto&& at) {
        if (edgeReversed(key)) key = reversedEdgePool(key);
        auto it = shared.find(key);
        if (it == shared.end()) it = shared.emplace(key, edgeDetail(*map, levels, sampleEdge(*map, at))).first;
        return it->second;
    };
    auto store = [](WindowDisplacement& wd, int e, const EdgeDetail& d) {
        wd.detail[size_t(e)] = float(d.detail);
        wd.texels[size_t(e)] = float(d.texels);
        for (size_t l = 0; l < d.coarser.size(); ++l) wd.coarser[size_t(e)][l] = float(d.coarser[l]);
    };
    for (size_t w = 0; w < windows.size(); ++w) {
        const PatchInstance& pi = windows[w];
        WindowDisplacement& wd = out[w];
        wd.own = ownOf(doc, pi);
        if (pi.surface >= 0) {  // a net's windows tile the map in net order
            const Surface& s = doc.surfaces[size_t(pi.surface)];
            const uint32_t step = netStep(s.basis);
            const double rows = double(netWindowCount(s.rows, s.closedV, step)), cols = double(netWindowCount(s.cols, s.closedU, step));
            const uint32_t r = pi.windowRow / step, c = pi.windowCol / step;  // window number, not first point
            wd.uvRect = {float(c / cols), float(r / rows), float((c + 1) / cols), float((r + 1) / rows)};
        }
        if (!map || map->empty()) continue;
        const WindowNet net = gatherWindow(doc, pi.idx);
        const int depth = pi.basis == Basis::Bezier ? 0 : 1;  // the points the control shader keys levels on
        for (int e = 0; e < 4; ++e) {
            std::array<uint32_t, 4> key{};
            for (int k = 0; k < 4; ++k) key[size_t(k)] = pi.idx[size_t(edgeSlot(Edge(e), k, depth))];
            // The edge as (u, v) of the window at t along it (u0: u = 0, v0: v = 0, u1: u = 1, v1: v = 1).
            auto param = [e](double t) {
                return e == 0 ? std::array{0.0, t} : e == 1 ? std::array{t, 0.0} : e == 2 ? std::array{1.0, t} : std::array{t, 1.0};
            };
            const std::array<float, 4> r = wd.uvRect;
            const EdgeDetail d = detailOf(key, [&](double t) {
                const auto [u, v] = param(t);
                if (planar) return planarUv(evaluateWindow(net, pi.basis, pi.tension, u, v).p, rect, zUp);
                return std::array{r[0] * (1 - u) + r[2] * u, r[1] * (1 - v) + r[3] * v};
            });
            store(wd, e, d);
        }
    }
    for (size_t t = 0; t < doc.triangles.size(); ++t) {
        const TrianglePatch& tri = doc.triangles[t];
        WindowDisplacement& wd = out[windows.size() + t];
        wd.own = tri.displacement;
        if (!map || map->empty()) continue;
        for (int e = 0; e < 3; ++e) {
            const std::array<uint32_t, 4> key = triEdgePool(tri.idx, e);
            std::array<Vec3, 4> p{};
            for (int k = 0; k < 4; ++k) p[size_t(k)] = doc.points[key[size_t(k)]];
            // Barycentric (u, v) of the edge's ends: edge 0 from v = 1 to w = 1, 1 from w = 1 to u = 1, 2 from u = 1 to v = 1.
            static constexpr std::array<std::array<double, 4>, 3> kEnds{{{0, 1, 0, 0}, {0, 0, 1, 0}, {1, 0, 0, 1}}};
            const EdgeDetail d = detailOf(key, [&](double s) {
                if (planar) {
                    const double a = 1 - s;
                    const Vec3 q = a * a * a * p[0] + 3 * a * a * s * p[1] + 3 * a * s * s * p[2] + s * s * s * p[3];
                    return planarUv(q, rect, zUp);
                }
                const auto& end = kEnds[size_t(e)];
                return std::array{end[0] + (end[2] - end[0]) * s, end[1] + (end[3] - end[1]) * s};
            });
            store(wd, e, d);
        }
    }
    return out;
}

}  // namespace eval
}  // namespace pw

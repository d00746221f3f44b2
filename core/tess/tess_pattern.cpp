#include "core/tess/tess_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace pw {
inline namespace tess {

std::vector<std::array<float, 2>> TessPattern::distinctPoints() const {
    std::vector<std::array<float, 2>> v = uv;
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

std::array<float, 2> domainPicturePoint(DomainKind kind, std::array<float, 2> uv) {
    if (kind != DomainKind::Triangle) return uv;
    // Corners: u = 1 at (0, 0), v = 1 at (1, 0), w = 1 at (0.5, sqrt(3)/2).
    const float w = 1.0f - uv[0] - uv[1];
    return {uv[1] + 0.5f * w, 0.8660254f * w};
}

namespace {

// Gives every point an id shared by all points within `tol` of the first point that took it.
class PointIds {
public:
    explicit PointIds(float tol) : tol_(tol), cell_(std::max(tol, 1e-7f)) {}
    int id(const std::array<float, 2>& p) {
        const auto cx = int64_t(std::floor(p[0] / cell_)), cy = int64_t(std::floor(p[1] / cell_));
        for (int64_t dx = -1; dx <= 1; ++dx)
            for (int64_t dy = -1; dy <= 1; ++dy) {
                auto it = cells_.find({cx + dx, cy + dy});
                if (it == cells_.end()) continue;
                for (int i : it->second)
                    if (std::abs(reps_[size_t(i)][0] - p[0]) <= tol_ && std::abs(reps_[size_t(i)][1] - p[1]) <= tol_) return i;
            }
        const int i = int(reps_.size());
        reps_.push_back(p);
        cells_[{cx, cy}].push_back(i);
        return i;
    }

private:
    float tol_, cell_;
    std::vector<std::array<float, 2>> reps_;
    std::map<std::pair<int64_t, int64_t>, std::vector<int>> cells_;
};

using Key = std::array<int, 3>;

// Primitive index lists by their sorted point ids; `keys` gets each primitive's, in emission order.
std::map<Key, std::vector<size_t>> primitivesByPoints(const TessPattern& p, PointIds& ids, std::set<int>& points, std::vector<Key>& keys) {
    std::map<Key, std::vector<size_t>> out;
    const int n = p.vertsPerPrimitive();
    for (size_t i = 0; i < p.primitives(); ++i) {
        Key k{-1, -1, -1};
        for (int c = 0; c < n; ++c) {
            k[size_t(c)] = ids.id(p.uv[i * size_t(n) + size_t(c)]);
            points.insert(k[size_t(c)]);
        }
        // Sorted by hand: std::sort over part of the array trips GCC 12's -Warray-bounds.
        if (k[0] > k[1]) std::swap(k[0], k[1]);
        if (n == 3 && k[1] > k[2]) std::swap(k[1], k[2]);
        if (k[0] > k[1]) std::swap(k[0], k[1]);
        out[k].push_back(i);
        keys.push_back(k);
    }
    return out;
}

// Twice the signed area of triangle `i` as drawn (positive: counter-clockwise).
float signedArea(const TessPattern& p, size_t i) {
    const auto a = domainPicturePoint(p.kind, p.uv[3 * i]), b = domainPicturePoint(p.kind, p.uv[3 * i + 1]),
               c = domainPicturePoint(p.kind, p.uv[3 * i + 2]);
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

}  // namespace

PatternDiff comparePatterns(const TessPattern& a, const TessPattern& b, float tolerance) {
    PatternDiff d;
    d.onlyInA.assign(a.primitives(), 0);
    d.onlyInB.assign(b.primitives(), 0);
    PointIds ids(tolerance);
    std::set<int> pointsA, pointsB;
    std::vector<Key> keysA, keysB;
    const auto primsA = primitivesByPoints(a, ids, pointsA, keysA);
    const auto primsB = primitivesByPoints(b, ids, pointsB, keysB);
    d.sameOrder = keysA == keysB;
    for (int p : pointsA) d.pointsOnlyA += pointsB.count(p) ? 0 : 1;
    for (int p : pointsB) d.pointsOnlyB += pointsA.count(p) ? 0 : 1;
    static const std::vector<size_t> none;
    const auto mark = [](const std::vector<size_t>& mine, size_t matched, std::vector<uint8_t>& flags, size_t& count) {
        for (size_t k = matched; k < mine.size(); ++k) flags[mine[k]] = 1;
        count += mine.size() - matched;
    };
    for (const auto& [key, listA] : primsA) {
        const auto it = primsB.find(key);
        const std::vector<size_t>& listB = it == primsB.end() ? none : it->second;
        const size_t matched = std::min(listA.size(), listB.size());
        mark(listA, matched, d.onlyInA, d.primitivesOnlyA);
        if (a.vertsPerPrimitive() == 3 && b.vertsPerPrimitive() == 3)
            for (size_t k = 0; k < matched; ++k) {
                const float sa = signedArea(a, listA[k]), sb = signedArea(b, listB[k]);
                // A triangle of no area (a collapsed ring) has no winding.
                if (std::abs(sa) > 1e-9f && std::abs(sb) > 1e-9f && (sa > 0.0f) != (sb > 0.0f)) ++d.windingFlips;
            }
    }
    for (const auto& [key, listB] : primsB) {
        const auto it = primsA.find(key);
        const size_t matched = it == primsA.end() ? 0 : std::min(it->second.size(), listB.size());
        mark(listB, matched, d.onlyInB, d.primitivesOnlyB);
    }
    return d;
}

}  // namespace tess
}  // namespace pw

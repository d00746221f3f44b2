// Join detection between patches that share boundary curves in the pool, and merging of
// coincident pool entries (used by the .bpt import).
//
// Tolerances (JoinDetectOptions). Every length test is absolute: tol = relativeTolerance ×
// modelSize(doc). For each point k of the edge, a = A0k − A1k and b = B1k − B0k; α is fitted by
// least squares over the edge (α = Σ a·b / Σ a·a) and every k must satisfy |b_k − α·a_k| ≤ tol,
// which tests collinearity, direction and constancy of α at once, in units of length (the same
// quantity maxConstraintResidual measures). C1 additionally needs |α − 1| ≤ c1RatioTolerance and
// |b_k − a_k| ≤ tol, and is then stored with α = 1 exactly.
//
// Defaults: 1e-4 for both. The tea set is given to 4–6 significant decimals. The teapot and the
// teacup were authored exactly (their seams are proportional to ~1e-17 of the model size, so any
// tolerance finds them: teapot 46 C1 + 6 G1, teacup 26 C1 + 16 G1 + 4 C0), but the teaspoon's seams
// are smooth only to ~3e-5 of its size (decimals rounded to 6 digits, α drifting 2.3996..2.3998
// along the bowl): with 1e-6 twelve of its 28 seams would be taken for creases. 1e-4 × size is far
// below anything visible (a tenth of a pixel on a 1000-pixel view of the whole model) and still
// well above 4-decimal rounding of coordinates of order 1. Such slightly-off joins have a residual
// up to tol until the first edit, when the constraint projection (constraint_solver.hpp) makes it
// exact; pass 1e-6 (or less) to accept only seams already exact to the solver's standard.
#include "core/model/join_detect.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <unordered_map>

namespace pw {
inline namespace model {

namespace {

struct EdgeRef {
    uint32_t patch;
    Edge edge;
    std::array<uint32_t, 4> idx;  // pool indices along the edge, increasing parameter
};

bool degenerateEdge(const Document& doc, const std::array<uint32_t, 4>& e) {
    if (e[0] == e[1] && e[1] == e[2] && e[2] == e[3]) return true;
    const Vec3& p = doc.points[e[0]];
    for (int k = 1; k < 4; ++k)
        if (doc.points[e[k]] != p) return false;
    return true;
}

// Classifies the continuity across an already index-matched edge pair; tol = relativeTolerance ×
// the model's size (computed once by the caller: it reads every point).
void classify(const Document& doc, const Patch& A, const Patch& B, Join& j, double tol, const JoinDetectOptions& opt) {
    std::array<Vec3, 4> a, b;
    std::array<bool, 4> use{};
    double num = 0, den = 0;
    for (int k = 0; k < 4; ++k) {
        const int kb = j.reversed ? 3 - k : k;
        a[k] = doc.points[A.idx[edgeSlot(j.edgeA, k, 0)]] - doc.points[A.idx[edgeSlot(j.edgeA, k, 1)]];
        b[k] = doc.points[B.idx[edgeSlot(j.edgeB, kb, 1)]] - doc.points[B.idx[edgeSlot(j.edgeB, kb, 0)]];
        const bool za = glm::length(a[k]) <= tol, zb = glm::length(b[k]) <= tol;
        if (za && zb) continue;  // collapsed tangent on both sides: no information
        if (za != zb) return;    // one side has a tangent, the other none: a crease (C0)
        use[k] = true;
        num += glm::dot(a[k], b[k]);
        den += glm::dot(a[k], a[k]);
    }
    if (den <= 0) return;  // no usable tangent anywhere along the edge
    const double alpha = num / den;
    if (!(alpha > 0) || !std::isfinite(alpha)) return;  // opposite directions: a fold
    for (int k = 0; k < 4; ++k)
        if (use[k] && glm::length(b[k] - alpha * a[k]) > tol) return;
    bool c1 = std::abs(alpha - 1.0) <= opt.c1RatioTolerance;
    for (int k = 0; k < 4 && c1; ++k)
        if (use[k] && glm::length(b[k] - a[k]) > tol) c1 = false;
    if (c1) {
        j.continuity = Continuity::C1;
        j.alpha = 1.0;
    } else {
        j.continuity = Continuity::G1;
        j.alpha = alpha;
    }
}

}  // namespace

std::vector<Join> detectJoins(const Document& doc, JoinDetectOptions options, size_t* nonManifoldEdges) {
    // Group non-degenerate edges by their index sequence, canonically oriented (the lexicographically
    // smaller of forward and reversed).
    std::map<std::array<uint32_t, 4>, std::vector<EdgeRef>> groups;
    for (uint32_t p = 0; p < doc.patches.size(); ++p) {
        const Patch& patch = doc.patches[p];
        for (int e = 0; e < 4; ++e) {
            EdgeRef ref{p, static_cast<Edge>(e), {}};
            bool inRange = true;
            for (int k = 0; k < 4; ++k) {
                ref.idx[k] = patch.idx[edgeSlot(ref.edge, k, 0)];
                inRange = inRange && ref.idx[k] < doc.points.size();
            }
            if (!inRange || degenerateEdge(doc, ref.idx)) continue;
            groups[edgeReversed(ref.idx) ? reversedEdgePool(ref.idx) : ref.idx].push_back(ref);
        }
    }

    std::vector<Join> joins;
    const double tol = options.relativeTolerance * modelSize(doc);
    if (nonManifoldEdges) *nonManifoldEdges = 0;
    for (const auto& [key, refs] : groups) {
        if (refs.size() > 2) {
            if (nonManifoldEdges) ++*nonManifoldEdges;
            continue;
        }
        if (refs.size() != 2) continue;
        const EdgeRef* ra = &refs[0];
        const EdgeRef* rb = &refs[1];
        if (ra->patch == rb->patch) continue;  // a patch closed onto itself
        if (ra->patch > rb->patch) std::swap(ra, rb);
        Join j;
        j.patchA = ra->patch;
        j.edgeA = ra->edge;
        j.patchB = rb->patch;
        j.edgeB = rb->edge;
        j.reversed = ra->idx != rb->idx;
        // Check every pool-index-matched tangent row for C1/G1.
        classify(doc, doc.patches[j.patchA], doc.patches[j.patchB], j, tol, options);
        joins.push_back(j);
    }
    std::sort(joins.begin(), joins.end(), [](const Join& l, const Join& r) {
        if (l.patchA != r.patchA) return l.patchA < r.patchA;
        if (l.edgeA != r.edgeA) return l.edgeA < r.edgeA;
        if (l.patchB != r.patchB) return l.patchB < r.patchB;
        return l.edgeB < r.edgeB;
    });
    return joins;
}

void mergeCoincidentPoints(Document& doc, double tolerance) {
    // Key: the coordinates' bit patterns, with -0.0 folded into +0.0 (equal values, one point), and
    // the weight's: points of different weights are different points of a rational surface.
    struct Key {
        uint64_t x, y, z, w = 0;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const {
            uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
            h ^= (k.y + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2));
            h ^= (k.z + 0x85157AF5ull + (h << 6) + (h >> 2));
            h ^= (k.w + 0x2545F491ull + (h << 6) + (h >> 2));
            return static_cast<size_t>(h);
        }
    };
    auto bits = [](double v) { return std::bit_cast<uint64_t>(v == 0.0 ? 0.0 : v); };

    std::vector<uint32_t> remap(doc.points.size());
    std::vector<Vec3> pool;
    std::vector<double> poolWeights;
    pool.reserve(doc.points.size());
    if (tolerance > 0.0) {
        // Cells of the tolerance's size: a point within it of a kept one lies in one of the 27
        // cells around it.
        std::unordered_map<Key, std::vector<uint32_t>, KeyHash> cells;
        auto cell = [&](const Vec3& p, int dx, int dy, int dz) {
            return Key{uint64_t(int64_t(std::floor(p.x / tolerance)) + dx), uint64_t(int64_t(std::floor(p.y / tolerance)) + dy),
                       uint64_t(int64_t(std::floor(p.z / tolerance)) + dz)};
        };
        for (size_t i = 0; i < doc.points.size(); ++i) {
            const Vec3& p = doc.points[i];
            uint32_t found = UINT32_MAX, near = UINT32_MAX;  // same weight; any weight
            for (int dx = -1; dx <= 1 && found == UINT32_MAX; ++dx)
                for (int dy = -1; dy <= 1 && found == UINT32_MAX; ++dy)
                    for (int dz = -1; dz <= 1 && found == UINT32_MAX; ++dz)
                        if (const auto it = cells.find(cell(p, dx, dy, dz)); it != cells.end())
                            for (uint32_t q : it->second)
                                if (glm::length(pool[q] - p) <= tolerance) {
                                    if (near == UINT32_MAX) near = q;
                                    if (poolWeights[q] == pointWeight(doc, uint32_t(i))) {
                                        found = q;
                                        break;
                                    }
                                }
            if (found == UINT32_MAX) {
                // A point of another weight stays its own pool point, at the same position: the
                // pole row of a rational sphere (weights 1, w, w, 1) is then collapsed exactly, so
                // the mesher folds it instead of making sliver triangles 1e-17 wide.
                found = static_cast<uint32_t>(pool.size());
                pool.push_back(near == UINT32_MAX ? p : pool[near]);
                poolWeights.push_back(pointWeight(doc, uint32_t(i)));
                cells[cell(p, 0, 0, 0)].push_back(found);
            }
            remap[i] = found;
        }
    } else {
        std::unordered_map<Key, uint32_t, KeyHash> first;
        first.reserve(doc.points.size());
        for (size_t i = 0; i < doc.points.size(); ++i) {
            const Vec3& p = doc.points[i];
            const Key key{bits(p.x), bits(p.y), bits(p.z), bits(pointWeight(doc, uint32_t(i)))};
            auto [it, inserted] = first.emplace(key, static_cast<uint32_t>(pool.size()));
            if (inserted) pool.push_back(p);
            remap[i] = it->second;
        }
    }
    if (pool.size() == doc.points.size()) return;
    auto rewrite = [&](uint32_t& idx) {
        if (idx < remap.size()) idx = remap[idx];
    };
    forEachPointIndex(doc, rewrite);
    remapWeights(doc, remap, pool.size());
    doc.points = std::move(pool);
}

}  // namespace model
}  // namespace pw

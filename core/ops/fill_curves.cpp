#include "core/ops/fill_curves.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/base/errors.hpp"
#include "core/model/construction_refs.hpp"
#include "core/model/topology.hpp"
#include "core/ops/join_ops.hpp"

namespace pw {
inline namespace ops {

// A curve of one polynomial cubic segment, not closed: a fill's side (or a triangle's).
const BezierCurve& sideCurve(const Document& d, int32_t c, const std::string& side) {
    const std::string name = "curve c" + std::to_string(c);
    if (c < 0 || size_t(c) >= d.curves.size()) throw EditError("no " + name);
    const BezierCurve& curve = d.curves[size_t(c)];
    if (curveSegmentCount(curve) != 1)
        throw EditError(name + " has " + std::to_string(curveSegmentCount(curve)) + " segments; " + side +
                        " is one cubic (split the hole's side so each is one segment)");
    if (curve.idx.front() == curve.idx.back()) throw EditError(name + " is a loop; " + side + " runs between two corners");
    for (uint32_t i : curve.idx)
        if (pointWeight(d, i) != 1.0) throw EditError(name + " is rational; a fill's side takes no weights");
    return curve;
}

// A fill of patches splits a curve side at its middle: refused where that would cut the curve
// loose from something else — a live construction made from it, or an item or another curve that
// shares its inner points (a triangle filled through it, a curve made from an edge).
void checkCurveSplittable(const Document& d, int32_t c) {
    const std::string name = "curve c" + std::to_string(c);
    for (size_t k = 0; k < d.constructions.size(); ++k)
        for (const CurveInput& in : d.constructions[k].inputs)
            if (in.curve == c)
                throw EditError(name + " is an input of " + constructionLabel(d, k) +
                                ", which the fill's split of it would break; bake that first, or give the hole a copy of the curve");
    const auto& q = d.curves[size_t(c)].idx;
    const auto inner = [&](uint32_t i) { return i == q[1] || i == q[2]; };
    std::string user;
    for (size_t p = 0; p < d.patches.size() && user.empty(); ++p)
        if (std::any_of(d.patches[p].idx.begin(), d.patches[p].idx.end(), inner)) user = "patch " + std::to_string(p);
    for (size_t t = 0; t < d.triangles.size() && user.empty(); ++t)
        if (std::any_of(d.triangles[t].idx.begin(), d.triangles[t].idx.end(), inner)) user = "triangle " + std::to_string(t);
    for (size_t n = 0; n < d.surfaces.size() && user.empty(); ++n)
        if (std::any_of(d.surfaces[n].idx.begin(), d.surfaces[n].idx.end(), inner)) user = "net " + std::to_string(n);
    for (size_t o = 0; o < d.curves.size() && user.empty(); ++o)
        if (int32_t(o) != c && std::any_of(d.curves[o].idx.begin(), d.curves[o].idx.end(), inner)) user = "curve c" + std::to_string(o);
    if (!user.empty())
        throw EditError(name + " shares its points with " + user +
                        ", which the fill's split of the curve would leave behind; give the hole a curve of its own");
}

}  // namespace ops
}  // namespace pw

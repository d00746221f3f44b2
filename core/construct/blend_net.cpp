// Blends between two patch edges (construction_nets.hpp): the rows across from each side's
// continuity condition, the middle of a G2 blend from C2 between its three spans.
#include <algorithm>
#include <array>
#include <string>

#include "core/base/errors.hpp"
#include "core/construct/construction_nets.hpp"
#include "core/model/construction_refs.hpp"
#include "core/model/topology.hpp"

namespace pw {
inline namespace construct {

namespace {

using Row = std::array<Vec3, 4>;

// Rows 0, 1 and 2 inward of an input edge, as Cartesian points along the edge.
std::array<Row, 3> edgeRows(const Document& doc, const CurveInput& in) {
    std::array<Row, 3> rows;
    for (int d = 0; d < 3; ++d) {
        const std::vector<HPoint> r = d == 0 ? inputShape(doc, in).points : inputTangentRow(doc, in, d);
        for (size_t k = 0; k < 4; ++k) rows[size_t(d)][k] = euclidean(r[k]);
    }
    return rows;
}

struct BlendSides {
    std::array<Row, 3> a, b;  // b's rows indexed by a's edge point k
    bool flipU = false;       // the blend's column j is a's point 3 - j
    bool reversed = false;    // b's point m is a's point 3 - m
    double gap = 0, ta = 0, tb = 0;
};

BlendSides blendSides(const Document& doc, const Construction& c) {
    if (c.inputs.size() != 2) throw EditError("a blend bridges two patch edges");
    for (const CurveInput& in : c.inputs) {
        if (in.curve >= 0) throw EditError("a blend bridges patch edges; " + curveInputName(in) + " is a curve");
        // The patch exists and is Bézier; a weighted (rational) side is refused: with weights the
        // rows' Cartesian conditions are not the surface's G1/G2.
        for (int d = 0; d < 3; ++d)
            for (const HPoint& h : d == 0 ? inputShape(doc, in).points : inputTangentRow(doc, in, d))
                if (h.w != 1.0)
                    throw EditError("edge " + curveInputName(in) + " is rational (weighted points); a blend needs polynomial sides");
    }
    if (c.ends[0] != c.ends[1] || (c.ends[0] != Continuity::G1 && c.ends[0] != Continuity::G2))
        throw EditError("a blend is G1 or G2 at both ends");
    const CurveInput &ia = c.inputs[0], &ib = c.inputs[1];
    if (ia.patch == ib.patch && ia.edge == ib.edge) throw EditError("a blend needs two different edges");
    BlendSides s;
    const std::vector<uint32_t> ea = curveInputPoints(doc, ia), eb = curveInputPoints(doc, ib);
    if (c.grid.size() >= 4) {  // made already: keep the pairing its net has
        s.flipU = c.grid[0] != ea[0];
        const uint32_t lastRow = c.grid[c.grid.size() - 4];
        s.reversed = (lastRow != eb[0]) != s.flipU;
    } else {
        s.flipU = edgeLoopSign(ia.edge) > 0;
        s.reversed = edgesPairReversed(doc, ia.patch, ia.edge, ib.patch, ib.edge);
        if (edgeLoopSign(ib.edge) * edgeLoopSign(Edge::V1) * (s.reversed != s.flipU ? -1 : 1) > 0)
            throw EditError("patch " + std::to_string(ib.patch) + " faces the other way from patch " + std::to_string(ia.patch) +
                            " across the blend; flip one of them first (`flip`)");
    }
    s.a = edgeRows(doc, ia);
    const std::array<Row, 3> b = edgeRows(doc, ib);
    for (size_t d = 0; d < 3; ++d)
        for (size_t k = 0; k < 4; ++k) s.b[d][k] = b[d][s.reversed ? 3 - k : k];
    for (size_t k = 0; k < 4; ++k) {
        s.gap += glm::length(s.b[0][k] - s.a[0][k]);
        s.ta += glm::length(s.a[0][k] - s.a[1][k]);
        s.tb += glm::length(s.b[0][k] - s.b[1][k]);
    }
    const double size = std::max(s.gap, s.ta + s.tb);
    if (s.gap <= 1e-9 * size)
        throw EditError("edges " + curveInputName(ia) + " and " + curveInputName(ib) + " meet already; join them instead");
    if (s.ta <= 1e-12 * size || s.tb <= 1e-12 * size)
        throw EditError("the tangent row at " + curveInputName(s.ta <= 1e-12 * size ? ia : ib) +
                        " has collapsed onto its edge, so a blend has no direction to leave it in");
    return s;
}

int spansOf(const Construction& c) { return c.ends[0] == Continuity::G2 ? 3 : 1; }

}  // namespace

void chooseBlendAlphas(const Document& doc, Construction& c) {
    const BlendSides s = blendSides(doc, c);
    // Kept within the range the file reader takes (a gap far smaller or larger than the tangent rows).
    const double third = s.gap / (3.0 * spansOf(c));
    c.endAlpha = {std::clamp(third / s.ta, 1e-3, 1e3), std::clamp(third / s.tb, 1e-3, 1e3)};
}

ConstructedNet blendNet(const Document& doc, const Construction& c) {
    const BlendSides s = blendSides(doc, c);
    const int spans = spansOf(c), n = 3 * spans;
    const double alphaA = c.endAlpha[0], alphaB = c.endAlpha[1];
    std::vector<Row> q(size_t(n + 1));
    for (size_t k = 0; k < 4; ++k) {
        const Vec3 &a0 = s.a[0][k], &a1 = s.a[1][k], &a2 = s.a[2][k], &b0 = s.b[0][k], &b1 = s.b[1][k], &b2 = s.b[2][k];
        q[0][k] = a0;
        q[size_t(n)][k] = b0;
        q[1][k] = a0 + alphaA * (a0 - a1);
        q[size_t(n - 1)][k] = b0 + alphaB * (b0 - b1);
        if (spans == 1) continue;
        // G2 with β2 = 0: each side's third row from its second difference.
        q[2][k] = 2.0 * q[1][k] - a0 + alphaA * alphaA * (a2 - 2.0 * a1 + a0);
        q[7][k] = 2.0 * q[8][k] - b0 + alphaB * alphaB * (b2 - 2.0 * b1 + b0);
        // C2 at rows 3 and 6 between equal spans, Q1 − 2Q2 + Q3 = Q3 − 2Q4 + Q5 and
        // Q4 − 2Q5 + Q6 = Q6 − 2Q7 + Q8, with Q3 and Q6 the midpoints of their neighbours (C1).
        q[5][k] = (-q[1][k] + 2.0 * q[2][k] + 4.0 * q[7][k] - 2.0 * q[8][k]) / 3.0;
        q[4][k] = 2.0 * q[5][k] - 2.0 * q[7][k] + q[8][k];
        q[3][k] = 0.5 * (q[2][k] + q[4][k]);
        q[6][k] = 0.5 * (q[5][k] + q[7][k]);
    }
    const std::vector<uint32_t> ea = curveInputPoints(doc, c.inputs[0]), eb = curveInputPoints(doc, c.inputs[1]);
    ConstructedNet net;
    net.rows = uint32_t(n + 1);
    net.cols = 4;
    net.seamV = Continuity::C2;
    net.points.resize(size_t(net.rows) * 4);
    net.shared.assign(net.points.size(), -1);
    for (uint32_t r = 0; r < net.rows; ++r)
        for (uint32_t j = 0; j < 4; ++j) {
            const size_t k = s.flipU ? 3 - j : j, g = size_t(r) * 4 + j;
            net.points[g] = homogeneous(q[r][k]);
            if (r == 0) net.shared[g] = ea[k];
            if (r == net.rows - 1) net.shared[g] = eb[s.reversed ? 3 - k : k];
        }
    // The shared rows keep their points' own weights (a rational edge stays exact).
    for (uint32_t j = 0; j < 4; ++j)
        for (uint32_t r : {0u, net.rows - 1}) {
            const size_t g = size_t(r) * 4 + j;
            const uint32_t i = uint32_t(net.shared[g]);
            net.points[g] = homogeneous(doc.points[i], pointWeight(doc, i));
        }
    return net;
}

}  // namespace construct
}  // namespace pw

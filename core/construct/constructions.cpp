#include "core/construct/constructions.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/construct/construction_nets.hpp"
#include "core/model/construction_refs.hpp"

namespace pw {
inline namespace construct {

namespace {

void checkNet(const ConstructedNet& net) {
    for (const HPoint& h : net.points)
        for (int a = 0; a < 3; ++a) {
            const double v = h[a] / h.w;
            if (!std::isfinite(v) || std::abs(v) > limits::kMaxCoordinate)
                throw EditError("the surface reaches beyond the coordinate limit of 1e9");
        }
}

// The window (pr, pc) of a net as 16 grid positions (row-major, row = v).
std::array<uint32_t, 16> window(const std::vector<uint32_t>& grid, uint32_t cols, uint32_t pr, uint32_t pc) {
    std::array<uint32_t, 16> w{};
    for (uint32_t i = 0; i < 4; ++i)
        for (uint32_t j = 0; j < 4; ++j) w[i * 4 + j] = grid[size_t(3 * pr + i) * cols + 3 * pc + j];
    return w;
}

// Writes the net into the construction's pool points; `moved` gets those whose position or weight changed.
void writeNet(Document& doc, const Construction& c, const ConstructedNet& net, std::vector<uint32_t>& moved) {
    for (size_t g = 0; g < c.grid.size(); ++g) {
        const uint32_t i = c.grid[g];
        const Vec3 p = euclidean(net.points[g]);
        const double w = net.points[g].w;
        if (doc.points[i] != p || pointWeight(doc, i) != w) {
            doc.points[i] = p;
            setPointWeight(doc, i, w);
            moved.push_back(i);
        }
    }
}

// True when patch b leaves patch a's edge along a's tangent: B1k - B0k = α (A0k - A1k) at all four
// points, within 1e-9 of the model's size (a join's G1 condition with the join's α).
bool tangentContinues(const Document& doc, const Join& j) {
    const Patch &a = doc.patches[j.patchA], &b = doc.patches[j.patchB];
    double size = 1.0, worst = 0.0;
    for (int k = 0; k < 4; ++k) {
        const int kb = j.reversed ? 3 - k : k;
        const Vec3 a0 = doc.points[a.idx[size_t(edgeSlot(j.edgeA, k))]], a1 = doc.points[a.idx[size_t(edgeSlot(j.edgeA, k, 1))]];
        const Vec3 b0 = doc.points[b.idx[size_t(edgeSlot(j.edgeB, kb))]], b1 = doc.points[b.idx[size_t(edgeSlot(j.edgeB, kb, 1))]];
        size = std::max({size, glm::length(a0), glm::length(a1), glm::length(b1)});
        worst = std::max(worst, glm::length((b1 - b0) - j.alpha * (a0 - a1)));
    }
    return worst <= 1e-9 * size;
}

}  // namespace

CurveShape inputShape(const Document& doc, const CurveInput& in) {
    CurveShape s;
    if (in.curve >= 0) {
        if (size_t(in.curve) >= doc.curves.size()) throw EditError("curve c" + std::to_string(in.curve) + " does not exist");
        const BezierCurve& cv = doc.curves[size_t(in.curve)];
        for (uint32_t i : cv.idx) s.points.push_back(homogeneous(doc.points[i], pointWeight(doc, i)));
        s.closed = curveClosed(cv);
        return s;
    }
    if (in.patch >= doc.patches.size()) throw EditError("patch " + std::to_string(in.patch) + " does not exist");
    const Patch& p = doc.patches[in.patch];
    if (p.basis != Basis::Bezier) throw EditError("patch " + std::to_string(in.patch) + " is not a Bézier patch; its edge is no curve");
    for (int k = 0; k < 4; ++k) {
        const uint32_t i = p.idx[size_t(edgeSlot(in.edge, k))];
        s.points.push_back(homogeneous(doc.points[i], pointWeight(doc, i)));
    }
    return s;
}

std::vector<HPoint> inputTangentRow(const Document& doc, const CurveInput& in, int depth) {
    std::vector<HPoint> row;
    if (in.curve >= 0 || in.patch >= doc.patches.size()) return row;
    for (int k = 0; k < 4; ++k) {
        const uint32_t i = doc.patches[in.patch].idx[size_t(edgeSlot(in.edge, k, depth))];
        row.push_back(homogeneous(doc.points[i], pointWeight(doc, i)));
    }
    return row;
}

ConstructedNet evaluateConstruction(const Document& doc, const Construction& c) {
    ConstructedNet net;
    switch (c.kind) {
        case ConstructionKind::Revolve:
            net = revolveNet(doc, c);
            break;
        case ConstructionKind::Extrude:
            net = extrudeNet(doc, c);
            break;
        case ConstructionKind::Loft:
            net = loftNet(doc, c);
            break;
        case ConstructionKind::EdgeSurface:
            net = edgeSurfaceNet(doc, c);
            break;
        case ConstructionKind::Sweep1:
            net = sweep1Net(doc, c);
            break;
        case ConstructionKind::Sweep2:
            net = sweep2Net(doc, c);
            break;
        case ConstructionKind::Network:
            net = networkNet(doc, c);
            break;
        case ConstructionKind::Blend:
            net = blendNet(doc, c);
            break;
    }
    checkNet(net);
    return net;
}

size_t addConstruction(Document& doc, Construction c, const std::string& name) {
    ConstructedNet net = evaluateConstruction(doc, c);
    if (c.kind == ConstructionKind::Network) {  // one pool point where curves meet, then the net on it
        makeNetworkCorners(doc, c);
        net = evaluateConstruction(doc, c);
    }
    const uint32_t wr = (net.rows - 1) / 3, wc = (net.cols - 1) / 3;
    if (net.rows > limits::kMaxNetSide || net.cols > limits::kMaxNetSide)
        throw EditError("the surface's net would be " + std::to_string(net.rows) + " x " + std::to_string(net.cols) + " points; " +
                        std::to_string(limits::kMaxNetSide) + " a side at most");
    if (doc.points.size() + net.points.size() > limits::kMaxPoints || doc.patches.size() + size_t(wr) * wc > limits::kMaxPatches)
        throw EditError("the document is full (the surface needs " + std::to_string(size_t(wr) * wc) + " patches)");
    c.rows = net.rows, c.cols = net.cols;
    c.grid.assign(net.points.size(), 0);
    c.error.clear();
    for (uint32_t i = 0; i < net.rows; ++i)
        for (uint32_t j = 0; j < net.cols; ++j) {
            uint32_t& g = c.grid[size_t(i) * net.cols + j];
            if (!net.shared.empty() && net.shared[size_t(i) * net.cols + j] >= 0)
                g = uint32_t(net.shared[size_t(i) * net.cols + j]);
            else if (net.closedU && j == net.cols - 1)
                g = c.grid[size_t(i) * net.cols];
            else if (net.closedV && i == net.rows - 1)
                g = c.grid[j];
            else {
                g = uint32_t(doc.points.size());
                doc.points.push_back(Vec3(0.0));
            }
        }
    std::vector<uint32_t> moved;
    writeNet(doc, c, net, moved);
    const uint32_t first = uint32_t(doc.patches.size());
    // The patches carry the construction's own name: the second blend's are "blend 2 0" …, so that
    // constructions of one kind (and their patches once baked) stay told apart.
    std::string base = name;
    for (int n = 2; std::any_of(doc.patches.begin(), doc.patches.end(), [&](const Patch& q) { return q.name.rfind(base + " ", 0) == 0; });
         ++n)
        base = name + " " + std::to_string(n);
    for (uint32_t pr = 0; pr < wr; ++pr)
        for (uint32_t pc = 0; pc < wc; ++pc) {
            Patch p;
            p.idx = window(c.grid, net.cols, pr, pc);
            p.name = base + " " + std::to_string(pr * wc + pc);
            c.patches.push_back(uint32_t(doc.patches.size()));
            doc.patches.push_back(std::move(p));
        }
    // Joins along every seam between the windows: G1 (α = 1) or C2 where the construction makes it
    // so, C0 elsewhere (the surface there is as smooth as its inputs; the readout measures it).
    const auto at = [&](uint32_t pr, uint32_t pc) { return first + pr * wc + pc; };
    for (uint32_t pr = 0; pr < wr; ++pr)
        for (uint32_t pc = 0; pc < wc; ++pc) {
            if (pc + 1 < wc || (net.closedU && wc > 1))
                doc.joins.push_back(
                    Join{at(pr, pc), Edge::U1, at(pr, (pc + 1) % wc), Edge::U0, false, net.smoothU ? Continuity::G1 : Continuity::C0, 1.0});
            if (pr + 1 < wr || (net.closedV && wr > 1))
                doc.joins.push_back(Join{at(pr, pc), Edge::V1, at((pr + 1) % wr, pc), Edge::V0, false, net.seamV, 1.0});
        }
    // Patch edges used as inputs whose points the surface shares: their patches are joined to the
    // new ones, G1 where the surface leaves the edge along the patch's tangent (a loft's G1 ends; an
    // edge surface's sides where the corners allow it), C0 elsewhere.
    for (size_t k = 0; k < c.inputs.size(); ++k) {
        const CurveInput& in = c.inputs[k];
        if (in.curve >= 0) continue;
        const std::vector<uint32_t> pts = curveInputPoints(doc, in);  // an edge: four
        const std::array<uint32_t, 4> e{pts[0], pts[1], pts[2], pts[3]};
        for (uint32_t n = 0; n < c.patches.size(); ++n)
            for (Edge mine : {Edge::U0, Edge::V0, Edge::U1, Edge::V1}) {
                std::array<uint32_t, 4> m{};
                for (int q = 0; q < 4; ++q) m[size_t(q)] = doc.patches[c.patches[n]].idx[size_t(edgeSlot(mine, q))];
                const bool same = m == e, reversed = m == reversedEdgePool(e);
                if (!(same || reversed) || e.front() == e.back()) continue;
                Join j{in.patch, in.edge, c.patches[n], mine, reversed, Continuity::C0, 1.0};
                const bool end = (c.kind == ConstructionKind::Loft && !c.closed) || c.kind == ConstructionKind::Blend;
                if (end && (k == 0 || k + 1 == c.inputs.size())) {
                    const size_t end = k == 0 ? 0 : 1;
                    j.continuity = c.ends[end];
                    j.alpha = c.endAlpha[end];
                } else if (c.kind == ConstructionKind::EdgeSurface && tangentContinues(doc, j)) {
                    j.continuity = Continuity::G1;
                }
                doc.joins.push_back(j);
            }
    }
    doc.constructions.push_back(std::move(c));
    return doc.constructions.size() - 1;
}

RerunReport rerunConstructions(Document& doc) {
    RerunReport report;
    for (size_t k = doc.constructions.size(); k-- > 0;) {
        const Construction& c = doc.constructions[k];
        const uint32_t wr = c.rows >= 4 ? (c.rows - 1) / 3 : 0, wc = c.cols >= 4 ? (c.cols - 1) / 3 : 0;
        bool intact = c.grid.size() == size_t(c.rows) * c.cols && c.patches.size() == size_t(wr) * wc;
        for (uint32_t n = 0; intact && n < c.patches.size(); ++n)
            intact = c.patches[n] < doc.patches.size() && doc.patches[c.patches[n]].idx == window(c.grid, c.cols, n / wc, n % wc);
        if (!intact) {
            report.baked.push_back(constructionLabel(doc, k));
            bakeConstruction(doc, k);
        }
    }
    for (size_t k = 0; k < doc.constructions.size(); ++k) {
        Construction& c = doc.constructions[k];
        try {
            const ConstructedNet net = evaluateConstruction(doc, c);
            if (net.rows != c.rows || net.cols != c.cols)
                throw EditError("the inputs now make a " + std::to_string((net.rows - 1) / 3) + " × " + std::to_string((net.cols - 1) / 3) +
                                " net of patches, the surface has " + std::to_string((c.rows - 1) / 3) + " × " +
                                std::to_string((c.cols - 1) / 3) + " (bake it, or undo the change of the input)");
            writeNet(doc, c, net, report.moved);
            c.error.clear();
        } catch (const EditError& e) {
            c.error = e.what();
            report.failed.push_back(constructionLabel(doc, k) + ": " + c.error);
        }
    }
    std::sort(report.moved.begin(), report.moved.end());
    report.moved.erase(std::unique(report.moved.begin(), report.moved.end()), report.moved.end());
    return report;
}

}  // namespace construct
}  // namespace pw

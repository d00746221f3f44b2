// Net surfaces: creation, row/column edits, closing, basis switch, exact conversion to Bézier
// patches and back, spline continuity, the C1 seams of Bézier nets, and file round trips.
#include <gtest/gtest.h>

#include <tuple>

#include <cmath>
#include <random>

#include "core/eval/patch_eval.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/ops/net_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/solve/constraint_solver.hpp"

namespace {

using pw::Basis;
using pw::Document;
using pw::Vec3;

// A net with bumpy, non-planar points so that every basis gives a distinct surface.
Document bumpyNet(Basis basis, uint32_t rows, uint32_t cols, pw::NetShape shape = pw::NetShape::Flat, double tension = 0.5) {
    Document doc;
    const uint32_t s = pw::addNetSurface(doc, rows, cols, shape, basis, Vec3(0.0), 4.0);
    std::mt19937 rng(7 + rows * 31 + cols);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    for (Vec3& p : doc.points) p += Vec3(jitter(rng), jitter(rng), jitter(rng));
    doc.surfaces[s].tension = tension;
    return doc;
}

// The surface of window (wr, wc) of net s at (u, v), evaluated straight from the net's basis.
pw::SurfacePoint netPoint(const Document& doc, const pw::Surface& s, uint32_t wr, uint32_t wc, double u, double v) {
    const uint32_t step = pw::netStep(s.basis);
    pw::Net16 net;
    for (uint32_t i = 0; i < 4; ++i)
        for (uint32_t j = 0; j < 4; ++j)
            net[i * 4 + j] = doc.points[s.idx[size_t((wr * step + i) % s.rows) * s.cols + (wc * step + j) % s.cols]];
    return pw::evaluateNet(net, s.basis, s.tension, u, v);
}

pw::SurfacePoint patchPoint(const Document& doc, uint32_t p, double u, double v) {
    return pw::evaluateNet(pw::gatherNet(doc, doc.patches[p].idx), doc.patches[p].basis, doc.patches[p].tension, u, v);
}

// Second derivatives along u and v by central differences of the analytic first derivatives.
Vec3 secondU(const Document& doc, const pw::Surface& s, uint32_t wr, uint32_t wc, double u, double v) {
    const double h = 1e-4;
    return (netPoint(doc, s, wr, wc, u + h, v).du - netPoint(doc, s, wr, wc, u - h, v).du) / (2 * h);
}

struct Case {
    Basis basis;
    uint32_t rows, cols;
    pw::NetShape shape;
    double tension;
};

const Case kCases[] = {
    {Basis::BSpline, 6, 7, pw::NetShape::Flat, 0.5},    {Basis::BSpline, 5, 8, pw::NetShape::Tube, 0.5},
    {Basis::BSpline, 6, 6, pw::NetShape::Torus, 0.5},   {Basis::CatmullRom, 5, 6, pw::NetShape::Flat, 0.5},
    {Basis::CatmullRom, 7, 5, pw::NetShape::Flat, 0.3}, {Basis::CatmullRom, 6, 9, pw::NetShape::Torus, 0.8},
    {Basis::Bezier, 7, 10, pw::NetShape::Flat, 0.5},    {Basis::Bezier, 6, 9, pw::NetShape::Torus, 0.5},
};

}  // namespace

TEST(NetOps, ConvertedBezierPatchesReproduceTheSplineSurface) {
    for (const Case& c : kCases) {
        SCOPED_TRACE(std::string(pw::basisName(c.basis)) + " " + std::to_string(c.rows) + "x" + std::to_string(c.cols));
        const Document doc = bumpyNet(c.basis, c.rows, c.cols, c.shape, c.tension);
        const pw::Surface s = doc.surfaces[0];
        Document conv = doc;
        const std::vector<uint32_t> patches = pw::convertNetToPatches(conv, 0);
        ASSERT_TRUE(conv.surfaces.empty());
        const uint32_t step = pw::netStep(c.basis);
        const uint32_t wu = uint32_t(pw::netWindowCount(s.cols, s.closedU, step));
        const uint32_t wv = uint32_t(pw::netWindowCount(s.rows, s.closedV, step));
        ASSERT_EQ(patches.size(), size_t(wu) * wv);
        double worst = 0.0;
        for (uint32_t wr = 0; wr < wv; ++wr)
            for (uint32_t wc = 0; wc < wu; ++wc)
                for (double u : {0.0, 0.13, 0.5, 0.77, 1.0})
                    for (double v : {0.0, 0.29, 0.5, 0.91, 1.0}) {
                        const pw::SurfacePoint a = netPoint(doc, s, wr, wc, u, v);
                        const pw::SurfacePoint b = patchPoint(conv, patches[wr * wu + wc], u, v);
                        worst = std::max({worst, glm::length(a.p - b.p), glm::length(a.du - b.du), glm::length(a.dv - b.dv)});
                    }
        EXPECT_LE(worst, 1e-9);
        // Neighbouring patches share their boundary points, and the joins the basis implies hold.
        const size_t expectedJoins = size_t(s.closedU ? wu : wu - 1) * wv + size_t(s.closedV ? wv : wv - 1) * wu;
        EXPECT_EQ(conv.joins.size(), expectedJoins);
        for (const pw::Join& j : conv.joins) EXPECT_EQ(j.continuity, c.basis == Basis::Bezier ? pw::Continuity::C0 : pw::Continuity::C1);
        EXPECT_LE(pw::maxConstraintResidual(conv), 1e-9 * pw::modelSize(conv));
    }
}

TEST(NetOps, BSplineNetsAreC2AndCatmullRomNetsInterpolate) {
    const Document bs = bumpyNet(Basis::BSpline, 6, 7);
    const pw::Surface& s = bs.surfaces[0];
    for (uint32_t wc = 0; wc + 1 < 4; ++wc)
        for (double v : {0.0, 0.4, 1.0}) {
            const pw::SurfacePoint a = netPoint(bs, s, 1, wc, 1.0, v), b = netPoint(bs, s, 1, wc + 1, 0.0, v);
            EXPECT_LE(glm::length(a.p - b.p), 1e-12);
            EXPECT_LE(glm::length(a.du - b.du), 1e-12);
            EXPECT_LE(glm::length(secondU(bs, s, 1, wc, 1.0 - 1e-4, v) - secondU(bs, s, 1, wc + 1, 1e-4, v)), 1e-3);
        }
    for (double tension : {0.5, 0.2}) {
        const Document cr = bumpyNet(Basis::CatmullRom, 5, 6, pw::NetShape::Flat, tension);
        const pw::Surface& c = cr.surfaces[0];
        for (uint32_t wr = 0; wr < 2; ++wr)
            for (uint32_t wc = 0; wc < 3; ++wc)
                for (uint32_t i : {0u, 1u})
                    for (uint32_t j : {0u, 1u}) {
                        const Vec3 inner = cr.points[c.idx[size_t(wr + 1 + i) * c.cols + wc + 1 + j]];
                        EXPECT_LE(glm::length(netPoint(cr, c, wr, wc, j, i).p - inner), 1e-12);
                    }
    }
}

TEST(NetOps, ClosedNetsHaveNoSeam) {
    for (Basis b : {Basis::BSpline, Basis::CatmullRom}) {
        const Document doc = bumpyNet(b, 6, 8, pw::NetShape::Torus);
        const pw::Surface& s = doc.surfaces[0];
        const uint32_t n = s.cols;
        for (double v : {0.0, 0.3, 1.0}) {
            const pw::SurfacePoint last = netPoint(doc, s, 2, n - 1, 1.0, v), first = netPoint(doc, s, 2, 0, 0.0, v);
            EXPECT_LE(glm::length(last.p - first.p), 1e-12);
            EXPECT_LE(glm::length(last.du - first.du), 1e-12);
            EXPECT_LE(glm::length(last.n - first.n), 1e-12);
        }
    }
}

TEST(NetOps, GridOfBezierPatchesConvertsBackToTheSameBSplineNet) {
    for (const Case& c : kCases) {
        if (c.basis != Basis::BSpline) continue;
        SCOPED_TRACE(std::to_string(c.rows) + "x" + std::to_string(c.cols));
        const Document doc = bumpyNet(c.basis, c.rows, c.cols, c.shape);
        Document conv = doc;
        pw::convertNetToPatches(conv, 0);
        const uint32_t s = pw::convertPatchesToNet(conv, {});
        ASSERT_TRUE(conv.patches.empty());
        ASSERT_TRUE(conv.joins.empty());
        const pw::Surface& a = doc.surfaces[0];
        const pw::Surface& b = conv.surfaces[s];
        ASSERT_EQ(b.rows, a.rows);
        ASSERT_EQ(b.cols, a.cols);
        EXPECT_EQ(b.closedU, a.closedU);
        EXPECT_EQ(b.closedV, a.closedV);
        double worst = 0.0;
        for (size_t k = 0; k < a.idx.size(); ++k) worst = std::max(worst, glm::length(doc.points[a.idx[k]] - conv.points[b.idx[k]]));
        EXPECT_LE(worst, 1e-9);
        EXPECT_EQ(conv.points.size(), a.idx.size());  // the Bézier points are gone
    }
}

TEST(NetOps, OnlyARegularC2GridConvertsToANet) {
    // Catmull-Rom windows are only C1: their Bézier patches are no C2 grid.
    Document cr = bumpyNet(Basis::CatmullRom, 6, 6);
    pw::convertNetToPatches(cr, 0);
    const Document before = cr;
    try {
        pw::convertPatchesToNet(cr, {});
        FAIL() << "expected an error";
    } catch (const pw::EditError& e) {
        EXPECT_NE(std::string(e.what()).find("not C2"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(cr == before);
    // A patch that is no part of the grid.
    Document bs = bumpyNet(Basis::BSpline, 5, 5);
    pw::convertNetToPatches(bs, 0);
    pw::addFlatPatch(bs, Vec3(10.0), 1.0);
    EXPECT_THROW(pw::convertPatchesToNet(bs, {}), pw::EditError);
    // The same grid without the stray patch converts.
    std::vector<uint32_t> grid;
    for (uint32_t p = 0; p + 1 < bs.patches.size(); ++p) grid.push_back(p);
    EXPECT_NO_THROW(pw::convertPatchesToNet(bs, grid));
    EXPECT_EQ(bs.patches.size(), 1u);
    EXPECT_EQ(bs.surfaces.size(), 1u);
}

// A C1 grid (a Catmull-Rom net's patches, closed around too) becomes one Bézier net keeping C1 on
// the patches' own points; a grid with a kink is refused and left as it was.
TEST(NetOps, AC1GridConvertsToABezierNetKeepingC1) {
    for (const pw::NetShape shape : {pw::NetShape::Flat, pw::NetShape::Tube}) {
        Document cr = bumpyNet(Basis::CatmullRom, 5, 6, shape);
        const pw::BezierGrid grid = pw::netToBezierGrid(cr, cr.surfaces[0]);
        pw::convertNetToPatches(cr, 0);
        const size_t points = cr.points.size();
        const uint32_t s = pw::convertPatchesToBezierNet(cr, {});
        EXPECT_TRUE(cr.patches.empty());
        EXPECT_EQ(cr.points.size(), points);  // the patches' own points
        const pw::Surface& net = cr.surfaces[s];
        EXPECT_EQ(net.basis, Basis::Bezier);
        EXPECT_TRUE(net.keepC1);
        EXPECT_EQ(std::tie(net.rows, net.cols, net.closedU, net.closedV), std::tie(grid.rows, grid.cols, grid.closedU, grid.closedV));
        for (size_t k = 0; k < grid.points.size(); ++k) EXPECT_LT(glm::length(cr.points[net.idx[k]] - grid.points[k]), 1e-12) << k;
    }
    Document kinked = bumpyNet(Basis::CatmullRom, 5, 5);
    pw::convertNetToPatches(kinked, 0);
    kinked.points[kinked.patches[0].idx[2]].z += 0.5;  // beside the seam u = 1 of patch 0
    const Document before = kinked;
    EXPECT_THROW(pw::convertPatchesToBezierNet(kinked, {}), pw::EditError);
    EXPECT_TRUE(kinked == before);
}

TEST(NetOps, RowsAndColumnsInsertDeleteAndClose) {
    Document doc;
    pw::addNetSurface(doc, 4, 5, pw::NetShape::Flat, Basis::BSpline, Vec3(0.0), 4.0);
    const Vec3 r0 = doc.points[doc.surfaces[0].idx[0]], r1 = doc.points[doc.surfaces[0].idx[5]];
    pw::insertNetRow(doc, 0, 1);
    ASSERT_EQ(doc.surfaces[0].rows, 5u);
    EXPECT_EQ(doc.points[doc.surfaces[0].idx[5]], 0.5 * (r0 + r1));  // midway
    pw::insertNetRow(doc, 0, 5);                                     // past the end: continues the spacing
    const pw::Surface& s = doc.surfaces[0];
    EXPECT_LE(glm::length(doc.points[s.idx[25]] - (2.0 * doc.points[s.idx[20]] - doc.points[s.idx[15]])), 1e-12);
    pw::insertNetColumn(doc, 0, 0);
    EXPECT_EQ(doc.surfaces[0].cols, 6u);
    EXPECT_EQ(doc.surfaces[0].idx.size(), 36u);
    pw::deleteNetColumn(doc, 0, 0);
    pw::deleteNetRow(doc, 0, 5);
    pw::deleteNetRow(doc, 0, 1);
    EXPECT_EQ(doc.surfaces[0].rows, 4u);
    EXPECT_EQ(doc.points.size(), 20u);  // points nobody uses are gone
    EXPECT_EQ(doc.points[doc.surfaces[0].idx[5]], r1);
    const Document before = doc;
    try {
        pw::deleteNetColumn(doc, 0, 0);
        pw::deleteNetColumn(doc, 0, 0);
        FAIL() << "expected an error";
    } catch (const pw::EditError& e) {
        EXPECT_NE(std::string(e.what()).find("4 columns"), std::string::npos) << e.what();
    }
    doc = before;
    pw::setNetClosed(doc, 0, true, true);
    EXPECT_TRUE(doc.surfaces[0].closedU);
    EXPECT_EQ(pw::expandPatches(doc).size(), 5u);  // 5 columns wrap into 5 windows, 1 row of windows
    // A closed Bézier net needs a multiple of 3 columns.
    EXPECT_THROW(pw::setNetBasis(doc, 0, Basis::Bezier, 0.5), pw::EditError);
    EXPECT_TRUE(doc.surfaces[0].basis == Basis::BSpline);
    pw::setNetClosed(doc, 0, true, false);
    pw::setNetBasis(doc, 0, Basis::Bezier, 0.5);
    ASSERT_TRUE(pw::netLayoutProblem(doc.surfaces[0]).has_value());
    EXPECT_NE(pw::netLayoutProblem(doc.surfaces[0])->find("3k + 1"), std::string::npos);
    EXPECT_THROW(pw::addNetSurface(doc, 3, 8, pw::NetShape::Flat, Basis::BSpline, Vec3(0.0), 1.0), pw::EditError);
    EXPECT_THROW(pw::addNetSurface(doc, 5, 5, pw::NetShape::Flat, Basis::BSpline, Vec3(0.0), std::nan("")), pw::EditError);
}

TEST(NetOps, BezierNetThatKeepsC1HoldsItWhileDragging) {
    Document doc = bumpyNet(Basis::Bezier, 7, 7);
    doc.surfaces[0].keepC1 = true;
    ASSERT_EQ(pw::netC1Triples(doc).size(), 2u * 7u);  // one seam each way, 7 points along it
    pw::projectConstraints(doc, {});
    EXPECT_LE(pw::maxConstraintResidual(doc), 1e-9 * pw::modelSize(doc));
    const uint32_t moved = doc.surfaces[0].idx[2 * 7 + 2];  // a tangent point beside the u seam
    pw::DragSolver solver(doc, {moved});
    Document dragged = doc;
    dragged.points[moved] += Vec3(0.3, -0.2, 0.5);
    solver.project(dragged.points);
    EXPECT_LE(pw::maxConstraintResidual(dragged), 1e-9 * pw::modelSize(dragged));
    const pw::Surface& s = dragged.surfaces[0];
    const Vec3 before = dragged.points[s.idx[2 * 7 + 2]], seam = dragged.points[s.idx[2 * 7 + 3]], after = dragged.points[s.idx[2 * 7 + 4]];
    EXPECT_LE(glm::length(seam - 0.5 * (before + after)), 1e-9);
    // Converted, the same net gives C1 joins that hold.
    pw::convertNetToPatches(dragged, 0);
    for (const pw::Join& j : dragged.joins) EXPECT_EQ(j.continuity, pw::Continuity::C1);
    EXPECT_LE(pw::maxConstraintResidual(dragged), 1e-9 * pw::modelSize(dragged));
}

TEST(NetOps, NetsRoundTripThroughPatchworkFiles) {
    Document doc = bumpyNet(Basis::Bezier, 7, 10);
    doc.surfaces[0].keepC1 = true;
    pw::addNetSurface(doc, 6, 9, pw::NetShape::Torus, Basis::CatmullRom, Vec3(5.0, 0.0, 0.0), 2.0);
    doc.surfaces[1].tension = 0.35;
    pw::addNetSurface(doc, 5, 8, pw::NetShape::Tube, Basis::BSpline, Vec3(-5.0, 0.0, 0.0), 2.0, false);
    const std::string text = pw::serializeDocument(doc);
    EXPECT_NE(text.find("\"keepC1\":true"), std::string::npos);
    EXPECT_TRUE(pw::parseDocument(text, "nets.patchwork") == doc);
}

TEST(NetOps, DeletingANetDropsItsPointsOnly) {
    Document doc;
    pw::addFlatPatch(doc, Vec3(0.0), 1.0);
    pw::addNetSurface(doc, 4, 5, pw::NetShape::Flat, Basis::BSpline, Vec3(3.0), 1.0);
    pw::deleteNetSurface(doc, 0);
    EXPECT_TRUE(doc.surfaces.empty());
    EXPECT_EQ(doc.points.size(), 16u);
    EXPECT_THROW(pw::deleteNetSurface(doc, 0), pw::EditError);
}

// Issue 40 item 4: Bézier triangles in joins (core/solve/triangle_seams, core/ops/triangle_joins).
// A triangle's edge joins C0 or G1 to a patch's edge or another triangle's with `join … tN:eK …`,
// the seam holds while points on either side are dragged, and the join survives saving, splits
// beside it and deletions of other items; what cannot be a triangle join is refused with a reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/commands/command_table.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/model/topology.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"
#include "support.hpp"

using namespace pw;

namespace {

// The smooth surface both sides sample: z = 0.3 x² + 0.2 y² (+ a tilt), quadratic in x and y, so a
// bicubic patch and a cubic triangle over any planar domain reproduce it exactly.
double height(double x, double y) { return 0.3 * x * x + 0.2 * y * y + 0.1 * x * y; }

// Solves the n×n system A x = b (rows of A, several right-hand sides) by Gaussian elimination with
// partial pivoting.
std::vector<Vec3> solve(std::vector<std::vector<double>> A, std::vector<Vec3> b) {
    const size_t n = A.size();
    for (size_t c = 0; c < n; ++c) {
        size_t pivot = c;
        for (size_t r = c + 1; r < n; ++r)
            if (std::abs(A[r][c]) > std::abs(A[pivot][c])) pivot = r;
        std::swap(A[c], A[pivot]);
        std::swap(b[c], b[pivot]);
        for (size_t r = c + 1; r < n; ++r) {
            const double f = A[r][c] / A[c][c];
            for (size_t k = c; k < n; ++k) A[r][k] -= f * A[c][k];
            b[r] -= f * b[c];
        }
    }
    std::vector<Vec3> x(n);
    for (size_t c = n; c-- > 0;) {
        Vec3 v = b[c];
        for (size_t k = c + 1; k < n; ++k) v -= A[c][k] * x[k];
        x[c] = v / A[c][c];
    }
    return x;
}

double bernstein3(int i, double t) {
    static constexpr double kC[4] = {1, 3, 3, 1};
    return kC[i] * std::pow(t, i) * std::pow(1 - t, 3 - i);
}

// The bicubic patch over [x0, x0+1] × [y0, y0+1] (u along x, v along y), interpolating the surface
// at the 4×4 grid of thirds (exact: it is a polynomial of degree 2 in each).
void addPatch(Document& d, double x0, double y0) {
    std::vector<std::vector<double>> A;
    std::vector<Vec3> b;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            std::vector<double> row(16);
            for (int a = 0; a < 4; ++a)
                for (int c = 0; c < 4; ++c) row[size_t(a * 4 + c)] = bernstein3(a, i / 3.0) * bernstein3(c, j / 3.0);
            A.push_back(row);
            const double x = x0 + j / 3.0, y = y0 + i / 3.0;
            b.emplace_back(x, y, height(x, y));
        }
    Patch p;
    const std::vector<Vec3> x = solve(A, b);
    for (size_t s = 0; s < 16; ++s) {
        p.idx[s] = uint32_t(d.points.size());
        d.points.push_back(x[s]);
    }
    d.patches.push_back(p);
}

// A cubic triangle whose corners (u = 1, v = 1, w = 1) lie over xy points cu, cv, cw: the 10
// control points interpolate the surface at the domain's cubic grid (exact for it).
void addTriangle(Document& d, Vec3 cu, Vec3 cv, Vec3 cw) {
    std::vector<std::vector<double>> A(10, std::vector<double>(10));
    std::vector<Vec3> b(10);
    size_t row = 0;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j + i <= 3; ++j, ++row) {
            const double u = i / 3.0, v = j / 3.0, w = (3 - i - j) / 3.0;
            for (int a = 0; a <= 3; ++a)
                for (int c = 0; a + c <= 3; ++c) {
                    const int e = 3 - a - c;
                    const double coef = 6.0 / (std::tgamma(a + 1) * std::tgamma(c + 1) * std::tgamma(e + 1));
                    A[row][size_t(triSlot(a, c, e))] = coef * std::pow(u, a) * std::pow(v, c) * std::pow(w, e);
                }
            const Vec3 xy = u * cu + v * cv + w * cw;
            b[row] = Vec3(xy.x, xy.y, height(xy.x, xy.y));
        }
    const std::vector<Vec3> x = solve(A, b);
    TrianglePatch t;
    for (size_t s = 0; s < 10; ++s) {
        t.idx[s] = uint32_t(d.points.size());
        d.points.push_back(x[s]);
    }
    d.triangles.push_back(t);
}

struct Recorder final : CommandHost {
    std::string last;
    void status(const std::string& s) override { last = s; }
    void write(const Document&, const std::string&) override {}
};

void run(EditSession& s, const std::string& line) {
    Recorder host;
    makeCommandTable().run(s, host, line);
}

std::string refusal(EditSession& s, const std::string& line) {
    try {
        run(s, line);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

// Every join within 0.1° (G1 ones) and the solver's residual.
void expectHeld(const Document& d, const std::string& when) {
    ASSERT_FALSE(d.joins.empty()) << when;
    for (const JoinContinuity& c : continuityReport(d, 32)) {
        EXPECT_LE(c.c0Gap, 1e-9) << when << ": join " << c.join;
        if (d.joins[c.join].continuity == Continuity::G1) {
            EXPECT_LE(c.normalAngleDeg, 0.1) << when << ": join " << c.join;
        }
    }
    EXPECT_LE(maxConstraintResidual(d), 1e-6 * modelSize(d)) << when;
}

// The largest G1 defect of join j along its seam.
double seamAngle(const Document& d, size_t j) { return continuityReport(d, 32, {j}).at(0).normalAngleDeg; }

// Patch 0 over [0,1]², triangle 0 below its v0 edge (its edge 2, w = 0, runs from (1,0) to (0,0)).
Document patchAndTriangle() {
    Document d;
    addPatch(d, 0, 0);
    addTriangle(d, Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0.4, -0.8, 0));
    return d;
}

}  // namespace

TEST(TriangleJoins, ATriangleJoinsAPatchG1AndHoldsWhileEitherSideIsDragged) {
    EditSession s;
    s.doc = patchAndTriangle();
    run(s, "join 0:v0 t0:e2 G1");
    ASSERT_EQ(s.doc.joins.size(), 1u);
    const Join j = s.doc.joins[0];
    EXPECT_EQ(j.edgeB, Edge::T2);
    EXPECT_TRUE(j.reversed);  // the triangle's edge runs from x = 1 to x = 0
    EXPECT_GT(j.alpha, 0.0);
    // One pool entry per seam point: the edges merged.
    for (int k = 0; k < 4; ++k) EXPECT_EQ(edgePoolOf(s.doc, 0, Edge::V0)[size_t(k)], edgePoolOf(s.doc, 0, Edge::T2)[size_t(3 - k)]);
    EXPECT_LE(seamAngle(s.doc, 0), 1e-6);  // one smooth surface: exactly G1 already
    expectHeld(s.doc, "joined");
    // The triangle's middle point, a patch point next to the seam and a seam point itself.
    const uint32_t middle = s.doc.triangles[0].idx[size_t(triSlot(1, 1, 1))];
    const uint32_t beside = s.doc.patches[0].idx[5], seam = s.doc.patches[0].idx[1];
    for (const auto& [pt, move] : {std::pair{middle, "0 0 0.15"}, {beside, "0.02 0.05 -0.1"}, {seam, "0 0 0.08"}}) {
        const Vec3 before = s.doc.points[pt];
        run(s, "select point " + std::to_string(pt));
        run(s, std::string("move ") + move);
        EXPECT_GT(glm::length(s.doc.points[pt] - before), 0.01) << "point " << pt << " moved";
        expectHeld(s.doc, "after moving point " + std::to_string(pt));
    }
    // Saved and reopened: the same join, still held.
    const Document back = parseDocument(serializeDocument(s.doc), "tri.patchwork");
    EXPECT_EQ(back.joins, s.doc.joins);
    EXPECT_NE(serializeDocument(s.doc).find("\"e2\""), std::string::npos);
}

TEST(TriangleJoins, TwoTrianglesJoinG1AndAKinkedSeamIsStraightened) {
    EditSession s;
    addTriangle(s.doc, Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0.4, -0.8, 0));
    addTriangle(s.doc, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.6, 0.9, 0));
    run(s, "join t0:e2 t1:e2 G1");
    ASSERT_EQ(s.doc.joins.size(), 1u);
    EXPECT_LE(seamAngle(s.doc, 0), 1e-6);
    run(s, "select point " + std::to_string(s.doc.triangles[1].idx[size_t(triSlot(1, 1, 1))]));
    run(s, "move 0 0 0.2");
    expectHeld(s.doc, "two triangles, after a drag");

    // A flat patch and a triangle bent 40° down from it along the seam: G1 straightens the seam.
    EditSession k;
    addPatch(k.doc, 0, 0);
    for (Vec3& p : k.doc.points) p.z = 0.0;
    addTriangle(k.doc, Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0.5, -0.8, 0));
    const double c = std::cos(0.7), sn = std::sin(0.7);
    for (uint32_t i : k.doc.triangles[0].idx) {
        Vec3& p = k.doc.points[i];
        p = Vec3(p.x, p.y * c, p.y * sn);  // rotated about the x axis, the seam (y = 0) fixed
    }
    run(k, "join 0:v0 t0:e2 C0");
    EXPECT_NEAR(seamAngle(k.doc, 0), 40.1, 0.1);  // 0.7 rad
    // Made G1 in place (the Continuity panel's combo runs the same command): straightened.
    run(k, "join t0:e2 0:v0 G1");
    ASSERT_EQ(k.doc.joins.size(), 1u);
    EXPECT_EQ(k.doc.joins[0].continuity, Continuity::G1);
    expectHeld(k.doc, "kinked seam made G1");
    run(k, "select point " + std::to_string(k.doc.patches[0].idx[10]));
    run(k, "move 0 0 0.1");
    expectHeld(k.doc, "straightened seam, after a drag");
}

TEST(TriangleJoins, WhatCannotBeATriangleJoinIsRefusedAndTheDocumentKept) {
    EditSession s;
    s.doc = patchAndTriangle();
    const Document before = s.doc;
    EXPECT_NE(refusal(s, "join 0:v0 t0:e2 C1").find("C0 or G1"), std::string::npos);
    EXPECT_NE(refusal(s, "join 0:v0 t0:e2 G2").find("C0 or G1"), std::string::npos);
    EXPECT_NE(refusal(s, "join 0:v0 t3:e2 G1").find("triangle"), std::string::npos);
    EXPECT_NE(refusal(s, "join 0:v0 t0:u1 G1").find("e0, e1 or e2"), std::string::npos);
    EXPECT_NE(refusal(s, "join 0:e1 t0:e2 G1").find("u0, v0, u1 or v1"), std::string::npos);
    EXPECT_EQ(s.doc, before);
    // The file reader refuses a triangle join that is not C0/G1 and a triangle index out of range.
    run(s, "join 0:v0 t0:e2 G1");
    std::string text = serializeDocument(s.doc);
    const size_t at = text.find("\"continuity\":\"G1\"");
    ASSERT_NE(at, std::string::npos);
    std::string c1 = text;
    c1.replace(at, 17, "\"continuity\":\"C1\"");
    try {
        parseDocument(c1, "bad.patchwork");
        ADD_FAILURE() << "a C1 triangle join was read";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("C0 or G1"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("bad.patchwork"), std::string::npos) << e.what();
    }
    std::string far = text;
    const size_t b = far.find("\"b\":0");
    ASSERT_NE(b, std::string::npos);
    far.replace(b, 5, "\"b\":4");
    try {
        parseDocument(far, "far.patchwork");
        ADD_FAILURE() << "a join to a missing triangle was read";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("triangle index"), std::string::npos) << e.what();
    }
}

TEST(TriangleJoins, SplitsDeletionsAndUnjoinKeepTheJoinRight) {
    EditSession s;
    addPatch(s.doc, -1, 0);  // patch 0, beside: deleting it renumbers the patch the triangle is joined to
    addPatch(s.doc, 0, 0);
    addTriangle(s.doc, Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0.4, -0.8, 0));
    run(s, "join 1:v0 t0:e2 G1");
    // A split across the joined edge would need the triangle split too: refused, naming it.
    const std::string across = refusal(s, "split-ring 1 u 0.5");
    EXPECT_NE(across.find("joined to triangle 0"), std::string::npos) << across;
    // A split along it keeps the join on the half that has the edge, measured again, still G1.
    run(s, "split-ring 1 v 0.4");
    ASSERT_EQ(s.doc.patches.size(), 3u);
    const int j = findJoin(s.doc, 0, Edge::T2);
    ASSERT_GE(j, 0);
    EXPECT_EQ(s.doc.joins[size_t(j)].patchA, 1u);
    EXPECT_LE(seamAngle(s.doc, size_t(j)), 1e-6);
    expectHeld(s.doc, "after the split");
    // Deleting patch 0 renumbers the patch side, never the triangle side.
    run(s, "select patch 0");
    run(s, "delete");
    const int after = findJoin(s.doc, 0, Edge::T2);
    ASSERT_GE(after, 0);
    EXPECT_EQ(s.doc.joins[size_t(after)].patchA, 0u);
    expectHeld(s.doc, "after deleting another patch");
    // Unjoin: the triangle gets its own edge points and can move away.
    const size_t points = s.doc.points.size();
    run(s, "unjoin t0:e2");
    EXPECT_TRUE(std::none_of(s.doc.joins.begin(), s.doc.joins.end(), [](const Join& jn) { return joinHasTriangle(jn); }));
    EXPECT_EQ(s.doc.points.size(), points + 4);
    // Joined again, then the triangle deleted: its join goes with it, the patches' stay.
    run(s, "join 0:v0 t0:e2 C0");
    run(s, "select triangle 0");
    run(s, "delete");
    EXPECT_TRUE(s.doc.triangles.empty());
    EXPECT_TRUE(std::none_of(s.doc.joins.begin(), s.doc.joins.end(), [](const Join& jn) { return joinHasTriangle(jn); }));
}

TEST(TriangleJoins, FillHoleWithATriangleIsG1ToItsThreeSidesAndHeldLive) {
    // Three patches round the pole of the unit sphere leave a triangular hole there.
    EditSession s;
    s.doc = test::poleRing();
    Document& d = s.doc;
    run(s, "fill-hole 0:v0 1:v0 2:v0 triangle");
    ASSERT_EQ(d.triangles.size(), 1u);
    ASSERT_EQ(d.joins.size(), 6u);
    for (size_t j = 3; j < 6; ++j) EXPECT_EQ(d.joins[j].continuity, Continuity::G1);
    expectHeld(d, "filled");
    // The triangle shares the ring's points: its only own point is the middle one.
    EXPECT_EQ(d.points.size(), 37u);
    // The fill follows drags of its middle point and of the ring, and undo takes it away again.
    for (const auto& [pt, move] :
         {std::pair{d.triangles[0].idx[size_t(triSlot(1, 1, 1))], "0 0 0.05"}, {d.patches[1].idx[5], "0.03 0 0.04"}}) {
        run(s, "select point " + std::to_string(pt));
        run(s, std::string("move ") + move);
        expectHeld(d, "after moving point " + std::to_string(pt));
    }
    // Its sides must be single edges: two end to end cannot be one cubic.
    EXPECT_NE(refusal(s, "fill-hole 0:v1 1:v1+2:v1 0:u0 triangle").find("one patch edge"), std::string::npos);
}

TEST(TriangleJoins, ATriangleFillsThroughCurvesToo) {
    // Three curves of one segment round a loop: one triangle through them, its edges their points.
    EditSession s;
    Document& d = s.doc;
    const Vec3 corner[3] = {Vec3(0, 0, 0), Vec3(2, 0, 0.3), Vec3(0.8, 1.6, 0.1)};
    for (int k = 0; k < 3; ++k) d.points.push_back(corner[k]);
    for (uint32_t k = 0; k < 3; ++k) {
        const Vec3 a = corner[k], b = corner[(k + 1) % 3], bulge(0, 0, 0.25);
        const uint32_t first = uint32_t(d.points.size());
        d.points.push_back(a + (b - a) / 3.0 + bulge);
        d.points.push_back(a + 2.0 * (b - a) / 3.0 + bulge);
        d.curves.push_back(BezierCurve{{k, first, first + 1, (k + 1) % 3}, "", false});
    }
    Recorder host;
    makeCommandTable().run(s, host, "fill-hole c0 c1 c2 triangle");
    ASSERT_EQ(d.triangles.size(), 1u);
    EXPECT_TRUE(d.joins.empty());
    EXPECT_NE(host.last.find("3 curves"), std::string::npos) << host.last;
    for (int e = 0; e < 3; ++e) {  // each triangle edge is one of the curves, point for point
        const std::vector<uint32_t> edge = edgePoolOf(d, 0, triangleEdge(e));
        const bool found = std::any_of(d.curves.begin(), d.curves.end(), [&](const BezierCurve& c) {
            return std::equal(edge.begin(), edge.end(), c.idx.begin()) || std::equal(edge.rbegin(), edge.rend(), c.idx.begin());
        });
        EXPECT_TRUE(found) << "edge " << e;
    }
    // (Without `triangle` curves fill with patches: tests/test_corners_fills.cpp.) A side of two
    // segments is no triangle's side.
    run(s, "curve-insert c0 0.5");
    EXPECT_NE(refusal(s, "fill-hole c0 c1 c2 triangle").find("has 2 segments"), std::string::npos);

    // Two patch edges and a curve (made on the third patch's edge, sharing its points): G1 to the
    // two patches only.
    EditSession r;
    r.doc = test::poleRing();
    run(r, "select patch 2");
    run(r, "curve-from-edge v0");
    Recorder said;
    makeCommandTable().run(r, said, "fill-hole 0:v0 1:v0 c0 triangle");
    ASSERT_EQ(r.doc.triangles.size(), 1u);
    EXPECT_EQ(r.doc.joins.size(), 5u);
    EXPECT_NE(said.last.find("G1 to its 2 patch edges, through the points of its 1 curve"), std::string::npos) << said.last;
    expectHeld(r.doc, "filled with a curve side");
}

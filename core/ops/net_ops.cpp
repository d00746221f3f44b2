#include "core/ops/net_ops.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "core/base/limits.hpp"
#include "core/model/basis.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/trim/trim_edits.hpp"

namespace pw {
inline namespace ops {

namespace {

// Inserting or deleting rows and columns, closing or converting a net changes its domain, which
// its trim loops live in: refused while it has any.
void refuseTrimmedNet(const Document& doc, uint32_t s, const char* what) {
    if (s < doc.surfaces.size() && !doc.surfaces[s].trims.empty())
        throw EditError("net " + std::to_string(s) + " is trimmed: " + what + " would move its trims; `untrim n" + std::to_string(s) +
                        "` first");
}

Surface& netAt(Document& doc, uint32_t s) {
    if (s >= doc.surfaces.size()) throw EditError("no net surface " + std::to_string(s));
    return doc.surfaces[s];
}

uint32_t appendPoint(Document& doc, const Vec3& p) {
    if (doc.points.size() >= limits::kMaxPoints) throw EditError("the point pool is full");
    doc.points.push_back(p);
    return uint32_t(doc.points.size() - 1);
}

// Operations that make new points as combinations of a net's points (inserting rows, converting to
// patches and back) are polynomial: they refuse points with weights rather than change the surface.
template <class Indices>
void refuseWeights(const Document& doc, const Indices& idx, const char* what) {
    for (uint32_t i : idx)
        if (pointWeight(doc, i) != 1.0)
            throw EditError(std::string(what) + " is not defined for points with weights yet (point " + std::to_string(i) + " weighs " +
                            std::to_string(pointWeight(doc, i)) + ")");
}

// Bézier nets tile exactly with 3k + 1 open or 3k closed rows; a closed direction needs 2 windows.
void checkBezierSide(uint32_t n, bool closed, const char* what) {
    if (closed && (n % 3 != 0 || n < 6))
        throw EditError(std::string("a closed Bézier net needs a multiple of 3 ") + what + " (at least 6); it has " + std::to_string(n));
}

void checkWindowLimit(const Surface& s) {
    const uint32_t step = netStep(s.basis);
    const uint64_t w = netWindowCount(s.rows, s.closedV, step) * netWindowCount(s.cols, s.closedU, step);
    if (w > limits::kMaxPatches) throw EditError("the net would have more than " + std::to_string(limits::kMaxPatches) + " windows");
}

// Rows of the 4x4 conversion from a window's control points to the Bézier points of the same
// cubic: b0 = p(0), b1 = p(0) + p'(0)/3, b2 = p(1) - p'(1)/3, b3 = p(1).
std::array<std::array<double, 4>, 4> toBezierRows(Basis basis, double tension) {
    const BasisWeights w0 = basisWeights(basis, tension, 0.0), w1 = basisWeights(basis, tension, 1.0);
    std::array<std::array<double, 4>, 4> a{};
    for (int k = 0; k < 4; ++k) {
        a[0][k] = w0.w[k];
        a[1][k] = w0.w[k] + w0.dw[k] / 3.0;
        a[2][k] = w1.w[k] - w1.dw[k] / 3.0;
        a[3][k] = w1.w[k];
    }
    return a;
}

// The inverse along one curve: Bézier points b (3n + 1 open, 3n closed) of a C2 cubic spline to
// its uniform B-spline control points (n + 3 open, n closed). Segment i has
// b(3i+1) = (2 d(i+1) + d(i+2)) / 3 and b(3i+2) = (d(i+1) + 2 d(i+2)) / 3, so
// d(i+1) = 2 b(3i+1) - b(3i+2); the open ends follow from b(0) = (d0 + 4 d1 + d2) / 6.
std::vector<Vec3> bezierToDeBoor(const std::vector<Vec3>& b, bool closed) {
    if (closed) {
        const size_t n = b.size() / 3;
        std::vector<Vec3> d(n);
        for (size_t i = 0; i < n; ++i) d[(i + 1) % n] = 2.0 * b[3 * i + 1] - b[3 * i + 2];
        return d;
    }
    const size_t n = (b.size() - 1) / 3;
    std::vector<Vec3> d(n + 3);
    for (size_t i = 0; i < n; ++i) d[i + 1] = 2.0 * b[3 * i + 1] - b[3 * i + 2];
    d[n + 1] = 2.0 * b[3 * n - 1] - b[3 * n - 2];
    d[0] = 6.0 * b[0] - 4.0 * d[1] - d[2];
    d[n + 2] = 6.0 * b[3 * n] - 4.0 * d[n + 1] - d[n];
    return d;
}

using EdgeKey = std::array<uint32_t, 4>;
EdgeKey slots(const Patch& p, int a, int b, int c, int d) {
    return {p.idx[size_t(a)], p.idx[size_t(b)], p.idx[size_t(c)], p.idx[size_t(d)]};
}
EdgeKey col0(const Patch& p) { return slots(p, 0, 4, 8, 12); }
EdgeKey col3(const Patch& p) { return slots(p, 3, 7, 11, 15); }
EdgeKey row0(const Patch& p) { return slots(p, 0, 1, 2, 3); }
EdgeKey row3(const Patch& p) { return slots(p, 12, 13, 14, 15); }

}  // namespace

uint32_t addNetSurface(Document& doc, uint32_t rows, uint32_t cols, NetShape shape, Basis basis, const Vec3& center, double size,
                       bool zUp) {
    if (rows < 4 || cols < 4) throw EditError("a net needs at least 4 rows and 4 columns");
    if (rows > limits::kMaxNetSide || cols > limits::kMaxNetSide)
        throw EditError("a net has at most " + std::to_string(limits::kMaxNetSide) + " rows and columns");
    if (!(size > 0.0) || !std::isfinite(size)) throw EditError("the net size must be a positive number");
    Surface s;
    s.rows = rows;
    s.cols = cols;
    s.basis = basis;
    s.closedU = shape != NetShape::Flat;
    s.closedV = shape == NetShape::Torus;
    s.name = shape == NetShape::Flat ? "net" : shape == NetShape::Tube ? "tube" : "torus";
    if (basis == Basis::Bezier) {
        checkBezierSide(cols, s.closedU, "columns");
        checkBezierSide(rows, s.closedV, "rows");
        if (!s.closedU && (cols - 1) % 3 != 0) throw EditError("an open Bézier net needs 3k + 1 columns");
        if (!s.closedV && (rows - 1) % 3 != 0) throw EditError("an open Bézier net needs 3k + 1 rows");
    }
    checkWindowLimit(s);
    if (doc.points.size() + size_t(rows) * cols > limits::kMaxPoints) throw EditError("the point pool is full");
    // Ground-plane axes a, b and the up axis, so that the normal (du x dv) points up or outward.
    const Vec3 up = zUp ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    const Vec3 a(1, 0, 0);
    const Vec3 b = zUp ? Vec3(0, 1, 0) : Vec3(0, 0, -1);
    constexpr double kTau = 2.0 * std::numbers::pi;
    s.idx.resize(size_t(rows) * cols);
    for (uint32_t i = 0; i < rows; ++i)
        for (uint32_t j = 0; j < cols; ++j) {
            Vec3 p;
            if (shape == NetShape::Flat) {
                p = center + size * ((double(j) / (cols - 1) - 0.5) * a + (double(i) / (rows - 1) - 0.5) * b);
            } else if (shape == NetShape::Tube) {
                const double th = kTau * j / cols;
                const Vec3 radial = std::cos(th) * a + std::sin(th) * b;
                p = center + 0.35 * size * radial + size * (double(i) / (rows - 1) - 0.5) * up;
            } else {
                const double th = kTau * j / cols, ph = kTau * i / rows;
                const Vec3 radial = std::cos(th) * a + std::sin(th) * b;
                p = center + (0.35 * size + 0.15 * size * std::cos(ph)) * radial + 0.15 * size * std::sin(ph) * up;
            }
            s.idx[size_t(i) * cols + j] = appendPoint(doc, p);
        }
    doc.surfaces.push_back(std::move(s));
    return uint32_t(doc.surfaces.size() - 1);
}

void deleteNetSurface(Document& doc, uint32_t s) {
    netAt(doc, s);
    dropSurfaceFromTrims(doc, SurfaceRef{true, s});
    doc.surfaces.erase(doc.surfaces.begin() + s);
    compactPool(doc);
}

void insertNetRow(Document& doc, uint32_t si, uint32_t at) {
    refuseTrimmedNet(doc, si, "inserting a row");
    Surface s = netAt(doc, si);
    refuseWeights(doc, s.idx, "inserting a row or column");
    if (at > s.rows) throw EditError("row " + std::to_string(at) + " is outside the net (0.." + std::to_string(s.rows) + ")");
    if (s.rows + 1 > limits::kMaxNetSide) throw EditError("a net has at most " + std::to_string(limits::kMaxNetSide) + " rows");
    ++s.rows;
    checkWindowLimit(s);
    const uint32_t oldRows = s.rows - 1;
    std::vector<uint32_t> idx;
    idx.reserve(size_t(s.rows) * s.cols);
    auto old = [&](uint32_t r, uint32_t c) { return doc.points[s.idx[size_t(r) * s.cols + c]]; };
    std::vector<uint32_t> fresh(s.cols);
    for (uint32_t c = 0; c < s.cols; ++c) {
        Vec3 p;
        if (s.closedV || (at > 0 && at < oldRows))
            p = 0.5 * (old((at + oldRows - 1) % oldRows, c) + old(at % oldRows, c));
        else if (at == 0)
            p = 2.0 * old(0, c) - old(1, c);
        else
            p = 2.0 * old(oldRows - 1, c) - old(oldRows - 2, c);
        fresh[c] = appendPoint(doc, p);
    }
    for (uint32_t r = 0; r <= oldRows; ++r) {
        if (r == at) idx.insert(idx.end(), fresh.begin(), fresh.end());
        if (r < oldRows) idx.insert(idx.end(), s.idx.begin() + long(r) * s.cols, s.idx.begin() + long(r + 1) * s.cols);
    }
    s.idx = std::move(idx);
    doc.surfaces[si] = std::move(s);
}

namespace {
// Columns become rows and back, so column operations reuse the row operations.
void transposeNet(Surface& s) {
    std::vector<uint32_t> t(s.idx.size());
    for (uint32_t r = 0; r < s.rows; ++r)
        for (uint32_t c = 0; c < s.cols; ++c) t[size_t(c) * s.rows + r] = s.idx[size_t(r) * s.cols + c];
    s.idx = std::move(t);
    std::swap(s.rows, s.cols);
    std::swap(s.closedU, s.closedV);
}
}  // namespace

void insertNetColumn(Document& doc, uint32_t si, uint32_t at) {
    refuseTrimmedNet(doc, si, "inserting a column");
    Document d = doc;
    transposeNet(netAt(d, si));
    insertNetRow(d, si, at);
    transposeNet(d.surfaces[si]);
    doc = std::move(d);
}

void deleteNetRow(Document& doc, uint32_t si, uint32_t row) {
    refuseTrimmedNet(doc, si, "deleting a row");
    Surface& s = netAt(doc, si);
    if (row >= s.rows) throw EditError("row " + std::to_string(row) + " is outside the net");
    if (s.rows <= 4) throw EditError("a net keeps at least 4 rows");
    if (s.basis == Basis::Bezier && s.closedV) checkBezierSide(s.rows - 1, true, "rows");
    s.idx.erase(s.idx.begin() + long(row) * s.cols, s.idx.begin() + long(row + 1) * s.cols);
    --s.rows;
    compactPool(doc);
}

void deleteNetColumn(Document& doc, uint32_t si, uint32_t col) {
    refuseTrimmedNet(doc, si, "deleting a column");
    Document d = doc;
    transposeNet(netAt(d, si));
    try {
        deleteNetRow(d, si, col);
    } catch (const EditError& e) {  // the same checks, told in columns
        std::string m = e.what();
        for (size_t p = m.find("row"); p != std::string::npos; p = m.find("row", p + 6)) m.replace(p, 3, "column");
        throw EditError(m);
    }
    transposeNet(d.surfaces[si]);
    doc = std::move(d);
}

void setNetClosed(Document& doc, uint32_t si, bool alongU, bool closed) {
    refuseTrimmedNet(doc, si, "opening or closing it");
    Surface s = netAt(doc, si);
    (alongU ? s.closedU : s.closedV) = closed;
    if (s.basis == Basis::Bezier && closed) checkBezierSide(alongU ? s.cols : s.rows, true, alongU ? "columns" : "rows");
    checkWindowLimit(s);
    doc.surfaces[si] = std::move(s);
}

void setNetBasis(Document& doc, uint32_t si, Basis basis, double tension) {
    Surface s = netAt(doc, si);
    if (!std::isfinite(tension) || std::abs(tension) > 1e3) throw EditError("the Catmull-Rom tension must be a number in [-1000, 1000]");
    s.basis = basis;
    s.tension = tension;
    if (basis == Basis::Bezier) {
        if (s.closedU) checkBezierSide(s.cols, true, "columns");
        if (s.closedV) checkBezierSide(s.rows, true, "rows");
    }
    checkWindowLimit(s);
    doc.surfaces[si] = std::move(s);
}

std::optional<std::string> netLayoutProblem(const Surface& s) {
    if (s.basis != Basis::Bezier) return std::nullopt;
    std::string out;
    auto side = [&](uint32_t n, bool closed, const char* what) {
        if (closed && n % 3 != 0) out += std::string("a closed Bézier net needs a multiple of 3 ") + what + "; ";
        if (!closed && n >= 4 && (n - 1) % 3 != 0)
            out += std::to_string((n - 1) % 3) + " " + what + " at the end are unused (a Bézier net needs 3k + 1); ";
    };
    side(s.cols, s.closedU, "columns");
    side(s.rows, s.closedV, "rows");
    if (out.empty()) return std::nullopt;
    out.resize(out.size() - 2);
    return out;
}

BezierGrid netToBezierGrid(const Document& doc, const Surface& s) {
    const uint32_t step = netStep(s.basis);
    const uint32_t wu = uint32_t(netWindowCount(s.cols, s.closedU, step)), wv = uint32_t(netWindowCount(s.rows, s.closedV, step));
    BezierGrid g;
    g.closedU = s.closedU;
    g.closedV = s.closedV;
    if (wu == 0 || wv == 0) return g;
    g.cols = s.closedU ? 3 * wu : 3 * wu + 1;
    g.rows = s.closedV ? 3 * wv : 3 * wv + 1;
    g.points.assign(size_t(g.rows) * g.cols, Vec3(0.0));
    std::vector<char> done(g.points.size(), 0);
    const auto A = toBezierRows(s.basis, s.tension);
    for (uint32_t wr = 0; wr < wv; ++wr)
        for (uint32_t wc = 0; wc < wu; ++wc) {
            Vec3 G[4][4];
            for (uint32_t k = 0; k < 4; ++k)
                for (uint32_t l = 0; l < 4; ++l)
                    G[k][l] = doc.points[s.idx[size_t((wr * step + k) % s.rows) * s.cols + (wc * step + l) % s.cols]];
            // Along u (columns) first, then along v (rows).
            Vec3 H[4][4];
            for (int k = 0; k < 4; ++k)
                for (int j = 0; j < 4; ++j) {
                    Vec3 acc(0.0);
                    for (int l = 0; l < 4; ++l) acc += A[j][l] * G[k][l];
                    H[k][j] = acc;
                }
            for (uint32_t i = 0; i < 4; ++i)
                for (uint32_t j = 0; j < 4; ++j) {
                    const size_t at = size_t((3 * wr + i) % g.rows) * g.cols + (3 * wc + j) % g.cols;
                    if (done[at]) continue;  // shared with the previous window: computed once
                    Vec3 acc(0.0);
                    for (int k = 0; k < 4; ++k) acc += A[i][k] * H[k][j];
                    g.points[at] = acc;
                    done[at] = 1;
                }
        }
    return g;
}

std::vector<uint32_t> convertNetToPatches(Document& doc, uint32_t si) {
    refuseTrimmedNet(doc, si, "converting it to patches");
    Document d = doc;
    const Surface s = netAt(d, si);
    refuseWeights(d, s.idx, "converting a net to patches");
    const BezierGrid g = netToBezierGrid(d, s);
    if (g.points.empty()) throw EditError("the net has no whole window to convert");
    const uint32_t wu = s.closedU ? g.cols / 3 : (g.cols - 1) / 3, wv = s.closedV ? g.rows / 3 : (g.rows - 1) / 3;
    if (d.patches.size() + size_t(wu) * wv > limits::kMaxPatches) throw EditError("too many patches");
    std::vector<uint32_t> ids(g.points.size());
    for (size_t k = 0; k < g.points.size(); ++k) ids[k] = appendPoint(d, g.points[k]);
    const uint32_t first = uint32_t(d.patches.size());
    std::vector<uint32_t> created;
    for (uint32_t wr = 0; wr < wv; ++wr)
        for (uint32_t wc = 0; wc < wu; ++wc) {
            Patch p;
            for (uint32_t i = 0; i < 4; ++i)
                for (uint32_t j = 0; j < 4; ++j) p.idx[i * 4 + j] = ids[size_t((3 * wr + i) % g.rows) * g.cols + (3 * wc + j) % g.cols];
            p.name = (s.name.empty() ? std::string("net") : s.name) + " " + std::to_string(wr) + "," + std::to_string(wc);
            created.push_back(uint32_t(d.patches.size()));
            d.patches.push_back(std::move(p));
        }
    const Continuity c = s.basis != Basis::Bezier || s.keepC1 ? Continuity::C1 : Continuity::C0;
    auto at = [&](uint32_t wr, uint32_t wc) { return first + wr * wu + wc; };
    for (uint32_t wr = 0; wr < wv; ++wr)
        for (uint32_t wc = 0; wc < wu; ++wc) {
            if (wc + 1 < wu || (s.closedU && wu > 1))
                d.joins.push_back(Join{at(wr, wc), Edge::U1, at(wr, (wc + 1) % wu), Edge::U0, false, c, 1.0});
            if (wr + 1 < wv || (s.closedV && wv > 1))
                d.joins.push_back(Join{at(wr, wc), Edge::V1, at((wr + 1) % wv, wc), Edge::V0, false, c, 1.0});
        }
    d.surfaces.erase(d.surfaces.begin() + si);
    compactPool(d);
    doc = std::move(d);
    return created;
}

namespace {

// Bézier patches laid out as a regular grid (neighbours share whole edges, u next to u, v next to
// v; a direction may wrap): the pool indices of the Bézier grid they share, rows x cols, row-major.
struct PatchGrid {
    std::vector<uint32_t> patches;  // sorted
    uint32_t rows = 0, cols = 0;    // of the Bézier grid (3 a patch, +1 on open sides)
    bool closedU = false, closedV = false;
    std::vector<uint32_t> idx;
};

PatchGrid patchGrid(const Document& doc, std::vector<uint32_t> patches, const char* what) {
    if (patches.empty())
        for (uint32_t p = 0; p < doc.patches.size(); ++p) patches.push_back(p);
    std::sort(patches.begin(), patches.end());
    patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
    if (patches.empty()) throw EditError("there are no patches to convert");
    for (uint32_t p : patches) {
        if (p >= doc.patches.size()) throw EditError("no patch " + std::to_string(p));
        refuseWeights(doc, doc.patches[p].idx, what);
        if (doc.patches[p].basis != Basis::Bezier) throw EditError("patch " + std::to_string(p) + " is not a Bézier patch");
    }
    // Neighbours through whole shared edges, same orientation.
    std::map<EdgeKey, uint32_t> byCol0, byCol3, byRow0, byRow3;
    for (uint32_t p : patches) {
        const Patch& P = doc.patches[p];
        if (!byCol0.emplace(col0(P), p).second || !byCol3.emplace(col3(P), p).second || !byRow0.emplace(row0(P), p).second ||
            !byRow3.emplace(row3(P), p).second)
            throw EditError("the patches do not form a regular grid: three or more patches meet at one edge");
    }
    auto find = [](const std::map<EdgeKey, uint32_t>& m, const EdgeKey& k) -> int {
        auto it = m.find(k);
        return it == m.end() ? -1 : int(it->second);
    };
    auto right = [&](uint32_t p) { return find(byCol0, col3(doc.patches[p])); };
    auto up = [&](uint32_t p) { return find(byRow0, row3(doc.patches[p])); };
    bool closedU = true, closedV = true;
    for (uint32_t p : patches) {
        closedU = closedU && find(byCol3, col0(doc.patches[p])) >= 0;
        closedV = closedV && find(byRow3, row0(doc.patches[p])) >= 0;
    }
    int origin = -1;
    for (uint32_t p : patches)
        if ((closedU || find(byCol3, col0(doc.patches[p])) < 0) && (closedV || find(byRow3, row0(doc.patches[p])) < 0)) {
            origin = int(p);
            break;
        }
    const std::string notGrid = "the patches do not form a regular grid (neighbours must share whole edges, u next to u, v next to v)";
    if (origin < 0) throw EditError(notGrid);
    auto walk = [&](uint32_t start, auto next, bool closed) {
        std::vector<uint32_t> line{start};
        for (int n = next(start); n >= 0; n = next(uint32_t(n))) {
            if (uint32_t(n) == start) {
                if (!closed) throw EditError(notGrid);
                return line;
            }
            if (std::find(line.begin(), line.end(), uint32_t(n)) != line.end() || line.size() > patches.size()) throw EditError(notGrid);
            line.push_back(uint32_t(n));
        }
        if (closed) throw EditError(notGrid);
        return line;
    };
    const std::vector<uint32_t> row = walk(uint32_t(origin), right, closedU);
    std::vector<std::vector<uint32_t>> columns;
    for (uint32_t p : row) columns.push_back(walk(p, up, closedV));
    const uint32_t C = uint32_t(row.size()), R = uint32_t(columns.front().size());
    for (const auto& col : columns)
        if (col.size() != R) throw EditError(notGrid);
    if (size_t(R) * C != patches.size())
        throw EditError(notGrid + ": " + std::to_string(patches.size() - size_t(R) * C) + " patch(es) left over");
    for (uint32_t r = 0; r < R; ++r)
        for (uint32_t c = 0; c + 1 < C || (closedU && c < C); ++c)
            if (right(columns[c][r]) != int(columns[(c + 1) % C][r])) throw EditError(notGrid);
    PatchGrid g;
    g.patches = patches;
    g.closedU = closedU;
    g.closedV = closedV;
    g.cols = closedU ? 3 * C : 3 * C + 1;
    g.rows = closedV ? 3 * R : 3 * R + 1;
    g.idx.resize(size_t(g.rows) * g.cols);
    for (uint32_t y = 0; y < g.rows; ++y)
        for (uint32_t x = 0; x < g.cols; ++x) {
            const uint32_t pr = std::min(y / 3, R - 1), pc = std::min(x / 3, C - 1);
            g.idx[size_t(y) * g.cols + x] = doc.patches[columns[pc][pr]].idx[(y - 3 * pr) * 4 + (x - 3 * pc)];
        }
    return g;
}

// Replaces the grid's patches by net `s` (made of existing or new points): one undoable whole.
uint32_t replaceByNet(Document& doc, const PatchGrid& g, Surface s, bool keepPatches) {
    if (keepPatches) {  // the caller removes them (many grids at once: one pool compaction)
        doc.surfaces.push_back(std::move(s));
        return uint32_t(doc.surfaces.size() - 1);
    }
    Document d = doc;
    d.surfaces.push_back(std::move(s));
    for (auto it = g.patches.rbegin(); it != g.patches.rend(); ++it) deletePatch(d, *it);
    doc = std::move(d);
    return uint32_t(doc.surfaces.size() - 1);
}

}  // namespace

uint32_t convertPatchesToNet(Document& doc, std::vector<uint32_t> patches, double tolerance, bool keepPatches) {
    const PatchGrid g = patchGrid(doc, std::move(patches), "converting patches to a net");
    const bool closedU = g.closedU, closedV = g.closedV;
    const uint32_t gc = g.cols, gr = g.rows;
    const uint32_t C = closedU ? gc / 3 : (gc - 1) / 3, R = closedV ? gr / 3 : (gr - 1) / 3;
    if ((closedU && C < 4) || (closedV && R < 4))
        throw EditError("a closed B-spline net needs at least 4 patches around each closed direction");
    // The de Boor points along u and along v of the Bézier grid.
    std::vector<Vec3> bez(g.idx.size());
    for (size_t k = 0; k < bez.size(); ++k) bez[k] = doc.points[g.idx[k]];
    const uint32_t nc = closedU ? C : C + 3, nr = closedV ? R : R + 3;
    std::vector<Vec3> half(size_t(gr) * nc), net(size_t(nr) * nc);
    for (uint32_t y = 0; y < gr; ++y) {
        const std::vector<Vec3> d = bezierToDeBoor(std::vector<Vec3>(bez.begin() + long(y) * gc, bez.begin() + long(y + 1) * gc), closedU);
        std::copy(d.begin(), d.end(), half.begin() + long(y) * nc);
    }
    for (uint32_t x = 0; x < nc; ++x) {
        std::vector<Vec3> column(gr);
        for (uint32_t y = 0; y < gr; ++y) column[y] = half[size_t(y) * nc + x];
        const std::vector<Vec3> d = bezierToDeBoor(column, closedV);
        for (uint32_t y = 0; y < nr; ++y) net[size_t(y) * nc + x] = d[y];
    }

    // Exact only for a C2 grid: convert back and compare.
    Document probe;
    probe.points = net;
    Surface s;
    s.rows = nr;
    s.cols = nc;
    s.basis = Basis::BSpline;
    s.closedU = closedU;
    s.closedV = closedV;
    s.name = "net";
    s.idx.resize(net.size());
    for (size_t k = 0; k < net.size(); ++k) s.idx[k] = uint32_t(k);
    const BezierGrid back = netToBezierGrid(probe, s);
    double worst = 0.0;
    for (size_t k = 0; k < bez.size(); ++k) worst = std::max(worst, glm::length(back.points[k] - bez[k]));
    const double size = modelSize(doc);
    if (!(worst <= tolerance * size)) {
        char msg[200];
        std::snprintf(msg, sizeof msg,
                      "the patches are not C2 across their seams (control points off by up to %.3g × the model size); "
                      "only a C2 grid converts to a B-spline net exactly",
                      worst / size);
        throw EditError(msg);
    }

    // Refused before any point is added, so that a full pool leaves the document as it was.
    if (doc.points.size() + net.size() > limits::kMaxPoints) throw EditError("the point pool is full");
    for (size_t k = 0; k < net.size(); ++k) s.idx[k] = appendPoint(doc, net[k]);
    return replaceByNet(doc, g, std::move(s), keepPatches);
}

uint32_t convertPatchesToBezierNet(Document& doc, std::vector<uint32_t> patches, double tolerance, bool keepPatches, bool keepC1) {
    const PatchGrid g = patchGrid(doc, std::move(patches), "converting patches to a net");
    if ((g.closedU && g.cols < 6) || (g.closedV && g.rows < 6))
        throw EditError("a closed Bézier net needs at least 2 patches around each closed direction");
    // C1 across every seam: each seam point the midpoint of its neighbours across it.
    const double tol = tolerance * modelSize(doc);
    auto at = [&](uint32_t y, uint32_t x) { return doc.points[g.idx[size_t(y % g.rows) * g.cols + x % g.cols]]; };
    double worst = 0.0;
    for (uint32_t y = 0; y < g.rows; ++y)
        for (uint32_t x = 3; x < g.cols || (g.closedU && x == g.cols); x += 3)
            if (x + 1 < g.cols || g.closedU) worst = std::max(worst, glm::length(at(y, x) - 0.5 * (at(y, x - 1) + at(y, x + 1))));
    for (uint32_t x = 0; x < g.cols; ++x)
        for (uint32_t y = 3; y < g.rows || (g.closedV && y == g.rows); y += 3)
            if (y + 1 < g.rows || g.closedV) worst = std::max(worst, glm::length(at(y, x) - 0.5 * (at(y - 1, x) + at(y + 1, x))));
    if (keepC1 && !(worst <= tol)) {
        char msg[160];
        std::snprintf(msg, sizeof msg, "the patches are not C1 across their seams (off by up to %.3g × the model size)",
                      worst / std::max(modelSize(doc), 1e-300));
        throw EditError(msg);
    }
    Surface s;
    s.rows = g.rows;
    s.cols = g.cols;
    s.basis = Basis::Bezier;
    s.keepC1 = keepC1;
    s.closedU = g.closedU;
    s.closedV = g.closedV;
    s.name = "net";
    s.idx = g.idx;
    return replaceByNet(doc, g, std::move(s), keepPatches);
}

}  // namespace ops
}  // namespace pw

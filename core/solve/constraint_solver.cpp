// Projection of edited control points onto the join constraints (DESIGN §1): a weighted
// least-change KKT solve, d = W⁻¹Cᵀy with (C W⁻¹ Cᵀ + εI) y = r, factorised once per drag.
#include "core/solve/constraint_solver.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "core/model/topology.hpp"
#include "core/solve/ldlt_solve.hpp"
#include "core/solve/sheared_joins.hpp"
#include "core/solve/solver_constraints.hpp"
#include "core/solve/triangle_seams.hpp"

namespace pw {
inline namespace solve {

namespace solver_detail {

bool joinPoints(const Document& doc, const Join& join, JoinPoints& out) {
    if (joinHasTriangle(join)) return false;  // core/solve/triangle_seams.hpp
    if (join.patchA >= doc.patches.size() || join.patchB >= doc.patches.size()) return false;
    const Patch& A = doc.patches[join.patchA];
    const Patch& B = doc.patches[join.patchB];
    for (int k = 0; k < 4; ++k) {
        const int kb = join.reversed ? 3 - k : k;
        out.a0[k] = A.idx[edgeSlot(join.edgeA, k, 0)];
        out.a1[k] = A.idx[edgeSlot(join.edgeA, k, 1)];
        out.a2[k] = A.idx[edgeSlot(join.edgeA, k, 2)];
        out.b0[k] = B.idx[edgeSlot(join.edgeB, kb, 0)];
        out.b1[k] = B.idx[edgeSlot(join.edgeB, kb, 1)];
        out.b2[k] = B.idx[edgeSlot(join.edgeB, kb, 2)];
    }
    return true;
}

bool joinPointsInPool(const JoinPoints& jp, size_t n) {
    for (int k = 0; k < 4; ++k)
        if (jp.a0[k] >= n || jp.a1[k] >= n || jp.a2[k] >= n || jp.b0[k] >= n || jp.b1[k] >= n || jp.b2[k] >= n) return false;
    return true;
}

ConstraintRow makeRow(std::vector<std::pair<uint32_t, double>> terms, uint32_t join) {
    std::sort(terms.begin(), terms.end());
    ConstraintRow row;
    row.join = join;
    for (const auto& [idx, c] : terms) {
        if (!row.terms.empty() && row.terms.back().first == idx)
            row.terms.back().second += c;
        else
            row.terms.emplace_back(idx, c);
    }
    std::erase_if(row.terms, [](const auto& t) { return t.second == 0.0; });
    return row;
}

namespace {

bool collapsed(const uint32_t (&e)[4]) { return e[0] == e[1] && e[1] == e[2] && e[2] == e[3]; }

}  // namespace

void appendTangentRows(const Join& join, const JoinPoints& jp, uint32_t ji, std::vector<ConstraintRow>& rows) {
    const double alpha = join.alpha;
    if (!hasShear(join) && !join.fitted) {
        for (int k = 0; k < 4; ++k) {
            const bool aFlat = jp.a1[k] == jp.a0[k], bFlat = jp.b1[k] == jp.b0[k];
            if (aFlat != bFlat) continue;  // one side's tangent collapsed onto the boundary point
            ConstraintRow row = makeRow({{jp.b1[k], 1.0}, {jp.a0[k], -(1.0 + alpha)}, {jp.a1[k], alpha}}, ji);
            if (!row.terms.empty()) rows.push_back(std::move(row));
        }
        return;
    }
    // A sheared G1 join (core/solve/sheared_joins.hpp): the degree-4 identity's five coefficients
    // (a fitted join's four, or a part's three: those orthogonal to what it lets go).
    std::array<std::vector<std::pair<uint32_t, double>>, 5> coefficient;
    for (int l = 0; l <= 4; ++l) {
        std::vector<std::pair<uint32_t, double>>& terms = coefficient[size_t(l)];
        for (int k = 0; k < 4; ++k) {
            const double w = elevationWeight(l, k);
            const double a = alpha * alphaWeight(l, k, 0) + endAlpha(join) * alphaWeight(l, k, 1);  // α(t)·(A0 − A1)
            if (w == 0.0 && a == 0.0) continue;
            terms.insert(terms.end(), {{jp.b1[k], w}, {jp.a0[k], -w - a}, {jp.a1[k], a}});
        }
        for (int i = 0; i < 3; ++i) {
            const int j = l - i;
            if (j < 0 || j > 2 || join.shear[size_t(i)] == 0.0) continue;
            const double w = join.shear[size_t(i)] * shearWeight(i, j);
            terms.insert(terms.end(), {{jp.a0[j + 1], -w}, {jp.a0[j], w}});
        }
    }
    for (const std::array<double, 5>& held : heldCoefficients(join)) {
        std::vector<std::pair<uint32_t, double>> terms;
        for (size_t l = 0; l <= 4; ++l)
            if (held[l] != 0.0)
                for (const auto& [idx, c] : coefficient[l]) terms.emplace_back(idx, c * held[l]);
        ConstraintRow row = makeRow(std::move(terms), ji);
        if (!row.terms.empty()) rows.push_back(std::move(row));
    }
}

std::vector<ConstraintRow> buildConstraintRows(const Document& doc) {
    std::vector<ConstraintRow> rows;
    rows.reserve(doc.joins.size() * 4);
    const uint32_t n = static_cast<uint32_t>(doc.points.size());
    for (size_t j = 0; j < doc.joins.size(); ++j) {
        const Join& join = doc.joins[j];
        const uint32_t ji = static_cast<uint32_t>(j);
        if (joinHasTriangle(join)) {
            appendTriangleJoinRows(doc, join, ji, rows);
            continue;
        }
        JoinPoints jp;
        if (!joinPoints(doc, join, jp) || !joinPointsInPool(jp, n)) continue;
        // C0: the two sides' edge points coincide (nothing to do when they share the pool entry).
        for (int k = 0; k < 4; ++k)
            if (jp.a0[k] != jp.b0[k]) rows.push_back(makeRow({{jp.a0[k], 1.0}, {jp.b0[k], -1.0}}, ji));
        if (!holdsTangent(join.continuity)) continue;
        if (collapsed(jp.a0) || collapsed(jp.b0)) continue;  // a pole: no cross-boundary tangent
        appendTangentRows(join, jp, ji, rows);
        if (!holdsCurvature(join.continuity)) continue;
        // β-constraint on the second cross-boundary difference; B's edge point is A's (C0 row).
        const double a2 = join.alpha * join.alpha, h = 0.5 * join.beta2;
        for (int k = 0; k < 4; ++k) {
            const bool aFlat = jp.a1[k] == jp.a0[k] || jp.a2[k] == jp.a1[k];
            const bool bFlat = jp.b1[k] == jp.b0[k] || jp.b2[k] == jp.b1[k];
            if (aFlat || bFlat) continue;  // a degenerate row: the curvature condition says nothing there
            ConstraintRow row =
                makeRow({{jp.b2[k], 1.0}, {jp.b1[k], -2.0}, {jp.a0[k], 1.0 - a2 - h}, {jp.a1[k], 2.0 * a2 + h}, {jp.a2[k], -a2}}, ji);
            if (!row.terms.empty()) rows.push_back(std::move(row));
        }
    }
    // Bézier nets that keep C1: each seam point midway between its neighbours across the seam.
    for (const auto& [before, seam, after] : netC1Triples(doc)) {
        if (before >= n || seam >= n || after >= n) continue;
        ConstraintRow row = makeRow({{before, 1.0}, {seam, -2.0}, {after, 1.0}}, kNetSeamJoin);
        if (!row.terms.empty()) rows.push_back(std::move(row));
    }
    return rows;
}

std::vector<char> joinedBoundaryPoints(const Document& doc) {
    std::vector<char> flag(doc.points.size(), 0);
    for (const Join& join : doc.joins) {
        if (joinHasTriangle(join)) {
            for (const bool sideB : {false, true})
                if (const auto side = seamSide(doc, join, sideB))
                    for (uint32_t i : side->edge) flag[i] = 1;
            continue;
        }
        JoinPoints jp;
        if (!joinPoints(doc, join, jp)) continue;
        for (int k = 0; k < 4; ++k) {
            if (jp.a0[k] < flag.size()) flag[jp.a0[k]] = 1;
            if (jp.b0[k] < flag.size()) flag[jp.b0[k]] = 1;
        }
    }
    for (const auto& t : netC1Triples(doc))
        if (t[1] < flag.size()) flag[t[1]] = 1;
    return flag;
}

}  // namespace solver_detail

using solver_detail::ConstraintRow;

namespace {

// Constraints that share no free point are independent: the solver splits them into connected
// components (on a patch grid each four-patch corner is one small component) and factorises each
// on its own, so a drag only pays for the components it disturbs.
struct Component {
    std::vector<uint32_t> rows;     // indices into Impl::rowStart
    std::vector<uint32_t> vars;     // free variables (indices into Impl::freePoints)
    Eigen::SparseMatrix<double> C;  // rows × vars, local numbering
    Eigen::LDLT<Eigen::MatrixXd> dense;
    std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> sparse;
};

struct UnionFind {
    std::vector<uint32_t> parent;
    explicit UnionFind(size_t n) : parent(n) {
        for (size_t i = 0; i < n; ++i) parent[i] = static_cast<uint32_t>(i);
    }
    uint32_t find(uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
};

// Local support (SolverOptions::localRings): every patch point farther than `rings` patches (through
// shared points and joins) from a patch holding a fixed point is frozen too. Points of no patch (nets, curves)
// stay free. With no fixed point on any patch nothing is frozen.
void freezeOutside(const Document& doc, std::vector<char>& fixed, int rings, const std::vector<uint32_t>& seeds) {
    const size_t n = fixed.size();
    std::vector<std::vector<uint32_t>> patchesOf(n);
    for (uint32_t p = 0; p < doc.patches.size(); ++p)
        for (uint32_t i : doc.patches[p].idx)
            if (i < n && (patchesOf[i].empty() || patchesOf[i].back() != p)) patchesOf[i].push_back(p);
    std::vector<char> inRegion(doc.patches.size(), 0);
    std::vector<uint32_t> frontier;
    const auto seed = [&](size_t i) {
        for (uint32_t p : patchesOf[i])
            if (!inRegion[p]) inRegion[p] = 1, frontier.push_back(p);
    };
    for (size_t i = 0; i < n; ++i)
        if (fixed[i]) seed(i);
    for (uint32_t i : seeds)
        if (i < n) seed(i);
    if (frontier.empty()) return;                                   // nothing fixed on a patch: the whole model takes part
    std::vector<std::vector<uint32_t>> joined(doc.patches.size());  // joins whose edges are stored twice share no point
    for (const Join& j : doc.joins)
        if (quadJoin(j) && j.patchA < joined.size() && j.patchB < joined.size())
            joined[j.patchA].push_back(j.patchB), joined[j.patchB].push_back(j.patchA);
    for (int r = 0; r < rings && !frontier.empty(); ++r) {
        std::vector<uint32_t> next;
        auto reach = [&](uint32_t q) {
            if (!inRegion[q]) inRegion[q] = 1, next.push_back(q);
        };
        for (uint32_t p : frontier) {
            for (uint32_t i : doc.patches[p].idx)
                if (i < n)
                    for (uint32_t q : patchesOf[i]) reach(q);
            for (uint32_t q : joined[p]) reach(q);
        }
        frontier = std::move(next);
    }
    for (size_t i = 0; i < n; ++i) {
        if (fixed[i] || patchesOf[i].empty()) continue;
        bool near = false;
        for (uint32_t p : patchesOf[i]) near = near || inRegion[p];
        if (!near) fixed[i] = 1;
    }
}

}  // namespace

struct DragSolver::Impl {
    size_t pointCount = 0;
    double tolerance = 0;          // residual to reach: 1e-13 × model size (well inside 1e-9)
    double conflictTolerance = 0;  // residual left after refinement that counts as a conflict: 1e-9 × size
    // Active constraints (at least one free point) in compressed rows over pool indices.
    std::vector<uint32_t> rowStart{0};
    std::vector<uint32_t> rowJoin;  // the join of each active row
    std::vector<uint32_t> termIdx;
    std::vector<double> termCoef;
    std::vector<uint32_t> freePoints;  // pool index of each free variable
    std::vector<double> invWeight;     // 1/w per free variable
    std::vector<Component> components;

    size_t rowCount() const { return rowStart.size() - 1; }

    Vec3 rowResidual(const std::vector<Vec3>& p, uint32_t row) const {
        Vec3 s(0.0);
        for (uint32_t t = rowStart[row]; t < rowStart[row + 1]; ++t) s += termCoef[t] * p[termIdx[t]];
        return s;
    }

    // Projects one component: solve, then refine against the true residual (at most 16 solves: the
    // rows round a regular corner where a fill meets its surroundings are nearly dependent, and the
    // regularised solve converges slowly there; a well-conditioned component stops after one).
    // Rows still violated after that cannot hold together: their joins go into `out`.
    void solveComponent(const Component& comp, std::vector<Vec3>& p, Eigen::MatrixXd& r, double worst2, Projection& out) const {
        const auto m = static_cast<Eigen::Index>(comp.rows.size());
        const double tol2 = tolerance * tolerance;
        for (int round = 0;; ++round) {
            if (round > 0) {
                worst2 = 0;
                for (Eigen::Index i = 0; i < m; ++i) {
                    const Vec3 s = rowResidual(p, comp.rows[static_cast<size_t>(i)]);
                    r(i, 0) = -s.x, r(i, 1) = -s.y, r(i, 2) = -s.z;
                    worst2 = std::max(worst2, glm::dot(s, s));
                }
            }
            if (worst2 <= tol2 || round == 16) break;
            const Eigen::MatrixXd y =
                comp.sparse ? solver_detail::solveLdltColumns(*comp.sparse, r.topRows(m)) : Eigen::MatrixXd(comp.dense.solve(r.topRows(m)));
            const Eigen::MatrixXd d = comp.C.transpose() * y;
            for (size_t k = 0; k < comp.vars.size(); ++k) {
                const uint32_t v = comp.vars[k];
                const auto e = static_cast<Eigen::Index>(k);
                p[freePoints[v]] += invWeight[v] * Vec3(d(e, 0), d(e, 1), d(e, 2));
            }
        }
        out.residual = std::max(out.residual, std::sqrt(worst2));
        for (uint32_t row : comp.rows)
            if (glm::length(rowResidual(p, row)) > conflictTolerance) out.conflictingJoins.push_back(rowJoin[row]);
    }
};

// What a solver is built from: the document's rows and point roles, kept (local solvers only) so
// that project() can widen to the whole model without the document.
struct DragSolver::Setup {
    std::vector<ConstraintRow> rows;
    std::vector<char> fixed;     // the dragged points (before freezing)
    std::vector<char> boundary;  // joinedBoundaryPoints
    double size = 1.0;
    SolverOptions options;
};

void DragSolver::build(Impl& im, const Setup& setup, const std::vector<char>& fixed) {
    const SolverOptions& options = setup.options;
    const size_t n = fixed.size();
    im.pointCount = n;
    im.tolerance = 1e-13 * setup.size;
    im.conflictTolerance = 1e-9 * setup.size;

    // Constraint rows, without duplicates (rows equal up to scale: a corner shared by four patches
    // gets the same tangent row from two joins) and without rows that only involve fixed points.
    std::map<std::vector<std::pair<uint32_t, double>>, bool> seen;
    for (const ConstraintRow& row : setup.rows) {
        bool anyFree = false;
        for (const auto& t : row.terms) anyFree = anyFree || !fixed[t.first];
        if (!anyFree) continue;
        std::vector<std::pair<uint32_t, double>> key = row.terms;
        const double lead = key.front().second;
        for (auto& t : key) t.second /= lead;
        if (!seen.emplace(std::move(key), true).second) continue;
        for (const auto& [idx, c] : row.terms) {
            im.termIdx.push_back(idx);
            im.termCoef.push_back(c);
        }
        im.rowStart.push_back(static_cast<uint32_t>(im.termIdx.size()));
        im.rowJoin.push_back(row.join);
    }
    const size_t m = im.rowCount();
    if (m == 0) return;

    // Free variables: the free points that appear in some constraint, weighted by their role.
    const std::vector<char>& boundary = setup.boundary;
    std::vector<int> column(n, -1);
    for (size_t t = 0; t < im.termIdx.size(); ++t) {
        const uint32_t idx = im.termIdx[t];
        if (fixed[idx] || column[idx] >= 0) continue;
        column[idx] = static_cast<int>(im.freePoints.size());
        im.freePoints.push_back(idx);
        im.invWeight.push_back(1.0 / (boundary[idx] ? options.boundaryWeight : options.tangentWeight));
    }

    // Connected components of rows through shared free variables.
    UnionFind uf(m);
    std::vector<int64_t> firstRowOfVar(im.freePoints.size(), -1);
    for (uint32_t i = 0; i < m; ++i)
        for (uint32_t t = im.rowStart[i]; t < im.rowStart[i + 1]; ++t) {
            const int c = column[im.termIdx[t]];
            if (c < 0) continue;
            if (firstRowOfVar[c] < 0)
                firstRowOfVar[c] = i;
            else
                uf.unite(i, static_cast<uint32_t>(firstRowOfVar[c]));
        }
    std::vector<int> compOfRoot(m, -1);
    for (uint32_t i = 0; i < m; ++i) {
        const uint32_t root = uf.find(i);
        if (compOfRoot[root] < 0) {
            compOfRoot[root] = static_cast<int>(im.components.size());
            im.components.emplace_back();
        }
        im.components[static_cast<size_t>(compOfRoot[root])].rows.push_back(i);
    }

    // Per component: C (free columns only), A = C W⁻¹ Cᵀ + εI and its factorisation. Dependent
    // rows (four patches around a corner, loops) make A singular: ε, tiny relative to the
    // diagonal, regularises it and project() removes the resulting error by iterative refinement.
    std::vector<int> localVar(im.freePoints.size(), -1);
    for (Component& comp : im.components) {
        std::vector<Eigen::Triplet<double>> trip;
        for (size_t li = 0; li < comp.rows.size(); ++li) {
            const uint32_t i = comp.rows[li];
            for (uint32_t t = im.rowStart[i]; t < im.rowStart[i + 1]; ++t) {
                const int c = column[im.termIdx[t]];
                if (c < 0) continue;
                if (localVar[c] < 0) {
                    localVar[c] = static_cast<int>(comp.vars.size());
                    comp.vars.push_back(static_cast<uint32_t>(c));
                }
                trip.emplace_back(static_cast<Eigen::Index>(li), localVar[c], im.termCoef[t]);
            }
        }
        const auto mc = static_cast<Eigen::Index>(comp.rows.size());
        const auto nc = static_cast<Eigen::Index>(comp.vars.size());
        comp.C.resize(mc, nc);
        comp.C.setFromTriplets(trip.begin(), trip.end());
        comp.C.makeCompressed();
        Eigen::VectorXd winv(nc);
        for (Eigen::Index k = 0; k < nc; ++k) winv[k] = im.invWeight[comp.vars[static_cast<size_t>(k)]];
        Eigen::SparseMatrix<double> A = comp.C * winv.asDiagonal() * comp.C.transpose();
        double maxDiag = 0;
        for (Eigen::Index i = 0; i < mc; ++i) maxDiag = std::max(maxDiag, A.coeff(i, i));
        // 1e-12: a C2 grid's row drag has eigenvalues down to ~3e-5 of the largest, so each round
        // of refinement cuts its error by ~3e-8 and two rounds reach the tolerance (at 1e-10, three).
        const double eps = 1e-12 * std::max(maxDiag, 1e-300);
        if (mc <= static_cast<Eigen::Index>(options.denseComponentLimit)) {
            Eigen::MatrixXd Ad = Eigen::MatrixXd(A);
            Ad.diagonal().array() += eps;
            comp.dense.compute(Ad);
            if (comp.dense.info() != Eigen::Success) throw std::runtime_error("DragSolver: factorisation failed");
        } else {
            for (Eigen::Index i = 0; i < mc; ++i) A.coeffRef(i, i) += eps;
            comp.sparse = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(A);
            if (comp.sparse->info() != Eigen::Success) throw std::runtime_error("DragSolver: factorisation failed");
        }
        for (uint32_t v : comp.vars) localVar[v] = -1;
    }
}

DragSolver::DragSolver(const Document& doc, std::vector<uint32_t> fixedPoints, SolverOptions options) : impl_(std::make_unique<Impl>()) {
    if (!(options.boundaryWeight > 0) || !(options.tangentWeight > 0)) throw std::invalid_argument("DragSolver: weights must be positive");
    auto setup = std::make_unique<Setup>();
    setup->rows = solver_detail::buildConstraintRows(doc);
    setup->boundary = solver_detail::joinedBoundaryPoints(doc);
    setup->size = modelSize(doc);
    setup->options = options;
    setup->fixed.assign(doc.points.size(), 0);
    for (uint32_t f : fixedPoints)
        if (f < setup->fixed.size()) setup->fixed[f] = 1;
    if (options.localRings <= 0) {
        build(*impl_, *setup, setup->fixed);
        return;
    }
    std::vector<char> frozen = setup->fixed;
    freezeOutside(doc, frozen, options.localRings, options.regionPoints);
    build(*impl_, *setup, frozen);
    setup_ = std::move(setup);
}

DragSolver::~DragSolver() = default;
DragSolver::DragSolver(DragSolver&&) noexcept = default;
DragSolver& DragSolver::operator=(DragSolver&&) noexcept = default;

size_t DragSolver::constraintCount() const { return impl_ ? impl_->rowCount() : 0; }

Projection DragSolver::projectWith(const Impl& im, std::vector<Vec3>& points) {
    Projection out;
    if (im.rowCount() == 0) return out;
    if (points.size() < im.pointCount) throw std::invalid_argument("DragSolver::project: point pool shrank");

    // Residual of every component; only the disturbed ones are solved.
    const double tol2 = im.tolerance * im.tolerance;
    Eigen::MatrixXd r;
    for (const Component& comp : im.components) {
        const auto m = static_cast<Eigen::Index>(comp.rows.size());
        double worst2 = 0;
        bool loaded = false;
        for (Eigen::Index i = 0; i < m; ++i) {
            const Vec3 s = im.rowResidual(points, comp.rows[static_cast<size_t>(i)]);
            const double s2 = glm::dot(s, s);
            if (s2 > tol2 && !loaded) {
                // First violated row: fill r for the whole component from here on.
                if (r.rows() < m) r.resize(std::max<Eigen::Index>(m, 64), 3);
                for (Eigen::Index k = 0; k < i; ++k) {
                    const Vec3 q = im.rowResidual(points, comp.rows[static_cast<size_t>(k)]);
                    r(k, 0) = -q.x, r(k, 1) = -q.y, r(k, 2) = -q.z;
                }
                loaded = true;
            }
            if (loaded) r(i, 0) = -s.x, r(i, 1) = -s.y, r(i, 2) = -s.z;
            worst2 = std::max(worst2, s2);
        }
        if (loaded)
            im.solveComponent(comp, points, r, worst2, out);
        else
            out.residual = std::max(out.residual, std::sqrt(worst2));
    }
    std::sort(out.conflictingJoins.begin(), out.conflictingJoins.end());
    out.conflictingJoins.erase(std::unique(out.conflictingJoins.begin(), out.conflictingJoins.end()), out.conflictingJoins.end());
    return out;
}

Projection DragSolver::project(std::vector<Vec3>& points) const {
    if (!impl_) return {};
    Projection out = projectWith(*impl_, points);
    if (out.ok() || !setup_) return out;
    // The local region could not hold the joins: widen to the whole model (built once) and go on
    // from there; what is still violated then is a real conflict.
    if (!global_) {
        global_ = std::make_unique<Impl>();
        build(*global_, *setup_, setup_->fixed);
    }
    return projectWith(*global_, points);
}

Projection projectConstraints(Document& doc, const std::vector<uint32_t>& fixedPoints, SolverOptions options) {
    DragSolver solver(doc, fixedPoints, options);
    return solver.project(doc.points);
}

std::string conflictMessage(const Projection& p) {
    if (p.ok()) return "";
    std::string names;
    size_t shown = 0;
    for (uint32_t j : p.conflictingJoins) {
        if (shown == 8) {
            names += " and " + std::to_string(p.conflictingJoins.size() - shown) + " more";
            break;
        }
        if (shown) names += shown + 1 == p.conflictingJoins.size() ? " and " : ", ";
        names += j == kNetSeamJoin ? std::string("a net's C1 seam") : std::to_string(j);
        ++shown;
    }
    char held[32];
    std::snprintf(held, sizeof held, "%.2g", p.residual);
    return (p.conflictingJoins.size() == 1 ? "join " + names + " cannot hold" : "joins " + names + " cannot all hold") +
           " (over-constrained; the worst condition is off by " + held + ")";
}

double maxConstraintResidual(const Document& doc) {
    const JoinResiduals r = joinResiduals(doc);
    double worst = r.netSeams;
    for (double v : r.perJoin) worst = std::max(worst, v);
    return worst;
}

JoinResiduals joinResiduals(const Document& doc) {
    JoinResiduals out;
    out.perJoin.assign(doc.joins.size(), 0.0);
    for (const ConstraintRow& row : solver_detail::buildConstraintRows(doc)) {
        Vec3 s(0.0);
        for (const auto& [idx, c] : row.terms) s += c * doc.points[idx];
        double& worst = row.join < out.perJoin.size() ? out.perJoin[row.join] : out.netSeams;
        worst = std::max(worst, double(glm::length(s)));
    }
    return out;
}

}  // namespace solve
}  // namespace pw

// Projection of edited control points onto the join constraints (DESIGN §1): a weighted
// least-change KKT solve, d = W⁻¹Cᵀy with (C W⁻¹ Cᵀ + εI) y = r, factorised once per drag.
#include "core/constraint_solver.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "core/net_ops.hpp"
#include "core/solver_constraints.hpp"

namespace pw {

namespace solver_detail {

bool joinPoints(const Document& doc, const Join& join, JoinPoints& out) {
    if (join.patchA >= doc.patches.size() || join.patchB >= doc.patches.size()) return false;
    const Patch& A = doc.patches[join.patchA];
    const Patch& B = doc.patches[join.patchB];
    for (int k = 0; k < 4; ++k) {
        const int kb = join.reversed ? 3 - k : k;
        out.a0[k] = A.idx[edgeSlot(join.edgeA, k, 0)];
        out.a1[k] = A.idx[edgeSlot(join.edgeA, k, 1)];
        out.b0[k] = B.idx[edgeSlot(join.edgeB, kb, 0)];
        out.b1[k] = B.idx[edgeSlot(join.edgeB, kb, 1)];
    }
    return true;
}

namespace {

// Merges repeated indices, drops zero coefficients and sorts by index.
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

bool collapsed(const uint32_t (&e)[4]) { return e[0] == e[1] && e[1] == e[2] && e[2] == e[3]; }

}  // namespace

std::vector<ConstraintRow> buildConstraintRows(const Document& doc) {
    std::vector<ConstraintRow> rows;
    rows.reserve(doc.joins.size() * 4);
    const uint32_t n = static_cast<uint32_t>(doc.points.size());
    for (size_t j = 0; j < doc.joins.size(); ++j) {
        const Join& join = doc.joins[j];
        JoinPoints jp;
        if (!joinPoints(doc, join, jp)) continue;
        bool valid = true;
        for (int k = 0; k < 4; ++k)
            valid = valid && jp.a0[k] < n && jp.a1[k] < n && jp.b0[k] < n && jp.b1[k] < n;
        if (!valid) continue;
        const uint32_t ji = static_cast<uint32_t>(j);
        // C0: the two sides' edge points coincide (nothing to do when they share the pool entry).
        for (int k = 0; k < 4; ++k)
            if (jp.a0[k] != jp.b0[k]) rows.push_back(makeRow({{jp.a0[k], 1.0}, {jp.b0[k], -1.0}}, ji));
        if (join.continuity == Continuity::C0) continue;
        if (collapsed(jp.a0) || collapsed(jp.b0)) continue;  // a pole: no cross-boundary tangent
        const double alpha = join.alpha;
        for (int k = 0; k < 4; ++k) {
            const bool aFlat = jp.a1[k] == jp.a0[k], bFlat = jp.b1[k] == jp.b0[k];
            if (aFlat != bFlat) continue;  // one side's tangent collapsed onto the boundary point
            ConstraintRow row = makeRow({{jp.b1[k], 1.0}, {jp.a0[k], -(1.0 + alpha)}, {jp.a1[k], alpha}}, ji);
            if (!row.terms.empty()) rows.push_back(std::move(row));
        }
    }
    // Bézier nets that keep C1: each seam point midway between its neighbours across the seam.
    for (const auto& [before, seam, after] : netC1Triples(doc)) {
        if (before >= n || seam >= n || after >= n) continue;
        ConstraintRow row = makeRow({{before, 1.0}, {seam, -2.0}, {after, 1.0}}, kNetSeamRow);
        if (!row.terms.empty()) rows.push_back(std::move(row));
    }
    return rows;
}

std::vector<char> joinedBoundaryPoints(const Document& doc) {
    std::vector<char> flag(doc.points.size(), 0);
    for (const Join& join : doc.joins) {
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
    std::vector<uint32_t> rows;  // indices into Impl::rowStart
    std::vector<uint32_t> vars;  // free variables (indices into Impl::freePoints)
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

}  // namespace

struct DragSolver::Impl {
    size_t pointCount = 0;
    double tolerance = 0;  // residual to reach: 1e-13 × model size (well inside 1e-9)
    // Active constraints (at least one free point) in compressed rows over pool indices.
    std::vector<uint32_t> rowStart{0};
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

    // Projects one component: solve, then refine against the true residual (at most 4 solves).
    void solveComponent(const Component& comp, std::vector<Vec3>& p, Eigen::MatrixXd& r, double worst2) const {
        const auto m = static_cast<Eigen::Index>(comp.rows.size());
        const double tol2 = tolerance * tolerance;
        for (int round = 0; round < 4; ++round) {
            if (round > 0) {
                worst2 = 0;
                for (Eigen::Index i = 0; i < m; ++i) {
                    const Vec3 s = rowResidual(p, comp.rows[static_cast<size_t>(i)]);
                    r(i, 0) = -s.x, r(i, 1) = -s.y, r(i, 2) = -s.z;
                    worst2 = std::max(worst2, glm::dot(s, s));
                }
            }
            if (worst2 <= tol2) return;
            const Eigen::MatrixXd y = comp.sparse ? Eigen::MatrixXd(comp.sparse->solve(r.topRows(m)))
                                                  : Eigen::MatrixXd(comp.dense.solve(r.topRows(m)));
            const Eigen::MatrixXd d = comp.C.transpose() * y;
            for (size_t k = 0; k < comp.vars.size(); ++k) {
                const uint32_t v = comp.vars[k];
                const auto e = static_cast<Eigen::Index>(k);
                p[freePoints[v]] += invWeight[v] * Vec3(d(e, 0), d(e, 1), d(e, 2));
            }
        }
    }
};

DragSolver::DragSolver(const Document& doc, std::vector<uint32_t> fixedPoints, SolverOptions options)
    : impl_(std::make_unique<Impl>()) {
    Impl& im = *impl_;
    const size_t n = doc.points.size();
    im.pointCount = n;
    im.tolerance = 1e-13 * modelSize(doc);
    if (!(options.boundaryWeight > 0) || !(options.tangentWeight > 0))
        throw std::invalid_argument("DragSolver: weights must be positive");

    std::vector<char> fixed(n, 0);
    for (uint32_t f : fixedPoints)
        if (f < n) fixed[f] = 1;

    // Constraint rows, without duplicates (rows equal up to scale: a corner shared by four patches
    // gets the same tangent row from two joins) and without rows that only involve fixed points.
    std::map<std::vector<std::pair<uint32_t, double>>, bool> seen;
    for (ConstraintRow& row : solver_detail::buildConstraintRows(doc)) {
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
    }
    const size_t m = im.rowCount();
    if (m == 0) return;

    // Free variables: the free points that appear in some constraint, weighted by their role.
    const std::vector<char> boundary = solver_detail::joinedBoundaryPoints(doc);
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
        const double eps = 1e-10 * std::max(maxDiag, 1e-300);
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

DragSolver::~DragSolver() = default;
DragSolver::DragSolver(DragSolver&&) noexcept = default;
DragSolver& DragSolver::operator=(DragSolver&&) noexcept = default;

size_t DragSolver::constraintCount() const { return impl_ ? impl_->rowCount() : 0; }

void DragSolver::project(std::vector<Vec3>& points) const {
    if (!impl_ || impl_->rowCount() == 0) return;
    const Impl& im = *impl_;
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
        if (loaded) im.solveComponent(comp, points, r, worst2);
    }
}

void projectConstraints(Document& doc, const std::vector<uint32_t>& fixedPoints, SolverOptions options) {
    DragSolver solver(doc, fixedPoints, options);
    solver.project(doc.points);
}

double maxConstraintResidual(const Document& doc) {
    double worst = 0;
    for (const ConstraintRow& row : solver_detail::buildConstraintRows(doc)) {
        Vec3 s(0.0);
        for (const auto& [idx, c] : row.terms) s += c * doc.points[idx];
        worst = std::max(worst, glm::length(s));
    }
    return worst;
}

}  // namespace pw

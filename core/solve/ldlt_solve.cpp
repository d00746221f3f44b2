#include "core/solve/ldlt_solve.hpp"

#include <vector>

namespace pw {
inline namespace solve {
namespace solver_detail {

namespace {

// L D L^T y = y in place for K interleaved right-hand sides (row-major, K doubles a row); column j
// of L holds its entries below the diagonal at [outer[j], last[j]).
template <int K>
void substitute(Eigen::Index n, const int* outer, const int* last, const int* inner, const double* value, const double* d, double* y) {
    for (Eigen::Index j = 0; j < n; ++j) {  // L y' = y: column j scatters y_j into the later rows
        const double* yj = y + j * K;
        for (int p = outer[j]; p < last[j]; ++p) {
            double* yi = y + Eigen::Index(inner[p]) * K;
            for (int c = 0; c < K; ++c) yi[c] -= value[p] * yj[c];
        }
    }
    for (Eigen::Index j = 0; j < n; ++j)
        for (int c = 0; c < K; ++c) y[j * K + c] /= d[j];
    for (Eigen::Index j = n - 1; j >= 0; --j) {  // L^T y'' = y': row j of L^T gathers the later rows
        double acc[K];
        for (int c = 0; c < K; ++c) acc[c] = y[j * K + c];
        for (int p = outer[j]; p < last[j]; ++p) {
            const double* yi = y + Eigen::Index(inner[p]) * K;
            for (int c = 0; c < K; ++c) acc[c] -= value[p] * yi[c];
        }
        for (int c = 0; c < K; ++c) y[j * K + c] = acc[c];
    }
}

}  // namespace

Eigen::MatrixXd solveLdltColumns(const SparseLdlt& f, const Eigen::MatrixXd& b) {
    const Eigen::Index n = b.rows(), k = b.cols();
    const Eigen::SparseMatrix<double>& L = f.matrixL().nestedExpression();  // unit lower, diagonal not stored
    const auto& D = f.vectorD();
    const auto& P = f.permutationP();
    // y = P b, row-major, so that one entry of L updates all k columns of a row together.
    std::vector<double> y(static_cast<size_t>(n * k));
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index to = P.size() ? P.indices()[i] : i;
        for (Eigen::Index c = 0; c < k; ++c) y[size_t(to * k + c)] = b(i, c);
    }
    const int* outer = L.outerIndexPtr();
    const int* inner = L.innerIndexPtr();
    const double* value = L.valuePtr();
    const int* nnz = L.innerNonZeroPtr();  // null when compressed
    std::vector<int> last(static_cast<size_t>(n));
    for (Eigen::Index j = 0; j < n; ++j) last[size_t(j)] = nnz ? outer[j] + nnz[j] : outer[j + 1];
    if (k == 3)
        substitute<3>(n, outer, last.data(), inner, value, D.data(), y.data());
    else
        for (Eigen::Index c = 0; c < k; ++c) {  // any other width, a column at a time
            std::vector<double> col(static_cast<size_t>(n));
            for (Eigen::Index i = 0; i < n; ++i) col[size_t(i)] = y[size_t(i * k + c)];
            substitute<1>(n, outer, last.data(), inner, value, D.data(), col.data());
            for (Eigen::Index i = 0; i < n; ++i) y[size_t(i * k + c)] = col[size_t(i)];
        }
    // x = P^-1 y.
    Eigen::MatrixXd x(n, k);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index from = P.size() ? P.indices()[i] : i;
        for (Eigen::Index c = 0; c < k; ++c) x(i, c) = y[size_t(from * k + c)];
    }
    return x;
}

}  // namespace solver_detail
}  // namespace solve
}  // namespace pw

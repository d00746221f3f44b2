// Solving with an Eigen SimplicialLDLT factorisation for several right-hand sides in one pass over
// its factor. Eigen's own solve runs the two triangular solves once per column; a drag's residual has
// three (x, y, z), and the factor of a C2 grid's row drag (127 k non-zeros) is read from memory three
// times over where once will do: the solve is 86 % of such a drag.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

namespace pw {
inline namespace solve {
namespace solver_detail {

using SparseLdlt = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;

// x with A x = b for the A that `f` factorised (P^T L D L^T P), every column of b at once; the same
// result as f.solve(b) up to rounding.
Eigen::MatrixXd solveLdltColumns(const SparseLdlt& f, const Eigen::MatrixXd& b);

}  // namespace solver_detail
}  // namespace solve
}  // namespace pw

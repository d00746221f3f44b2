// Spline bases for one 4x4 window: Bézier, uniform cubic B-spline and Catmull-Rom (DESIGN §2).
#pragma once

#include <optional>
#include <string_view>

#include "core/base/math_types.hpp"

namespace pw {
inline namespace model {

enum class Basis { Bezier, BSpline, CatmullRom };

// Name used in files and on the command line: "bezier", "bspline", "catmull-rom".
std::string_view basisName(Basis basis);
std::optional<Basis> parseBasis(std::string_view name);

// The basis matrix M of p(t) = [t^3 t^2 t 1] · M · G. `tension` is τ, used by Catmull-Rom only.
Mat4 basisMatrix(Basis basis, double tension = 0.5);

// Weights of the four control points at t, and their first and second derivatives.
struct BasisWeights {
    double w[4];
    double dw[4];
    double ddw[4];
};

// Weights from the matrix form: w = [t^3 t^2 t 1]·M, dw = [3t^2 2t 1 0]·M, ddw = [6t 2 0 0]·M.
BasisWeights matrixWeights(const Mat4& m, double t);

// Cubic Bernstein weights computed from t and s = 1 - t given separately, so that a caller can pass
// s exactly (e.g. (n-k)/n) and get bit-identical results from either end of a curve.
BasisWeights bernsteinWeights(double t, double s);

// Weights for `basis`: Bernstein (from t, 1-t) for Bézier, the matrix form otherwise.
BasisWeights basisWeights(Basis basis, double tension, double t);

}  // namespace model
}  // namespace pw

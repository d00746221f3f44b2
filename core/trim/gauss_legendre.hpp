// Eight-point Gauss-Legendre quadrature on [0, 1] (exact for polynomials of degree 15): trimmed
// areas (Green's theorem along the loops, the surface's area element inside).
#pragma once

namespace pw {
inline namespace trim {

inline constexpr double kGaussX[8] = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355, 0.4082826787521751,
                                      0.5917173212478249, 0.7627662049581645, 0.8983332387068134, 0.9801449282487681};
inline constexpr double kGaussW[8] = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436, 0.1813418916891810,
                                      0.1813418916891810, 0.1568533229389436, 0.1111905172266872, 0.0506142681451881};

}  // namespace trim
}  // namespace pw

// Rational (weighted) evaluation, written once for the CPU (core/eval/rational_eval.cpp, in double) and
// the shaders (in float); core/gpu/glsl_cpp.h says how one header serves both languages.
//
// A rational patch is Σ N·w·P / Σ N·w. Its control points travel in homogeneous form
// (w·P, w − 1): the fourth component holds w − 1, not w, so that the denominator is
// W = 1 + Σ N·(w − 1). For a polynomial patch (every weight 1) that sum is exactly 0 and W exactly 1,
// the numerator is Σ N·P bit for bit, and the quotient rule below divides by 1 and subtracts zeros:
// polynomial patches evaluate to the same bits as without weights, seams included.
// Derivatives by the quotient rule: with H = Σ N·w·P and W, P = H / W and
//   P_a  = (H_a − W_a·P) / W
//   P_ab = (H_ab − W_a·P_b − W_b·P_a − W_ab·P) / W
// (a, b any of the parameters; a = b gives the second derivative along one of them).
#ifndef PW_RATIONAL_MATH_H
#define PW_RATIONAL_MATH_H

#include "core/gpu/glsl_cpp.h"

PW_BEGIN_NAMESPACE

// A control point p of weight w in the homogeneous form the sums take.
PW_REAL_FN PW_REAL_VEC4 homogeneousPoint(PW_REAL_VEC3 p, PW_REAL w) { return PW_REAL_VEC4(p * w, w - PW_REAL(1)); }

// The point of a homogeneous sum h = Σ N·(w·P, w − 1).
PW_REAL_FN PW_REAL_VEC3 rationalPoint(PW_REAL_VEC4 h) { return PW_REAL_VEC3(h.x, h.y, h.z) / (PW_REAL(1) + h.w); }

// The first derivative from the sum h, its derivative ha and the point p = rationalPoint(h).
PW_REAL_FN PW_REAL_VEC3 rationalDerivative(PW_REAL_VEC4 h, PW_REAL_VEC4 ha, PW_REAL_VEC3 p) {
    return (PW_REAL_VEC3(ha.x, ha.y, ha.z) - ha.w * p) / (PW_REAL(1) + h.w);
}

// The second derivative ∂²/∂a∂b from the sums h, ha, hb, hab, the point p and its first
// derivatives pa, pb (rationalDerivative).
PW_REAL_FN PW_REAL_VEC3 rationalSecondDerivative(PW_REAL_VEC4 h, PW_REAL_VEC4 ha, PW_REAL_VEC4 hb, PW_REAL_VEC4 hab, PW_REAL_VEC3 p,
                                                 PW_REAL_VEC3 pa, PW_REAL_VEC3 pb) {
    return (PW_REAL_VEC3(hab.x, hab.y, hab.z) - ha.w * pb - hb.w * pa - hab.w * p) / (PW_REAL(1) + h.w);
}

PW_END_NAMESPACE

#endif  // PW_RATIONAL_MATH_H

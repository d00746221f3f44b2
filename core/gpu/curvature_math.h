// Curvature of a parametric surface from its first and second derivatives, written once for the
// CPU (continuity report, curvature combs, tests; in double) and the shaders (curvature shading and
// the comb overlay; in float). core/gpu/glsl_cpp.h says how one header serves both languages.
#ifndef PW_CURVATURE_MATH_H
#define PW_CURVATURE_MATH_H

#include "core/gpu/glsl_cpp.h"

PW_BEGIN_NAMESPACE

// Gaussian and mean curvature (K, H) from the fundamental forms (E F G from du dv; L M N from the
// second derivatives and the unit normal n). (0, 0) where the first form is singular (a collapsed
// edge), whose curvature the derivatives there cannot give.
PW_REAL_FN PW_REAL_VEC2 gaussMeanCurvature(PW_REAL_VEC3 du, PW_REAL_VEC3 dv, PW_REAL_VEC3 duu, PW_REAL_VEC3 duv, PW_REAL_VEC3 dvv,
                                           PW_REAL_VEC3 n) {
    PW_REAL E = dot(du, du), F = dot(du, dv), G = dot(dv, dv);
    PW_REAL L = dot(duu, n), M = dot(duv, n), N = dot(dvv, n);
    PW_REAL den = E * G - F * F;
    if (!(den > PW_REAL(1e-12) * (E * G + PW_REAL(1e-30)))) return PW_REAL_VEC2(PW_REAL(0), PW_REAL(0));
    return PW_REAL_VEC2((L * N - M * M) / den, (E * N - PW_REAL(2) * F * M + G * L) / (PW_REAL(2) * den));
}

// Normal curvature II(w, w) / I(w, w) in the parameter direction (a, b), i.e. along the surface
// tangent a·du + b·dv; positive where the surface bends towards n. 0 for a zero tangent.
PW_REAL_FN PW_REAL normalCurvature(PW_REAL_VEC3 du, PW_REAL_VEC3 dv, PW_REAL_VEC3 duu, PW_REAL_VEC3 duv, PW_REAL_VEC3 dvv, PW_REAL_VEC3 n,
                                   PW_REAL a, PW_REAL b) {
    PW_REAL first = a * a * dot(du, du) + PW_REAL(2) * a * b * dot(du, dv) + b * b * dot(dv, dv);
    PW_REAL second = a * a * dot(duu, n) + PW_REAL(2) * a * b * dot(duv, n) + b * b * dot(dvv, n);
    return first > PW_REAL(0) ? second / first : PW_REAL(0);
}

// Curvature vector of a curve with derivatives d1, d2: (d1 × d2) × d1 / |d1|⁴, pointing to the
// centre of curvature, of length κ (0 where the curve stops). A curvature comb draws −κ·N, the
// tooth outward from the centre (Rhino's and Alias's convention).
PW_REAL_FN PW_REAL_VEC3 curveCurvatureVector(PW_REAL_VEC3 d1, PW_REAL_VEC3 d2) {
    PW_REAL l2 = dot(d1, d1);
    if (!(l2 > PW_REAL(0))) return PW_REAL_VEC3(PW_REAL(0), PW_REAL(0), PW_REAL(0));
    return (d2 * l2 - d1 * dot(d1, d2)) / (l2 * l2);
}

PW_END_NAMESPACE

#endif  // PW_CURVATURE_MATH_H

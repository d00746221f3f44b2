#include "core/model/basis.hpp"

#include "core/base/enum_names.hpp"
#include "core/gpu/patch_math.h"

namespace pw {
inline namespace model {

namespace {
constexpr std::array<std::string_view, 3> kBasisNames{"bezier", "bspline", "catmull-rom"};
}

std::string_view basisName(Basis basis) { return enumName(basis, kBasisNames); }
std::optional<Basis> parseBasis(std::string_view name) { return parseEnum<Basis>(name, kBasisNames); }

Mat4 basisMatrix(Basis basis, double tension) {
    switch (basis) {
        case Basis::Bezier:
            return {{{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}}};
        case Basis::BSpline: {
            const double s = 1.0 / 6.0;
            return {{{-1 * s, 3 * s, -3 * s, 1 * s}, {3 * s, -6 * s, 3 * s, 0}, {-3 * s, 0, 3 * s, 0}, {1 * s, 4 * s, 1 * s, 0}}};
        }
        case Basis::CatmullRom: {
            const double t = tension;
            return {{{-t, 2 - t, t - 2, t}, {2 * t, t - 3, 3 - 2 * t, -t}, {-t, 0, t, 0}, {0, 1, 0, 0}}};
        }
    }
    return {};
}

BasisWeights matrixWeights(const Mat4& m, double t) {
    const double u[4] = {t * t * t, t * t, t, 1.0};
    const double du[4] = {3 * t * t, 2 * t, 1.0, 0.0};
    const double ddu[4] = {6 * t, 2.0, 0.0, 0.0};
    BasisWeights r{};
    for (int j = 0; j < 4; ++j) {
        for (int k = 0; k < 4; ++k) {
            r.w[j] += u[k] * m[k][j];
            r.dw[j] += du[k] * m[k][j];
            r.ddw[j] += ddu[k] * m[k][j];
        }
    }
    return r;
}

BasisWeights bernsteinWeights(double t, double s) {
    const glm::dvec4 w = gpu::bernstein3(t, s), dw = gpu::bernstein3D1(t, s), ddw = gpu::bernstein3D2(t, s);
    BasisWeights r{};
    for (int i = 0; i < 4; ++i) r.w[i] = w[i], r.dw[i] = dw[i], r.ddw[i] = ddw[i];
    return r;
}

BasisWeights basisWeights(Basis basis, double tension, double t) {
    if (basis == Basis::Bezier) return bernsteinWeights(t, 1.0 - t);
    const Mat4 m = basisMatrix(basis, tension);
    if (t != 1.0) return matrixWeights(m, t);
    // Uniform splines are shift-invariant: the weights at t = 1 are those at t = 0 moved one point
    // on. Taking them so (not from the rounded column sums) makes the boundary a window shares
    // with its neighbour bit-identical on both sides.
    const BasisWeights w0 = matrixWeights(m, 0.0);
    BasisWeights w1{};
    for (int j = 1; j < 4; ++j) {
        w1.w[j] = w0.w[j - 1];
        w1.dw[j] = w0.dw[j - 1];
        w1.ddw[j] = w0.ddw[j - 1];
    }
    return w1;
}

}  // namespace model
}  // namespace pw

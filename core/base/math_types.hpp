// Basic numeric types shared by the core: double-precision vectors (GLM) and 4x4 basis matrices.
#pragma once

#include <array>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace pw {
inline namespace base {

using Vec3 = glm::dvec3;

// Row-major 4x4 matrix; for a basis matrix, rows are the coefficients of t^3, t^2, t, 1.
using Mat4 = std::array<std::array<double, 4>, 4>;

// Sixteen control points of one bicubic window, row-major: index = i*4 + j, i = v row, j = u column.
using Net16 = std::array<Vec3, 16>;
// Their weights (rational windows, core/eval/rational_eval.hpp).
using Weights16 = std::array<double, 16>;

}  // namespace base
}  // namespace pw

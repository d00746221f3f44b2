// Evaluation of a window whose points may carry weights (rational patches, issue 21): a window's
// points with their weights, and position, derivatives and normal at (u, v), a curvature jet and
// the watertight grid, like core/eval/patch_eval.hpp's polynomial evaluators, which a window without
// weights goes straight to. Rational windows evaluate Σ N·w·P / Σ N·w through homogeneous sums and
// the quotient rule of core/gpu/rational_math.h (one home with the shaders), any basis.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/eval/patch_eval.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace eval {

struct WindowNet {
    Net16 points{};
    std::optional<Weights16> weights;  // none: every weight is 1 (a polynomial window)
};
WindowNet gatherWindow(const Document& doc, const std::array<uint32_t, 16>& idx);

SurfacePoint evaluateWindow(const WindowNet& net, Basis basis, double tension, double u, double v);
SurfaceJet evaluateWindowJet(const WindowNet& net, Basis basis, double tension, double u, double v);
// evaluateGrid for a window with weights: Bézier boundaries from each boundary's four points and
// weights alone in its canonical direction, so neighbours get the same bits along a shared edge
// (and, where the edge's weights are all 1, the same bits as a polynomial neighbour).
void evaluateWindowGrid(const WindowNet& net, const std::array<uint32_t, 16>& poolIdx, const GridWeights& gw,
                        std::vector<SurfacePoint>& out);

// A rational Bézier patch split like splitBezierU/V: de Casteljau on the homogeneous points, so each
// half is the same surface; the halves' points and weights.
struct WeightedSplit {
    WindowNet first, second;
};
WeightedSplit splitWindowBezier(const WindowNet& net, bool alongU, double t);

// A cubic rational Bézier curve (four points, four weights) at t, and its first and second derivatives.
struct CurveJet {
    Vec3 p{0.0}, d1{0.0}, d2{0.0};
};
CurveJet evaluateRationalCurve(const std::array<Vec3, 4>& p, const std::array<double, 4>& w, double t);

}  // namespace eval
}  // namespace pw

// A patch or a net as one surface over its whole (u, v) domain [0, 1]² (issue 64): the domain that
// trim loops live in. A patch is its one window; a net's W x H windows tile the square, window
// (r, c) covering [c/W, (c+1)/W] x [r/H, (r+1)/H]. Evaluation, the window under a domain point,
// closest points and projections along a direction.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/eval/rational_eval.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace trim {

// "3" or "n2" (commands, messages).
std::string surfaceRefName(const SurfaceRef& s);
// Parses "3" (a patch) or "nN" (a net) against `doc`; throws EditError naming the word.
SurfaceRef parseSurfaceRef(const Document& doc, std::string_view word);
bool surfaceExists(const Document& doc, const SurfaceRef& s);
std::vector<TrimLoop>& trimsOf(Document& doc, const SurfaceRef& s);
const std::vector<TrimLoop>& trimsOf(const Document& doc, const SurfaceRef& s);

class DomainSurface {
public:
    DomainSurface(const Document& doc, const SurfaceRef& ref);

    uint32_t windowsU() const { return wu_; }
    uint32_t windowsV() const { return wv_; }
    bool closedU() const { return closedU_; }
    bool closedV() const { return closedV_; }
    // Position, derivatives (with respect to the domain's u, v) and normal at a domain point
    // (clamped into [0, 1]²).
    SurfacePoint evaluate(UV uv) const;
    // The domain point nearest to p (Newton from the best of a sample grid, or from `guess`).
    UV closest(const Vec3& p, std::optional<UV> guess = std::nullopt) const;
    // Where the line through p along `dir` meets the surface nearest p, if it does.
    std::optional<UV> alongDirection(const Vec3& p, const Vec3& dir, std::optional<UV> guess = std::nullopt) const;
    // Area of the whole domain's surface (Gauss quadrature per window).
    double area() const;
    // Sample grid of the surface (n x n per window) and its bounding box diagonal.
    double size() const { return size_; }

private:
    struct Window {
        WindowNet net;
        Basis basis = Basis::Bezier;
        double tension = 0.5;
    };
    std::vector<Window> windows_;  // row-major, wv_ rows of wu_
    uint32_t wu_ = 1, wv_ = 1;
    bool closedU_ = false, closedV_ = false;
    double size_ = 1.0;
    std::vector<std::pair<UV, Vec3>> samples_;
};

// ∫₀ᵘ |S_u × S_v|(s, v) ds, the inner integral of Green's theorem for trimmed areas, at many
// points (the Gauss points along trim loops, thousands on a CAD face): the
// whole windows left of u from a table per window row, filled when the row is first asked for
// (their strip integrals at 16 Chebyshev points of the row's v, summed along u, interpolated in
// v), the last window's part by Gauss quadrature (8 points per quarter window). One loop point costs one window's
// quadrature instead of a whole row's. Not thread-safe: one per computation.
class AreaStrips {
public:
    explicit AreaStrips(const DomainSurface& surface) : s_(surface), rows_(surface.windowsV()) {}
    double at(UV uv);

private:
    const DomainSurface& s_;
    std::vector<std::vector<double>> rows_;  // per row: (windowsU + 1) prefixes x 16 nodes, empty until used
};

}  // namespace trim
}  // namespace pw

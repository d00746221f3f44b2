// Trim loops (issue 64; the struct is core/model/document.hpp's TrimLoop): their checks (closed,
// inside the domain, not crossing themselves or each other), orientation, the v-monotone segments
// that the GPU and the CPU test points against (core/gpu/trim_math.h), and trimmed areas.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/model/document.hpp"

namespace pw {
inline namespace trim {

class DomainSurface;

// "" when the loop can trim a surface; else why not ("is not closed", "crosses itself near
// (0.31, 0.52)", "leaves the domain [0, 1]² at (1.2, 0.4)", "encloses no area").
std::string trimLoopProblem(const TrimLoop& loop);
// The same for a surface's loops together: each loop, and no two loops crossing.
std::string trimLoopsProblem(const std::vector<TrimLoop>& loops);

// The loop's signed area in the (u, v) domain (counter-clockwise positive), exact for the cubic
// segments (Green's theorem, ∮ u dv, integrated exactly by Gauss points).
double signedUvArea(const TrimLoop& loop);
// Turns the loop round when needed so that it is clockwise for a hole, counter-clockwise otherwise.
void orientLoop(TrimLoop& loop, bool hole);
// True when some loop is counter-clockwise (an outer boundary): then only what loops enclose is kept.
bool hasOuterLoop(const std::vector<TrimLoop>& loops);

// The part [t0, t1] of a cubic Bézier in the plane (de Casteljau: the same curve).
std::array<glm::dvec2, 4> cubicPiece(const std::array<glm::dvec2, 4>& b, double t0, double t1);

// A cubic Bézier piece of a loop, monotone in v.
struct TrimSegment {
    std::array<glm::dvec2, 4> b{};
};
std::vector<TrimSegment> monotoneSegments(const std::vector<TrimLoop>& loops);
// Whether domain point uv is kept (the parity rule of core/gpu/trim_math.h).
bool trimKeeps(const std::vector<TrimSegment>& segments, bool outer, glm::dvec2 uv);
inline bool trimKeeps(const std::vector<TrimLoop>& loops, glm::dvec2 uv) {
    return loops.empty() || trimKeeps(monotoneSegments(loops), hasOuterLoop(loops), uv);
}

// A circle about `centre` in the domain as four cubic arcs (handles 0.5523 r: within 2.7e-4 r of
// the circle), turned for `hole`: test patterns and the benchmark's holes.
TrimLoop circleLoop(UV centre, double radius, bool hole);

// The loop's cubic segments: how many, and segment s's four points (3s .. 3s + 3).
size_t segmentCount(const TrimLoop& loop);
std::array<glm::dvec2, 4> loopSegment(const TrimLoop& loop, size_t s);

// Points along the loop, `perSegment` per cubic segment, the first not repeated at the end.
std::vector<glm::dvec2> loopPolyline(const TrimLoop& loop, int perSegment);
glm::dvec2 loopPoint(const TrimLoop& loop, size_t segment, double t);

// The area of the surface's kept part: the whole surface's less the holes', or what the outer
// loops enclose less the holes inside them (Green's theorem over the loops with the surface's area
// element, Gauss quadrature: relative error ~1e-9 on smooth surfaces).
double trimmedArea(const DomainSurface& surface, const std::vector<TrimLoop>& loops);

// The loops of a surface seen in one window's own [0, 1]² (window (r, c) of W x H): an affine map
// of every point, the segments that can affect the window's test (those reaching its v range and
// not wholly left of it), sorted by their lowest v, and the flags of core/gpu/trim_math.h. A window
// no segment reaches is wholly kept (no segments, flags 0) or wholly gone (kTrimAllGone).
struct WindowTrim {
    std::vector<TrimSegment> segments;
    uint32_t flags = 0;
};
WindowTrim windowTrim(const std::vector<TrimSegment>& netSegments, bool outer, uint32_t r, uint32_t c, uint32_t wu, uint32_t wv);

// Each window's share of its surface's trims (expandPatches order), the surface's loops split into
// v-monotone pieces once, not once per window: what the renderer, picking, the overlays and the
// trimmed mesh ask of every window.
class WindowTrims {
public:
    explicit WindowTrims(const Document& doc) : doc_(doc) {}
    // None for a window of an untrimmed patch or net (or a triangle).
    std::optional<WindowTrim> of(const PatchInstance& w);

private:
    struct Split {
        std::vector<TrimSegment> segments;
        bool outer = false;
    };
    const Document& doc_;
    int32_t net_ = -1;  // the net whose pieces `split_` holds
    Split split_;
};

}  // namespace trim
}  // namespace pw

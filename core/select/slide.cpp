#include "core/select/slide.hpp"

#include <cmath>

namespace pw {
inline namespace select {

std::optional<SlideAxis> parseSlideAxis(std::string_view word) {
    if (word == "u" || word == "U") return SlideAxis::U;
    if (word == "v" || word == "V") return SlideAxis::V;
    if (word == "n" || word == "N") return SlideAxis::N;
    return std::nullopt;
}

namespace {

// The grid of pool indices a point sits in, and its place: a patch's 4×4 or a net's rows×cols.
struct GridSpot {
    const uint32_t* idx = nullptr;
    int cols = 0, rows = 0, col = 0, row = 0;
    bool closedU = false, closedV = false;
};

std::optional<GridSpot> spotOf(const Document& doc, uint32_t i) {
    for (const Patch& p : doc.patches)
        for (int s = 0; s < 16; ++s)
            if (p.idx[size_t(s)] == i) return GridSpot{p.idx.data(), 4, 4, s % 4, s / 4};
    for (const Surface& n : doc.surfaces)
        for (size_t s = 0; s < n.idx.size(); ++s)
            if (n.idx[s] == i)
                return GridSpot{n.idx.data(), int(n.cols), int(n.rows), int(s % n.cols), int(s / n.cols), n.closedU, n.closedV};
    return std::nullopt;
}

// The chord through the spot along one direction of its grid (wrapping a closed net).
Vec3 chord(const Document& doc, const GridSpot& g, bool alongU) {
    const int n = alongU ? g.cols : g.rows, at = alongU ? g.col : g.row;
    const bool closed = alongU ? g.closedU : g.closedV;
    auto point = [&](int k) {
        k = closed ? (k % n + n) % n : k;
        return doc.points[g.idx[size_t(alongU ? g.row * g.cols + k : k * g.cols + g.col)]];
    };
    const int lo = closed || at > 0 ? at - 1 : at, hi = closed || at < n - 1 ? at + 1 : at;
    return point(hi) - point(lo);
}

}  // namespace

std::optional<Vec3> slideDirection(const Document& doc, uint32_t i, SlideAxis axis) {
    if (i >= doc.points.size()) return std::nullopt;
    const auto g = spotOf(doc, i);
    if (!g) return std::nullopt;
    const Vec3 du = chord(doc, *g, true), dv = chord(doc, *g, false);
    Vec3 d = axis == SlideAxis::U ? du : axis == SlideAxis::V ? dv : glm::cross(du, dv);
    const double len = glm::length(d);
    if (!(len > 1e-12 * std::max(1.0, modelSize(doc)))) return std::nullopt;
    return d / len;
}

std::string slideRefusal(uint32_t i) {
    return "point " + std::to_string(i) + " has no control polygon to slide along (a point of a patch or net slides)";
}

}  // namespace select
}  // namespace pw

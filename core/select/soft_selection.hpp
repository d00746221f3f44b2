// Soft selection (Blender's proportional editing, O): a transform moves the selected points fully
// and the points around them partly, by a falloff of their distance measured along the control nets
// (patch, net, triangle and curve polygons; a join's shared points carry it across to the next
// patch), never through empty space to a part that is not connected. The solver still holds every
// join afterwards (core/edit/drag_controller).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/document.hpp"
#include "core/select/symmetry.hpp"

namespace pw {
inline namespace select {

enum class Falloff : uint8_t { Smooth, Linear, Sharp, Constant };
std::string_view falloffName(Falloff f);  // "smooth", "linear", "sharp", "constant"
std::optional<Falloff> parseFalloff(std::string_view name);

struct SoftSelection {
    bool on = false;
    double radius = 1.0;  // model units, along the nets
    Falloff falloff = Falloff::Smooth;
    bool operator==(const SoftSelection&) const = default;
};

// The share of a transform a point at distance `d` takes (1 at 0, 0 at the radius and beyond).
double falloffWeight(const SoftSelection& s, double d);

// The points the transform of `moved` carries partly, with their shares in (0, 1): every point
// within the radius along the nets of some moved point, the moved points themselves left out.
struct SoftWeights {
    std::vector<uint32_t> points;
    std::vector<double> weights;
};
// Under live symmetry (`sym` on) with the moved points on one side of the plane, only that side's
// points (and those on the plane) are soft: the other side's follow as their mirror images.
SoftWeights softWeights(const Document& doc, const std::vector<uint32_t>& moved, const SoftSelection& s, const Symmetry& sym = {});

// "soft 0.5 smooth"
std::string softDescription(const SoftSelection& s);

}  // namespace select
}  // namespace pw

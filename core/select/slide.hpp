// Slide (issue 40, item 6; Rhino 9's UVN move of control points, Plasticity's slide): a control
// point moves along its own control polygon in u or v, or along the surface normal there, by a
// distance. Each point has its own direction, so a slide of many points is not one translation.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/model/document.hpp"

namespace pw {
inline namespace select {

enum class SlideAxis : uint8_t { U, V, N };
std::optional<SlideAxis> parseSlideAxis(std::string_view word);  // "u", "v", "n" (either case)

// The unit direction point i slides along: for a point of a patch (the first that uses it) or of a
// net, the control polygon through it in u or v (the chord between its neighbours; one-sided at an
// edge), and N = U × V turned to the patch's normal side. nullopt for a point no patch or net uses,
// or where the polygon collapses there.
std::optional<Vec3> slideDirection(const Document& doc, uint32_t i, SlideAxis axis);
// Why point i cannot slide (slideDirection gave nullopt): the `slide` command's and the drag's words.
std::string slideRefusal(uint32_t i);

}  // namespace select
}  // namespace pw

// The level of every window edge when patches and triangles have their own levels (DESIGN §3): a
// boundary curve shared by two windows (the same four pool points) has one outer level, whatever
// the overrides on its two sides — the level belongs to the edge, so no crack opens. Pure (no
// Vulkan): the renderer uploads the result per window, and the control shaders finish it with
// sharedEdgeLevel (core/gpu/patch_math.h), which the tests run on the CPU too.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace tess {

struct WindowLevels {
    // Per outer level slot (quads: u0, v0, u1, v1; triangles: edges 0, 1, 2): when bit e of
    // fixedMask is set, edge e's level is outer[e] as is (every window on the edge has its own
    // levels: the largest of theirs); otherwise it is the level the document's settings give
    // (uniform or adaptive, the same on both sides), raised to outer[e] (the largest own level of
    // the windows on the edge, 0 when none has one).
    std::array<float, 4> outer{0.0f, 0.0f, 0.0f, 0.0f};
    uint32_t fixedMask = 0;
    std::optional<std::array<float, 2>> inner;  // the window's own inner levels (triangles: one)
    bool operator==(const WindowLevels&) const = default;
};

// One entry per window of `windows` (expandPatches(doc)), then one per Bézier triangle. Edges are
// shared by their four pool indices (either direction) between Bézier windows and triangles;
// spline windows' edges are their own.
std::vector<WindowLevels> resolveEdgeLevels(const Document& doc, const std::vector<PatchInstance>& windows);

}  // namespace tess
}  // namespace pw

// Displacement of the model by a height map (DESIGN §11), the CPU side: where the map file is,
// the planar mapping, and per window and triangle what the shaders need (core/gpu/gpu_interface.h
// PatchData): the patch mapping's map rectangle, the own scale and bias, and per edge the map's
// detail along it for displacement-adaptive levels (core/gpu/patch_math.h displacementEdgeLevel).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/model/document.hpp"
#include "core/model/height_map.hpp"

namespace pw {
inline namespace eval {

// Where the document's map file is: absolute, or relative to the document's folder (the working
// directory for an unsaved document).
std::filesystem::path resolveMapPath(const DisplacementSettings& d, const std::filesystem::path& documentPath);

// The planar mapping's rectangle (x0, y0, width, height) over the ground plane (x-y for Z-up
// documents, x-z for Y-up): the document's own, or the bounds of its points (never zero-sized).
std::array<double, 4> planarRect(const Document& doc);
// The map UV of p under the planar mapping (the image upright seen from above).
std::array<double, 2> planarUv(const Vec3& p, const std::array<double, 4>& rect, bool zUp);

// Detail of the map along one edge, given as UV samples at equal parameter steps: the largest second
// difference of the heights per unit parameter squared (times |scale| it is world units: n straight
// segments miss the displaced edge by about detail / (8 n^2)), and how many texels the edge crosses.
struct EdgeDetail {
    double detail = 0.0;
    double texels = 0.0;
    // The detail at the map's mip levels 1..8 (band-limited displacement, core/gpu/patch_math.h
    // heightMapLod), measured like `detail` on each level; the coarsest level repeats past the chain's end.
    std::array<double, 8> coarser{};
};
EdgeDetail edgeDetail(const HeightMap& map, const std::vector<std::array<double, 2>>& uvs);
// The same with `coarser` filled from `mips` (heightMipChain(map, 8)).
EdgeDetail edgeDetail(const HeightMap& map, const std::vector<HeightMap>& mips, const std::vector<std::array<double, 2>>& uvs);

// The map's texels per world unit: exact under the planar mapping; under the patch mapping the
// least over the windows' edges of the texels they cross per unit of their length, so that no
// window samples a coarser level than its view shows (denser windows keep some detail finer than a
// pixel). 0 without a map.
double mapTexelsPerUnit(const Document& doc, const std::vector<PatchInstance>& windows, const HeightMap* map);

// What one window (or triangle) carries for displacement.
struct WindowDisplacement {
    std::array<float, 4> uvRect{0.0f, 0.0f, 1.0f, 1.0f};  // patch mapping: (u, v) -> mix(xy, zw)
    std::optional<DisplacementOverride> own;
    std::array<float, 4> detail{}, texels{};        // per edge (quads u0, v0, u1, v1; triangles 0, 1, 2)
    std::array<std::array<float, 8>, 4> coarser{};  // per edge, EdgeDetail::coarser
};
// Every window of expandPatches(doc) (`windows`), then every triangle. A shared edge gets the same
// detail on both sides (computed once per edge, keyed by the pool points its levels come from), so
// displacement-adaptive levels never open a crack. Without a map the details are zero.
// `mips`: the map's heightMipChain when the caller holds it already (the renderer's texture has it),
// else made here.
std::vector<WindowDisplacement> windowDisplacements(const Document& doc, const std::vector<PatchInstance>& windows, const HeightMap* map,
                                                    const std::vector<HeightMap>* mips = nullptr);

}  // namespace eval
}  // namespace pw

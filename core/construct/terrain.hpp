// The terrain of the lecture notes' Direct3D 12 demo (DESIGN §11): a flat B-spline net of n x n
// windows over a square, displaced by a height map under the planar mapping, with distance-adaptive
// levels and frustum culling; and the deterministic fractal height map it ships with
// (data/terrain.png; tests/test_terrain.cpp checks that data/ still holds exactly this).
#pragma once

#include "core/model/document.hpp"
#include "core/model/height_map.hpp"

namespace pw {
inline namespace construct {

struct TerrainSpec {
    int windows = 32;      // per side
    double size = 128.0;   // side of the square (model units), centred on the origin, z up
    float height = 14.0f;  // displacement scale (the map's white)
    std::string map = "terrain.png";
};

// The terrain document: camera looking across it from near the ground (bench --scene terrain also
// looks from far above), distance-adaptive levels up to 16 and off-screen culling.
Document makeTerrainDocument(const TerrainSpec& spec = {});
// size x size values of fractal value noise (eight octaves, a ridge, seeded): the same map on every
// machine.
HeightMap makeTerrainHeightMap(uint32_t size = 512, uint32_t seed = 7);

}  // namespace construct
}  // namespace pw

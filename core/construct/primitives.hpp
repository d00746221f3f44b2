// Exact primitives from rational bicubic Bézier patches (issue 21): sphere, cylinder, cone and
// torus as surfaces of revolution about the document's up axis. The profile (radius, height) is a
// chain of rational cubics: straight segments, and quarter circles, the quadratic arc of weights
// 1, √2/2, 1 raised to degree 3 (weights 1, (1 + √2)/3, (1 + √2)/3, 1). Each quarter turn about the
// axis is the same arc, so patch (segment s, quarter q) has points ρ_i·C_k + z_i·up and weights
// wp_i·wc_k, which is exactly the surface of revolution (Piegl & Tiller, The NURBS Book §8.5).
// Neighbouring patches share their seam points; on the axis (poles, apex, cap centres) each row
// collapses to shared points, one per weight. Normals point out of the solid; cylinder and cone
// are closed by flat caps, so every primitive is watertight. Every seam is joined: C1 where the
// surface is smooth across it (held while points are dragged), C0 at the rims' creases.
#pragma once

#include <cstdint>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace construct {

struct PrimitiveResult {
    std::vector<uint32_t> patches;  // the new patches
    std::vector<uint32_t> points;   // their pool points
};

PrimitiveResult addSphere(Document& doc, const Vec3& center, double radius, bool zUp);
// Radius and height; the base circle lies in the ground plane through `center`.
PrimitiveResult addCylinder(Document& doc, const Vec3& center, double radius, double height, bool zUp);
PrimitiveResult addCone(Document& doc, const Vec3& center, double radius, double height, bool zUp);
// Distance from the axis to the tube's centre, and the tube's radius (0 < minor < major).
PrimitiveResult addTorus(Document& doc, const Vec3& center, double major, double minor, bool zUp);

}  // namespace construct
}  // namespace pw

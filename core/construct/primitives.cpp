#include "core/construct/primitives.hpp"

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace pw {
inline namespace construct {

namespace {

// A point of the profile plane (radius from the axis, height along it) with its weight.
struct ProfilePoint {
    double rho = 0.0, z = 0.0, w = 1.0;
};
using Segment = std::array<ProfilePoint, 4>;

const double kHalfSqrt2 = std::sqrt(0.5);
const double kArcInnerWeight = (1.0 + 2.0 * kHalfSqrt2) / 3.0;

Segment line(double r0, double z0, double r1, double z1) {
    Segment s;
    for (int i = 0; i < 4; ++i) s[size_t(i)] = {r0 + (r1 - r0) * i / 3.0, z0 + (z1 - z0) * i / 3.0, 1.0};
    return s;
}

// The quarter circle about (cr, cz) of radius r from angle a·90° to (a + 1)·90°, counterclockwise
// in the (radius, height) plane: the quadratic arc P0, corner P1 (weight √2/2), P2 raised to a cubic.
Segment arc(double cr, double cz, double r, int a) {
    const double c0 = std::cos(a * M_PI / 2), s0 = std::sin(a * M_PI / 2);
    const double ca = std::round(c0), sa = std::round(s0);  // exact quarter angles
    const double p0r = cr + r * ca, p0z = cz + r * sa;
    const double p2r = cr - r * sa, p2z = cz + r * ca;
    const double p1r = cr + r * (ca - sa), p1z = cz + r * (sa + ca);
    const double k = 2.0 * kHalfSqrt2, d = 1.0 + k;
    return Segment{ProfilePoint{p0r, p0z, 1.0}, ProfilePoint{(p0r + k * p1r) / d, (p0z + k * p1z) / d, kArcInnerWeight},
                   ProfilePoint{(k * p1r + p2r) / d, (k * p1z + p2z) / d, kArcInnerWeight}, ProfilePoint{p2r, p2z, 1.0}};
}

// The unit quarter circle in the ground plane from angle q·90°: four points (e1, e2 coordinates) and weights.
std::array<ProfilePoint, 4> quarter(int q) { return arc(0.0, 0.0, 1.0, q); }

// Revolves the chain of segments (closed: the last ends where the first starts) about the up axis.
PrimitiveResult revolve(Document& doc, const Vec3& center, bool zUp, const std::vector<Segment>& profile, bool closedProfile,
                        const std::string& name) {
    const Vec3 e1 = zUp ? Vec3(1, 0, 0) : Vec3(0, 0, 1), e2 = zUp ? Vec3(0, 1, 0) : Vec3(1, 0, 0), up = zUp ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    const size_t profileCount = 3 * profile.size() + (closedProfile ? 0 : 1);
    if (doc.points.size() + profileCount * 12 > limits::kMaxPoints || doc.patches.size() + 4 * profile.size() > limits::kMaxPatches)
        throw EditError("the document is full (" + name + " needs " + std::to_string(4 * profile.size()) + " patches)");
    PrimitiveResult out;
    std::map<std::pair<size_t, size_t>, uint32_t> made;    // (profile point, turn point) → pool point
    std::map<std::pair<size_t, double>, uint32_t> onAxis;  // (profile point, weight) → pool point
    const auto point = [&](size_t g, size_t c, const ProfilePoint& pp, const ProfilePoint& cp) {
        const double w = pp.w * cp.w;
        if (pp.rho == 0.0) {  // on the axis: one point per weight
            if (const auto it = onAxis.find({g, w}); it != onAxis.end()) return it->second;
        } else if (const auto it = made.find({g, c}); it != made.end()) {
            return it->second;
        }
        const uint32_t i = uint32_t(doc.points.size());
        doc.points.push_back(center + pp.rho * (cp.rho * e1 + cp.z * e2) + pp.z * up);
        setPointWeight(doc, i, w);
        out.points.push_back(i);
        if (pp.rho == 0.0)
            onAxis[{g, w}] = i;
        else
            made[{g, c}] = i;
        return i;
    };
    const uint32_t first = uint32_t(doc.patches.size());
    for (size_t s = 0; s < profile.size(); ++s)
        for (int q = 0; q < 4; ++q) {
            const std::array<ProfilePoint, 4> turn = quarter(q);
            Patch p;
            for (size_t i = 0; i < 4; ++i)
                for (size_t k = 0; k < 4; ++k) {
                    const size_t g = (3 * s + i) % profileCount, c = (3 * size_t(q) + k) % 12;
                    p.idx[i * 4 + k] = point(g, c, profile[s][i], turn[k]);
                }
            p.name = name + " " + std::to_string(out.patches.size());
            out.patches.push_back(uint32_t(doc.patches.size()));
            doc.patches.push_back(std::move(p));
        }
    // Joins along every seam: C1 around the axis (consecutive quarter arcs are mirror images at
    // their joint, so the tangent rows continue with α = 1), and across the profile C1 where its
    // segments meet smoothly (arcs of one circle), C0 at a crease (the cylinder's rims, the cone's).
    const auto patchAt = [&](size_t s, int q) { return first + uint32_t(s * 4 + size_t(q)); };
    for (size_t s = 0; s < profile.size(); ++s)
        for (int q = 0; q < 4; ++q)
            doc.joins.push_back(Join{patchAt(s, q), Edge::U1, patchAt(s, (q + 1) % 4), Edge::U0, false, Continuity::C1, 1.0});
    for (size_t s = 0; s + (closedProfile ? 0 : 1) < profile.size(); ++s) {
        const Segment& a = profile[s];
        const Segment& b = profile[(s + 1) % profile.size()];
        const double dr = (a[3].rho - a[2].rho) - (b[1].rho - b[0].rho), dz = (a[3].z - a[2].z) - (b[1].z - b[0].z);
        const bool smooth = std::hypot(dr, dz) <= 1e-12 * (std::abs(a[3].rho) + std::abs(a[3].z) + 1.0) && a[2].w == b[1].w;
        for (int q = 0; q < 4; ++q)
            doc.joins.push_back(Join{patchAt(s, q), Edge::V1, patchAt((s + 1) % profile.size(), q), Edge::V0, false,
                                     smooth ? Continuity::C1 : Continuity::C0, 1.0});
    }
    return out;
}

void checkSize(double v, const char* what) {
    if (!(v > 0.0) || !(v <= limits::kMaxCoordinate)) throw EditError(std::string(what) + " must be a positive number up to 1e9");
}

}  // namespace

PrimitiveResult addSphere(Document& doc, const Vec3& center, double radius, bool zUp) {
    checkSize(radius, "the radius");
    return revolve(doc, center, zUp, {arc(0.0, 0.0, radius, 3), arc(0.0, 0.0, radius, 0)}, false, "sphere");
}

PrimitiveResult addCylinder(Document& doc, const Vec3& center, double radius, double height, bool zUp) {
    checkSize(radius, "the radius");
    checkSize(height, "the height");
    return revolve(doc, center, zUp, {line(0, 0, radius, 0), line(radius, 0, radius, height), line(radius, height, 0, height)}, false,
                   "cylinder");
}

PrimitiveResult addCone(Document& doc, const Vec3& center, double radius, double height, bool zUp) {
    checkSize(radius, "the radius");
    checkSize(height, "the height");
    return revolve(doc, center, zUp, {line(0, 0, radius, 0), line(radius, 0, 0, height)}, false, "cone");
}

PrimitiveResult addTorus(Document& doc, const Vec3& center, double major, double minor, bool zUp) {
    checkSize(major, "the major radius");
    checkSize(minor, "the minor radius");
    if (!(minor < major)) throw EditError("the tube's radius must be smaller than the distance to its centre (a torus without a hole)");
    return revolve(doc, center, zUp, {arc(major, 0, minor, 0), arc(major, 0, minor, 1), arc(major, 0, minor, 2), arc(major, 0, minor, 3)},
                   true, "torus");
}

}  // namespace construct
}  // namespace pw

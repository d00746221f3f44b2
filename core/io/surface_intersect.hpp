// Intersection curves of two surfaces (issue 64, `intersect A B`), through OpenCASCADE's
// GeomAPI_IntSS on the exact surfaces (a patch as its Bézier surface, a net as one B-spline
// surface), sampled, with each sample's point in both surfaces' domains.
#pragma once

#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace io {

struct IntersectionBranch {
    std::vector<Vec3> points;  // in order along the curve; a closed branch does not repeat its first point
    std::vector<UV> onA, onB;  // the same points in each surface's [0, 1]² domain
    bool closed = false;
};

// Every intersection curve of a and b, longest first. Throws EditError when OpenCASCADE fails.
std::vector<IntersectionBranch> intersectSurfaces(const Document& doc, const SurfaceRef& a, const SurfaceRef& b,
                                                  size_t samplesPerBranch = 160);

}  // namespace io
}  // namespace pw

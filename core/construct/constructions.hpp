// Surfaces from curves that stay live (issue 39): revolve, extrude, loft, edge surfaces, sweeps and
// curve networks (the nets: core/construct/construction_nets.hpp). A construction is
// stored in the document with its inputs (Construction in core/model/document.hpp) and its output,
// a Bézier control net whose 4x4 windows are ordinary joined patches; rerunConstructions() makes
// the net again from the inputs after every edit and every mouse move of a drag
// (core/edit/live_constructions.hpp holds the joins to other patches while it does).
//
// Every construction is exact in its own terms: a revolve is the rational surface of revolution of
// its profile (the profile's points ρ·C_k about the axis, C_k a rational arc of at most 90° per
// segment, weights multiplied; Piegl & Tiller §8.5), an extrude is the profile swept straight along
// a vector, and a loft passes through every section: each column of control points is the C2
// cubic spline through the sections' columns at chord-length parameters, in homogeneous
// coordinates (so rational sections are reproduced too). An edge surface is the bilinearly blended
// Coons patch of 2 to 4 boundaries (2: ruled) on the control nets, again homogeneous, which holds
// each boundary exactly and shares its points: a patch edge used as a side is joined (C0) to it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/construct/curves.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace construct {

// The input as a Bézier chain: a curve's points, or a patch edge's four.
CurveShape inputShape(const Document& doc, const CurveInput& in);
// For a patch edge: the patch's row `depth` rows inward from it (1: the tangent row; homogeneous,
// along the edge); empty for a curve.
std::vector<HPoint> inputTangentRow(const Document& doc, const CurveInput& in, int depth = 1);

// A made control net: rows x cols homogeneous points, row-major; a closed direction repeats its
// first row (closedV) or column (closedU) at the end.
struct ConstructedNet {
    uint32_t rows = 0, cols = 0;
    std::vector<HPoint> points;
    bool closedU = false, closedV = false;
    // Seams between neighbouring windows across u that hold G1 by construction (revolve: the
    // rotation's arcs meet with equal tangents, α = 1); every other seam is C0.
    bool smoothU = false;
    // The joins between neighbouring windows across v (a blend's spans: C2); else C0.
    Continuity seamV = Continuity::C0;
    // Per net point: the pool point it is (an input's own point on a boundary the net shares with
    // it: an edge surface's sides), or -1 for a point of its own.
    std::vector<int64_t> shared;
};

// The net of a construction from the document's inputs as they are now; EditError says why when
// they do not fit (sections of different segment counts, a profile on its axis, ...).
ConstructedNet evaluateConstruction(const Document& doc, const Construction& c);

// Makes a construction: its net's points, its patches (named `name` 0, 1, ...) and the joins
// between them; returns its index. EditError, changing nothing, when the inputs do not fit.
size_t addConstruction(Document& doc, Construction c, const std::string& name);

struct RerunReport {
    std::vector<uint32_t> moved;      // pool points whose position or weight changed
    std::vector<std::string> failed;  // "loft k1 from c0 c2: ..." for constructions whose inputs no longer fit
    std::vector<std::string> baked;   // constructions detached because their patches were rebuilt by hand
};
// Makes every live construction again from its inputs. One whose inputs no longer fit keeps its
// last surface and records why in its `error` (cleared once they fit again); one whose patches no
// longer are its net's windows (split, flipped, unjoined by hand) is baked.
RerunReport rerunConstructions(Document& doc);

}  // namespace construct
}  // namespace pw

// The net of each kind of construction from its inputs (core/construct/constructions.hpp makes,
// stores and re-runs them): one function per kind, EditError saying why when the inputs do not fit.
//   construction_nets.cpp: revolve, extrude, loft, edge surface
//   sweep_nets.cpp:        sweep1 (one rail), sweep2 (two rails)
//   network_net.cpp:       network (Gordon surface of a curve network)
//   blend_net.cpp:         blend (bridging two patch edges, G1 or G2 at both)
#pragma once

#include <string>

#include "core/construct/constructions.hpp"

namespace pw {
inline namespace construct {

ConstructedNet revolveNet(const Document& doc, const Construction& c);
ConstructedNet extrudeNet(const Document& doc, const Construction& c);
ConstructedNet loftNet(const Document& doc, const Construction& c);
ConstructedNet edgeSurfaceNet(const Document& doc, const Construction& c);
// sweep1's rail is split into c.split pieces a segment (at least 1) for the frames to sit on.
ConstructedNet sweep1Net(const Document& doc, const Construction& c);
// The fewest pieces a rail segment (1, 2, 4, ... up to kMaxSweepPieces) for which sweep1 stays
// within `tolerance` of the exact sweep (the profile in the rotation-minimising frame) at every
// segment's middle.
uint32_t sweep1Pieces(const Document& doc, Construction c, double tolerance);
ConstructedNet sweep2Net(const Document& doc, const Construction& c);
ConstructedNet networkNet(const Document& doc, const Construction& c);
// A blend between two open patch edges (Rhino's BlendSrf, issue 40): G1, one bicubic span whose
// first two rows continue the first patch's tangent rows (B1 = B0 + α (A0 − A1)) and last two the
// second's; G2, three spans of one cubic B-spline across (C2 inside), the first three rows from the
// first patch's curvature condition (β2 = 0), the last three from the second's. The rows share the
// edges' points; the end points pair the nearer way and the blend's normal agrees with the first
// patch's (kept from the made net on later runs). EditError when the second patch faces the other
// way across it, the edges meet, or a tangent row has collapsed.
ConstructedNet blendNet(const Document& doc, const Construction& c);
// Each end's α for a new blend: its tangent rows a third of a span of the mean gap between the edges.
void chooseBlendAlphas(const Document& doc, Construction& c);

// A network's curves meet at their segment ends; makeNetworkCorners() lets each meeting be one pool
// point, so that dragging it moves both curves and the network stays compatible: the V curve takes
// the U curve's point, or, where the V input is a patch edge, the U curve takes the edge's. Where
// both are patch edges their points stay their patches' (the surface shares the U edge's).
void makeNetworkCorners(Document& doc, const Construction& c);

// "1 segment", "3 segments"
inline std::string segmentsWord(size_t n) { return std::to_string(n) + (n == 1 ? " segment" : " segments"); }

}  // namespace construct
}  // namespace pw

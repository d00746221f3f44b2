// The net of each kind of construction from its inputs (core/construct/constructions.hpp makes,
// stores and re-runs them): one function per kind, EditError saying why when the inputs do not fit.
//   construction_nets.cpp: revolve, extrude, loft, edge surface
//   sweep_nets.cpp:        sweep1 (one rail), sweep2 (two rails)
//   network_net.cpp:       network (Gordon surface of a curve network)
#pragma once

#include <string>

#include "core/construct/constructions.hpp"

namespace pw {

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

// A network's curves meet at their segment ends; makeNetworkCorners() lets each meeting be one pool
// point, so that dragging it moves both curves and the network stays compatible: the V curve takes
// the U curve's point, or, where the V input is a patch edge, the U curve takes the edge's. Where
// both are patch edges their points stay their patches' (the surface shares the U edge's).
void makeNetworkCorners(Document& doc, const Construction& c);

// "1 segment", "3 segments"
inline std::string segmentsWord(size_t n) { return std::to_string(n) + (n == 1 ? " segment" : " segments"); }

}  // namespace pw

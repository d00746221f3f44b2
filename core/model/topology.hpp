// How the document's pieces connect, as queries the layers above share (the solver, picking and the
// operations): the join on a patch edge, the C1 seams that a Bézier net keeps by itself, and how two
// patch edges pair up and face.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace model {

// Index of a join that uses edge e of patch p (of triangle p for a triangle edge), or -1.
int findJoin(const Document& doc, uint32_t p, Edge e);

// The join on every patch and triangle edge, built once in O(joins + items): what a pass over
// every edge asks instead of findJoin, which scans the joins (a load of 65 536 patches spent 82 %
// of its time there). at() is the join's index or -1; add() records a join appended later.
class EdgeJoinIndex {
public:
    explicit EdgeJoinIndex(const Document& doc);
    int at(uint32_t item, Edge e) const;
    void add(const Join& j, size_t index);

private:
    std::vector<std::array<int32_t, 4>> quads_;
    std::vector<std::array<int32_t, 3>> triangles_;
    void set(uint32_t item, Edge e, int32_t index);
};

// A join's side A (or B) in messages, "patch 3 u0" or "triangle 2 e1", and as a command argument,
// "3:u0" or "t2:e1".
std::string joinSideName(const Join& j, bool sideB);
std::string joinSideName(uint32_t item, Edge e);
std::string joinSideRef(const Join& j, bool sideB);
std::string joinSideRef(uint32_t item, Edge e);

// The four pool indices along edge e of patch p, or of triangle p for a triangle edge, in that
// item's own order; empty when the item does not exist.
std::vector<uint32_t> edgePoolOf(const Document& doc, uint32_t p, Edge e);

// The C1 conditions of Bézier nets that keep C1, as triples (before, seam, after) of pool indices
// with seam = (before + after) / 2 (rows of the constraint solver).
std::vector<std::array<uint32_t, 3>> netC1Triples(const Document& doc);

// +1 when walking edge e with k increasing runs counter-clockwise around the (u, v) square (the
// boundary loop of the normal du × dv), -1 when it runs clockwise. Two patches' normals agree
// across a seam when their loops walk it in opposite directions.
int edgeLoopSign(Edge e);

// The nearer way to pair the end points of a's edge ea with b's edge eb (true: k with 3 - k).
bool edgesPairReversed(const Document& doc, uint32_t a, Edge ea, uint32_t b, Edge eb);

}  // namespace model
}  // namespace pw

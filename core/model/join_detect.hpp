// Finds joins between patches that share a boundary curve in the pool: C0 where the four edge
// indices coincide (same or reversed order); C1 or G1 (with the ratio alpha) where the cross-
// boundary control rows are also collinear with a constant ratio along the edge.
#pragma once

#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace model {

// Defaults absorb coordinates rounded to ~4-6 significant decimals (the tea set); see join_detect.cpp.
struct JoinDetectOptions {
    double relativeTolerance = 1e-4;  // × model size: largest |b_k - alpha·a_k| (collinearity, constant ratio)
    double c1RatioTolerance = 1e-4;   // |alpha - 1| at most this (and |b_k - a_k| within tolerance) is C1
};

// An edge whose pool indices more than two patch sides share (a fin, or stacked copies of one
// patch) is non-manifold: no pair of them is joined (any two could be, so none is; and n stacked
// copies would otherwise give n² joins). `nonManifoldEdges`, when given, receives their number.
std::vector<Join> detectJoins(const Document& doc, JoinDetectOptions options = {}, size_t* nonManifoldEdges = nullptr);

// Pool entries with bit-identical coordinates (-0.0 counting as +0.0) merged into one, keeping the
// first; patch and surface indices rewritten. With a tolerance > 0, a point within that distance of
// an earlier kept one merges into it (files whose shared corners differ in the last digits: STEP);
// a point of another weight within it keeps its own entry but moves onto the kept one's position.
void mergeCoincidentPoints(Document& doc, double tolerance = 0.0);

}  // namespace model
}  // namespace pw

// Live constructions inside edits (issue 39): after every edit the surfaces made from curves are
// made again from their inputs (core/construct/constructions.hpp) and the joins from their patches
// to other patches are held by the solver, with the made surfaces and their inputs fixed, so that
// the neighbours follow. The drag controller does the same on every mouse move.
#pragma once

#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace edit {

// The points a solve must keep where the constructions put them: every made net's points and
// every input's points. Sorted, unique.
std::vector<uint32_t> constructionFixedPoints(const Document& doc);
// `driven` (the points a transform moves) and those, sorted and unique: a drag's fixed points.
std::vector<uint32_t> withConstructionPoints(const Document& doc, std::vector<uint32_t> driven);

// Re-runs the constructions of `doc` and holds the joins, then the live trims (core/edit/live_trims.hpp). Throws EditError naming the joins
// when they cannot hold with the new surfaces (the caller keeps its document). Returns notes for the status line: constructions whose
// inputs no longer fit, constructions baked.
std::vector<std::string> refreshConstructions(Document& doc);

// "" or why points may not be moved by hand: they are made by a live construction ("patch 3 is
// made by revolve k0 from c1: move c1, or `bake` it to edit its points").
std::string constructedPointsRefusal(const Document& doc, const std::vector<uint32_t>& points);

}  // namespace edit
}  // namespace pw

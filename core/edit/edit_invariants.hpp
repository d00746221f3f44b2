// What every accepted edit keeps (issues 40 and 44; DESIGN §1): every join within its tolerance,
// and no join held by folding. EditSession::apply checks each edit's result against the document
// before it and refuses (EditError, the document untouched) an edit that breaks either, naming the
// joins or the folded patch. (The operations that join refuse folds first with the reason that
// fits them — core/ops/join_ops, corner_ops, triangle_joins; this is the one place every edit
// passes.)
#pragma once

#include <cstdint>
#include <string>

#include "core/model/document.hpp"

namespace pw {
inline namespace edit {

// The residual every join must stay within after an edit: 1e-6 × model size.
double joinTolerance(const Document& doc);

// "join 2 (patch 0 u0 – patch 2 v0, G1)"
std::string describeJoin(const Document& doc, size_t j);

// Throws EditError when `after` leaves a join outside joinTolerance, unless the document before
// was already that far off and the edit made it no worse; when a join it measures along the seam
// is out of the document's tolerances; or when it folds a patch or triangle it reshaped
// (turned-over triangles or a collapsed corner it did not have) or makes a new one turned over.
// What an edit brings in besides its own work: joins found by join detection (a mirror's, an
// import's), held to detection's own tolerance (1e-4 × model size) like a file that is opened; and
// for an import, surfaces whose shapes are the file's own (not checked for folds).
enum class Brought : uint8_t { Nothing, DetectedJoins, File };

void checkEditInvariants(const Document& before, const Document& after, Brought brought = Brought::Nothing);

}  // namespace edit
}  // namespace pw

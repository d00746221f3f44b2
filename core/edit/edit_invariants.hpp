// What every accepted edit keeps (issues 40 and 44; DESIGN §1): every join within its tolerance,
// and no join held by folding. EditSession::apply checks each edit's result against the document
// before it and refuses (EditError, the document untouched) an edit that breaks either, naming the
// joins or the folded patch. (The operations that join refuse folds first with the reason that
// fits them — core/ops/join_ops, corner_ops, triangle_joins; this is the one place every edit
// passes.)
#pragma once

#include <string>

#include "core/model/document.hpp"

namespace pw {
inline namespace edit {

// The residual every join must stay within after an edit: 1e-6 × model size.
double joinTolerance(const Document& doc);

// "join 2 (patch 0 u0 – patch 2 v0, G1)"
std::string describeJoin(const Document& doc, size_t j);

// Throws EditError when `after` leaves a join outside joinTolerance, unless the document before
// was already that far off and the edit made it no worse; or when it adds or changes a join and
// folds a patch or triangle (turned-over triangles or a collapsed corner it did not have). `detected`: the edit brought in joins
// found by join detection (import, mirror), held to detection's own tolerance (1e-4 × model size).
void checkEditInvariants(const Document& before, const Document& after, bool detected = false);

}  // namespace edit
}  // namespace pw

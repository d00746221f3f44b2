// Bookkeeping of live constructions (Construction in core/model/document.hpp, issue 39): their
// input references as words ("c3", "2:u0"), what happens to them when patches or curves are
// deleted, and `bake` (Rhino's history break: the patches stay, the link to the inputs goes).
// Making and re-running them is core/construct/constructions.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace model {

// "c3" for a curve, "2:u0" for a patch edge.
std::string curveInputName(const CurveInput& in);
// Parses one; EditError naming the word when it is neither or refers to nothing.
CurveInput parseCurveInput(const Document& doc, const std::string& word);

// The pool points of an input in its own order: a curve's, or a patch edge's four (none when it
// refers to nothing).
std::vector<uint32_t> curveInputPoints(const Document& doc, const CurveInput& in);

// "revolve k0 from c1" for the outliner and messages.
std::string constructionLabel(const Document& doc, size_t k);

// The construction that made patch p (its index), or -1.
int constructionOfPatch(const Document& doc, uint32_t p);
// True when point i is an output of a live construction and no input's (the inputs' own points,
// a lofted edge for instance, may be shared with the output).
bool constructedOnly(const Document& doc, uint32_t i);

// Detaches construction k: its patches become ordinary patches.
void bakeConstruction(Document& doc, size_t k);
// Before patch p or curve c is erased: constructions made of or from it are baked (their label
// in `baked`, when given), the others renumbered for the erased index.
void dropPatchFromConstructions(Document& doc, uint32_t p, std::vector<std::string>* baked = nullptr);
void dropCurveFromConstructions(Document& doc, uint32_t c, std::vector<std::string>* baked = nullptr);

}  // namespace model
}  // namespace pw

// Selection for real models (Blender's L, A, Ctrl+I, H, Shift+H, Alt+H), pure: select what is
// linked to the selection, invert it, hide and reveal items, and the document as it is shown (hidden
// items left out) for drawing and picking. Hidden items are flags of the document's patches, nets,
// triangles and curves, saved with it and undone like any edit.
#pragma once

#include <cstdint>
#include <vector>

#include "core/model/document.hpp"
#include "core/select/selection.hpp"

namespace pw {
inline namespace select {

bool anyHidden(const Document& doc);
// The document without its hidden items (joins between shown patches kept, renumbered); the point
// pool is the same, so pool indices, selections and partial uploads still apply.
Document visibleDocument(const Document& doc);
// Pool points used by a shown item.
std::vector<bool> visiblePointMask(const Document& doc);

// Every shown point of every item connected to the selection through shared points (a joined
// group, a net, triangles meeting a patch), the selection's own points too.
std::vector<uint32_t> linkedPoints(const Document& doc, const std::vector<uint32_t>& selected);
// The shown points that are not selected.
std::vector<uint32_t> invertedPoints(const Document& doc, const std::vector<uint32_t>& selected);

// Hides the items the selection covers (the selected patch, net, triangle or curve, and every item
// whose points are all selected), or with `unselected` every shown item it does not touch.
// Returns how many items were hidden.
size_t hideItems(Document& doc, const Selection& sel, const std::vector<uint32_t>& selected, bool unselected);
// Shows every hidden item; returns the points of the items revealed (Blender selects them).
std::vector<uint32_t> revealItems(Document& doc);

}  // namespace select
}  // namespace pw

// What a CAD face is called in a file Patchwork writes: the item's own name, or its place in the
// document ("patch 12", "net 3", "triangle 0": how `info`, the commands and the panels number
// them), so that an import puts every face back in its place (a sewn shell lists its faces
// together, so the file alone would renumber a document whose shells interleave) and a CAD user
// can tell which face is which item.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pw {
inline namespace io {

// `name`, or "`kind` `index`" when it is empty.
std::string cadFaceName(std::string_view kind, size_t index, const std::string& name);

// N when `name` is exactly "`kind` N" (a place, not a name), nullopt otherwise.
std::optional<size_t> cadFaceLabelIndex(std::string_view name, std::string_view kind);

// The name of a part (a sewn shell or solid) from the names the user gave its items (empty ones
// left out): what they have in common, without a trailing numbering, spaces and separators ("lid 0",
// "lid 1" → "lid"; "rim front", "rim back" → "rim"; "patch10", "patch11" → "patch"), keeping digits
// that are part of the name ("M8", "bolt M8 0" and "bolt M8 1" → "bolt M8"); empty when there is none.
std::string cadPartName(const std::vector<std::string>& itemNames);

// A name as a CAD file can hold it (issue 73: a 1 300-character name smashed the stack of
// OpenCASCADE's IGES writer; 30 000 characters, or 10 000 × "é", gave STEP files nothing could read):
// control characters (a newline) become spaces; at most `maxBytes` bytes, cut between UTF-8
// characters; with `asciiOnly` (IGES) every other character becomes '_'.
inline constexpr size_t kMaxStepNameBytes = 200, kMaxIgesNameBytes = 64;
std::string cadSafeName(std::string_view name, size_t maxBytes, bool asciiOnly);

// Puts each item with a place at that place and the others, in their order, in the places left.
// Leaves the order as it is when the places are not distinct and within the items.
template <class T>
void placeByLabel(std::vector<T>& items, const std::vector<std::optional<size_t>>& places) {
    const size_t n = items.size();
    if (places.size() != n) return;
    std::vector<int> taken(n, -1);
    for (size_t k = 0; k < n; ++k)
        if (places[k]) {
            if (*places[k] >= n || taken[*places[k]] >= 0) return;
            taken[*places[k]] = int(k);
        }
    size_t next = 0;
    for (size_t k = 0; k < n; ++k)
        if (!places[k]) {
            while (taken[next] >= 0) ++next;
            taken[next] = int(k);
        }
    std::vector<T> out;
    out.reserve(n);
    for (int k : taken) out.push_back(std::move(items[size_t(k)]));
    items = std::move(out);
}

}  // namespace io
}  // namespace pw

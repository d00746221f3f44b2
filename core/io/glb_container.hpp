// The GLB container (glTF 2.0, section 4.4): a 12-byte header, a JSON chunk, an optional BIN chunk.
// Split with every length checked (InputError naming the file), and joined again around new JSON
// (the exporter splices the document into the JSON; the importer hands the glTF reader the file
// without it).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pw {
inline namespace io {

struct GlbParts {
    std::string_view json;  // the JSON chunk's bytes (padding included)
    std::string_view rest;  // every chunk after it (the BIN chunk with its header), as stored
};

GlbParts splitGlb(std::string_view file, const std::string& sourceName);

// The data size of the BIN chunk that starts `rest` (0 when there is none); InputError when the
// chunk says more than the file holds.
size_t binChunkBytes(std::string_view rest, const std::string& sourceName);

// A GLB of `json` (padded with spaces to 4 bytes) followed by `rest` as split. Trailing spaces
// `json` already has (a split chunk's padding) are dropped first, so the bytes depend on the JSON
// alone. Throws std::length_error past the 4 GiB a GLB can describe.
std::string joinGlb(std::string json, std::string_view rest);
// The same with `rest` given in pieces, written one after another (an exporter's BIN chunk straight
// from its arrays, with no copy of it first).
std::string joinGlb(std::string json, const std::vector<std::string_view>& rest);
// The header and JSON chunk of that GLB alone, for `restBytes` bytes following it: what a writer
// streams before the pieces (joinGlb is this and the pieces).
std::string glbHead(std::string json, size_t restBytes);

}  // namespace io
}  // namespace pw

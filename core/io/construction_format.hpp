// Live constructions in a .patchwork file (issue 39): the "constructions" array, one object per
// construction with its kind, inputs ("c0", "2:u1"), parameters, its net (rows, cols, grid) and
// its patches. The reader checks every reference and that each patch is its net's window, so a
// file read back is live exactly as it was written.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "core/base/json_reader.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace io {

nlohmann::json constructionsJson(const Document& doc);
// Reads `v` (the "constructions" array) into doc.constructions; doc's points, patches and curves
// are already read. InputError naming the field for anything that does not fit.
void readConstructions(const json_reader::Reader& r, const nlohmann::json& v, Document& doc);

}  // namespace io
}  // namespace pw

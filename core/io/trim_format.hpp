// Trim loops and live curves in .patchwork (issue 64; docs/FILE_FORMAT.md "trims", "link"): written
// only where there are some, so documents without trims serialise as before; read with each loop
// checked (closed, inside the domain, not crossing) and every reference checked.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "core/base/json_reader.hpp"
#include "core/model/document.hpp"

namespace pw {
inline namespace io {

nlohmann::json trimsJson(const std::vector<TrimLoop>& loops);
void readTrims(const json_reader::Reader& r, const nlohmann::json& v, const std::string& path, std::vector<TrimLoop>& loops);
nlohmann::json curveLinkJson(const CurveLink& l);
CurveLink readCurveLink(const json_reader::Reader& r, const nlohmann::json& v, const std::string& path);
// After the whole document is read: every curve and surface a loop or link names exists.
void checkTrimReferences(const json_reader::Reader& r, const Document& doc);

}  // namespace io
}  // namespace pw

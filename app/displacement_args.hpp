// The displacement options of render, export, sweep and bench (DESIGN §11): --displacement FILE
// --displacement-scale S [--displacement-bias B] [--displacement-mapping planar|patch], applied on
// top of the document's own displacement, and the height map they name loaded once.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <string>

#include "core/model/document.hpp"
#include "core/model/height_map.hpp"

namespace pw::app {

struct DisplacementArgs {
    std::string file, scale, bias, mapping, heightDetail;
};

void addDisplacementOptions(CLI::App* cmd, DisplacementArgs& a);
// The options on top of doc.displacement (a given FILE is made absolute, so the document keeps
// naming it wherever it is saved); InputError naming the command and option on a bad value.
void applyDisplacementArgs(const std::string& command, const DisplacementArgs& a, Document& doc);
// The document's height map (its path relative to `documentPath`'s folder), or null when the
// document has no displacement; InputError naming the map file when it cannot be read.
std::shared_ptr<const HeightMap> loadDocumentHeightMap(const Document& doc, const std::filesystem::path& documentPath);

}  // namespace pw::app

#include "app/displacement_args.hpp"

#include "app/level_args.hpp"
#include "core/eval/displacement.hpp"

namespace pw::app {

void addDisplacementOptions(CLI::App* cmd, DisplacementArgs& a) {
    cmd->add_option("--displacement", a.file, "Height map (8- or 16-bit PNG) displacing the surface along its normal");
    cmd->add_option("--displacement-scale", a.scale, "Displacement: height of the map's white over its black (model units)");
    cmd->add_option("--displacement-bias", a.bias, "Displacement: height of the map's black (model units, default 0)");
    cmd->add_option("--displacement-mapping", a.mapping,
                    "Displacement UVs: planar (over the ground plane) | patch (each patch's parameters)");
    cmd->add_option("--height-detail", a.heightDetail,
                    "on (default) | off: whether the height map's detail, band-limited to what the view shows, raises adaptive "
                    "levels (off: the distance or screen formula alone, the full map only moves the vertices)");
}

void applyDisplacementArgs(const std::string& command, const DisplacementArgs& a, Document& doc) {
    DisplacementSettings& d = doc.displacement;
    if (!a.file.empty()) d.map = std::filesystem::absolute(a.file).lexically_normal().string();
    if (!a.scale.empty()) d.scale = float(parseNumber(command, "--displacement-scale", a.scale, -1e9, 1e9));
    if (!a.bias.empty()) d.bias = float(parseNumber(command, "--displacement-bias", a.bias, -1e9, 1e9));
    if (!a.mapping.empty()) {
        const auto m = parseDisplacementMapping(a.mapping);
        if (!m) badOption(command, "--displacement-mapping", "'" + a.mapping + "' is not planar or patch");
        d.mapping = *m;
    }
    if (!a.heightDetail.empty()) {
        if (a.heightDetail != "on" && a.heightDetail != "off")
            badOption(command, "--height-detail", "'" + a.heightDetail + "' is not on or off");
        doc.tess.heightDetail = a.heightDetail == "on";
    }
    if (a.file.empty() && (!a.scale.empty() || !a.bias.empty() || !a.mapping.empty()) && !d.active())
        badOption(command, a.scale.empty() ? (a.bias.empty() ? "--displacement-mapping" : "--displacement-bias") : "--displacement-scale",
                  "the document has no height map; give one with --displacement FILE");
}

std::shared_ptr<const HeightMap> loadDocumentHeightMap(const Document& doc, const std::filesystem::path& documentPath) {
    if (!doc.displacement.active()) return nullptr;
    return std::make_shared<const HeightMap>(loadHeightMap(resolveMapPath(doc.displacement, documentPath)));
}

}  // namespace pw::app

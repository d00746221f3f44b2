// `patchwork info FILE`: counts, bounds, joins by continuity, and the measured continuity of every
// join (C0 gap, C1 residual, seam normal angle) with the largest constraint residual.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/commands.hpp"
#include "core/errors.hpp"
#include "core/constraint_solver.hpp"
#include "core/continuity_report.hpp"
#include "core/document_io.hpp"

namespace pw::app {

namespace {

struct InfoOptions {
    std::string file;
    bool json = false;
    bool noJoins = false;  // omit the per-join table
    int samples = 32;
};

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string vec(const Vec3& v) { return "(" + fmt("%.6g", v.x) + ", " + fmt("%.6g", v.y) + ", " + fmt("%.6g", v.z) + ")"; }

int runInfo(const InfoOptions& opt) {
    const Document doc = loadDocument(opt.file);
    const std::vector<PatchInstance> windows = expandPatches(doc);
    const Bounds bounds = computeBounds(doc.points);
    const double size = modelSize(doc);
    size_t byKind[3] = {0, 0, 0};
    for (const Join& j : doc.joins) ++byKind[static_cast<int>(j.continuity)];
    const std::vector<JoinContinuity> report = continuityReport(doc, opt.samples);
    JoinContinuity worst;
    for (const JoinContinuity& c : report) {
        worst.c0Gap = std::max(worst.c0Gap, c.c0Gap);
        // The C1 residual only means something where the join asks for C1/G1.
        if (doc.joins[c.join].continuity != Continuity::C0) worst.c1Residual = std::max(worst.c1Residual, c.c1Residual);
        worst.normalAngleDeg = std::max(worst.normalAngleDeg, c.normalAngleDeg);
    }
    const double residual = maxConstraintResidual(doc);

    if (opt.json) {
        using nlohmann::json;
        json j{{"file", opt.file},
               {"name", doc.name},
               {"points", doc.points.size()},
               {"patches", doc.patches.size()},
               {"surfaces", doc.surfaces.size()},
               {"triangles", doc.triangles.size()},
               {"curves", doc.curves.size()},
               {"windows", windows.size()},
               {"joins", {{"total", doc.joins.size()}, {"C0", byKind[0]}, {"C1", byKind[1]}, {"G1", byKind[2]}}},
               {"modelSize", bounds.empty ? 0.0 : bounds.diagonal()},
               {"maxConstraintResidual", residual},
               {"largest", {{"c0Gap", worst.c0Gap}, {"c1Residual", worst.c1Residual}, {"normalAngleDeg", worst.normalAngleDeg}}}};
        if (!bounds.empty)
            j["bounds"] = {{"min", {bounds.min.x, bounds.min.y, bounds.min.z}}, {"max", {bounds.max.x, bounds.max.y, bounds.max.z}}};
        else
            j["bounds"] = nullptr;
        json joins = json::array();
        for (const JoinContinuity& c : report) {
            const Join& jn = doc.joins[c.join];
            joins.push_back({{"a", jn.patchA},
                             {"edgeA", edgeName(jn.edgeA)},
                             {"b", jn.patchB},
                             {"edgeB", edgeName(jn.edgeB)},
                             {"reversed", jn.reversed},
                             {"continuity", continuityName(jn.continuity)},
                             {"alpha", jn.alpha},
                             {"c0Gap", c.c0Gap},
                             {"c1Residual", c.c1Residual},
                             {"normalAngleDeg", c.normalAngleDeg}});
        }
        j["joinReport"] = std::move(joins);
        std::cout << j.dump(2, ' ', false, json::error_handler_t::replace) << "\n";
        return 0;
    }

    std::cout << printable(opt.file) << (doc.name.empty() ? "" : "  (\"" + printable(doc.name) + "\")") << "\n";
    std::cout << "  points      " << doc.points.size() << "\n";
    std::cout << "  patches     " << doc.patches.size() << "\n";
    std::cout << "  surfaces    " << doc.surfaces.size() << "\n";
    std::cout << "  triangles   " << doc.triangles.size() << "  (cubic Bézier triangles)\n";
    std::cout << "  curves      " << doc.curves.size() << "  (cubic Bézier curves)\n";
    std::cout << "  windows     " << windows.size() << "  (patches + surface windows)\n";
    std::cout << "  joins       " << doc.joins.size() << "  (C0 " << byKind[0] << ", C1 " << byKind[1] << ", G1 "
              << byKind[2] << ")\n";
    if (bounds.empty)
        std::cout << "  bounds      (empty)\n";
    else
        std::cout << "  bounds      min " << vec(bounds.min) << "  max " << vec(bounds.max) << "\n";
    std::cout << "  model size  " << fmt("%.6g", bounds.empty ? 0.0 : bounds.diagonal()) << "  (bounding-box diagonal)\n";
    std::cout << "  largest C0 gap            " << fmt("%.3g", worst.c0Gap) << "\n";
    std::cout << "  largest C1 residual       " << fmt("%.3g", worst.c1Residual) << "  (C1/G1 joins)\n";
    std::cout << "  largest seam normal angle " << fmt("%.3g", worst.normalAngleDeg) << " deg\n";
    std::cout << "  max constraint residual   " << fmt("%.3g", residual) << "  (" << fmt("%.3g", residual / size)
              << " x model size; edits keep it <= 1e-6)\n";

    if (!opt.noJoins && !report.empty()) {
        std::cout << "\n  join  patch edge  patch edge  rev  cont   alpha      C0 gap     C1 resid   normal deg\n";
        for (const JoinContinuity& c : report) {
            const Join& jn = doc.joins[c.join];
            char line[200];
            std::snprintf(line, sizeof line, "  %4zu  %5u %-4s  %5u %-4s  %-3s  %-4s %9.6g  %9.3g  %9.3g  %9.3g\n", c.join,
                          jn.patchA, std::string(edgeName(jn.edgeA)).c_str(), jn.patchB,
                          std::string(edgeName(jn.edgeB)).c_str(), jn.reversed ? "yes" : "no",
                          std::string(continuityName(jn.continuity)).c_str(), jn.alpha, c.c0Gap, c.c1Residual,
                          c.normalAngleDeg);
            std::cout << line;
        }
    }
    return 0;
}

}  // namespace

void registerInfoCommand(CLI::App& app, Action& run) {
    const auto [cmd, opt] = addSubcommand<InfoOptions>(app, run, "info", "Print counts, bounds, joins and measured continuity of a document", runInfo);
    cmd->add_option("file", opt->file, "Document (.patchwork, .bpt, .gltf, .glb)")->required();
    cmd->add_flag("--json", opt->json, "Machine-readable output (JSON)");
    cmd->add_option("--samples", opt->samples, "Samples per seam for the continuity report")
        ->default_val(32)
        ->check(CLI::Range(1, 4096));
    cmd->add_flag("--no-joins", opt->noJoins, "Omit the per-join table");
}

}  // namespace pw::app

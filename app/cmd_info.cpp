// `patchwork info FILE`: counts, bounds (of the control points and of the surface), joins by
// continuity, and the measured continuity of every join (C0 gap, seam normal angle, curvature
// deviation across the seam, control-point residuals),
// checked against the document's tolerances, with the largest constraint residual.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/displacement_args.hpp"
#include "core/base/errors.hpp"
#include "core/construct/constructions.hpp"
#include "core/edit/live_trims.hpp"
#include "core/io/document_io.hpp"
#include "core/io/formats.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/model/construction_refs.hpp"
#include "core/solve/constraint_solver.hpp"
#include "core/solve/continuity_report.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"

namespace pw::app {

namespace {

struct InfoOptions {
    std::string file;
    bool json = false;
    bool noJoins = false;  // omit the per-join table
    int samples = 32;
    bool partial = false;
};

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string vec(const Vec3& v) { return "(" + fmt("%.6g", v.x) + ", " + fmt("%.6g", v.y) + ", " + fmt("%.6g", v.z) + ")"; }

int runInfo(const InfoOptions& opt) {
    LoadReport loadReport;
    const Document doc = loadDocument(opt.file, &loadReport, opt.partial);
    for (const std::string& note : loadReport.notes) std::cerr << "patchwork info: " << opt.file << ": " << note << "\n";
    (void)loadDocumentHeightMap(doc, opt.file);  // the document's height map must read too (issue 44: not only on export)
    const std::vector<PatchInstance> windows = expandPatches(doc);
    const Bounds bounds = computeBounds(doc.points);
    // The surface's own box (the control box holds it but can be larger: the teapot's spout
    // reaches x = 3.43, its control points 3.525), from the surface at level 8; skipped for very
    // large documents, where the tessellation would cost more than the rest of `info`.
    constexpr size_t kSurfaceBoundsMaxWindows = 20000;
    constexpr int kSurfaceBoundsLevel = 8;
    Bounds surface;
    if (windows.size() + doc.triangles.size() <= kSurfaceBoundsMaxWindows) {
        for (const auto& p : tessellateDocument(doc, kSurfaceBoundsLevel).positions) surface.add(Vec3(p[0], p[1], p[2]));
    }
    const double size = modelSize(doc);
    constexpr size_t kKinds = 5;
    size_t byKind[kKinds] = {};
    for (const Join& j : doc.joins) ++byKind[static_cast<int>(j.continuity)];
    const std::vector<JoinContinuity> report = continuityReport(doc, opt.samples);
    JoinContinuity worst;
    size_t outOfTolerance = 0;
    for (const JoinContinuity& c : report) {
        const Continuity cont = doc.joins[c.join].continuity;
        worst.c0Gap = std::max(worst.c0Gap, c.c0Gap);
        // Residuals only mean something where the join asks for that order.
        if (holdsTangent(cont)) worst.c1Residual = std::max(worst.c1Residual, c.c1Residual);
        if (holdsCurvature(cont)) {
            worst.c2Residual = std::max(worst.c2Residual, c.c2Residual);
            worst.curvatureDeviationPct = std::max(worst.curvatureDeviationPct, c.curvatureDeviationPct);
        }
        worst.normalAngleDeg = std::max(worst.normalAngleDeg, c.normalAngleDeg);
        if (toleranceFailures(c, cont, doc.tolerances) != kWithinTolerance) ++outOfTolerance;
    }
    auto failureNames = [](uint8_t f) {
        std::vector<std::string> names;
        if (f & kPositionOut) names.emplace_back("position");
        if (f & kAngleOut) names.emplace_back("angle");
        if (f & kCurvatureOut) names.emplace_back("curvature");
        return names;
    };
    const double residual = maxConstraintResidual(doc);
    // Curves as `cN` and the live constructions as `kN`, each with whether its inputs still fit
    // (made again here, as the editor does on opening).
    Document live = doc;
    rerunConstructions(live);
    // Trimmed surfaces (issue 64): each one's loops, whole and trimmed area, and the trim edges'
    // gaps between two surfaces cut by one curve.
    struct Trimmed {
        SurfaceRef ref;
        size_t loops = 0, holes = 0;
        double area = 0.0, trimmedArea = 0.0;
        std::string error;
    };
    std::vector<Trimmed> trimmed;
    auto addTrimmed = [&](const SurfaceRef& ref, const std::vector<TrimLoop>& loops) {
        if (loops.empty()) return;
        Trimmed t{ref, loops.size(), 0, 0.0, 0.0, ""};
        for (const TrimLoop& l : loops) {
            t.holes += signedUvArea(l) < 0.0 ? 1 : 0;
            if (!l.error.empty()) t.error = l.error;
        }
        const DomainSurface s(doc, ref);
        t.area = s.area();
        t.trimmedArea = trimmedArea(s, loops);
        trimmed.push_back(t);
    };
    for (uint32_t p = 0; p < doc.patches.size(); ++p) addTrimmed(SurfaceRef{false, p}, doc.patches[p].trims);
    for (uint32_t s = 0; s < doc.surfaces.size(); ++s) addTrimmed(SurfaceRef{true, s}, doc.surfaces[s].trims);
    const std::vector<TrimEdgeGap> trimEdges = trimEdgeGaps(doc);
    const auto rational = [&](const BezierCurve& c) {
        return std::any_of(c.idx.begin(), c.idx.end(), [&](uint32_t i) { return pointWeight(doc, i) != 1.0; });
    };

    if (opt.json) {
        using nlohmann::json;
        json j{
            {"file", opt.file},
            {"name", doc.name},
            {"points", doc.points.size()},
            {"patches", doc.patches.size()},
            {"surfaces", doc.surfaces.size()},
            {"triangles", doc.triangles.size()},
            {"curves", doc.curves.size()},
            {"windows", windows.size()},
            {"joins",
             {{"total", doc.joins.size()}, {"C0", byKind[0]}, {"C1", byKind[1]}, {"G1", byKind[2]}, {"C2", byKind[3]}, {"G2", byKind[4]}}},
            {"modelSize", bounds.empty ? 0.0 : bounds.diagonal()},
            {"unit", lengthUnitName(doc.unit)},
            {"up", doc.camera.zUp ? "z" : "y"},
            {"maxConstraintResidual", residual},
            {"tolerances",
             {{"position", doc.tolerances.position}, {"angleDeg", doc.tolerances.angleDeg}, {"curvaturePct", doc.tolerances.curvaturePct}}},
            {"joinsOutOfTolerance", outOfTolerance},
            {"largest",
             {{"c0Gap", worst.c0Gap},
              {"c1Residual", worst.c1Residual},
              {"c2Residual", worst.c2Residual},
              {"normalAngleDeg", worst.normalAngleDeg},
              {"curvatureDeviationPct", worst.curvatureDeviationPct}}}};
        if (!bounds.empty)
            j["bounds"] = {{"min", {bounds.min.x, bounds.min.y, bounds.min.z}}, {"max", {bounds.max.x, bounds.max.y, bounds.max.z}}};
        else
            j["bounds"] = nullptr;
        if (!surface.empty)
            j["surfaceBounds"] = {{"min", {surface.min.x, surface.min.y, surface.min.z}},
                                  {"max", {surface.max.x, surface.max.y, surface.max.z}}};
        else
            j["surfaceBounds"] = nullptr;
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
                             {"beta2", jn.beta2},
                             {"shear", jn.shear},
                             {"alphaEnd", jn.alphaEnd},
                             {"fitted", jn.fitted},
                             {"fittedSpan", jn.fittedSpan},
                             {"c0Gap", c.c0Gap},
                             {"c1Residual", c.c1Residual},
                             {"c2Residual", c.c2Residual},
                             {"normalAngleDeg", c.normalAngleDeg},
                             {"curvatureDeviationPct", c.curvatureDeviationPct},
                             {"maxCurvature", c.maxCurvature},
                             {"outOfTolerance", failureNames(toleranceFailures(c, jn.continuity, doc.tolerances))}});
        }
        j["joinReport"] = std::move(joins);
        json curves = json::array();
        for (size_t i = 0; i < doc.curves.size(); ++i) {
            const BezierCurve& c = doc.curves[i];
            curves.push_back({{"id", "c" + std::to_string(i)},
                              {"name", c.name},
                              {"segments", curveSegmentCount(c)},
                              {"closed", curveClosed(c)},
                              {"rational", rational(c)},
                              {"points", c.idx},
                              {"live", !c.link                                    ? ""
                                       : c.link->kind == CurveLinkKind::Intersect ? "intersect"
                                                                                  : "project"},
                              {"error", c.link ? c.link->error : ""}});
        }
        j["curveList"] = std::move(curves);
        json made = json::array();
        for (size_t k = 0; k < live.constructions.size(); ++k) {
            const Construction& c = live.constructions[k];
            json inputs = json::array();
            for (const CurveInput& in : c.inputs) inputs.push_back(curveInputName(in));
            made.push_back({{"id", "k" + std::to_string(k)},
                            {"kind", constructionKindName(c.kind)},
                            {"inputs", std::move(inputs)},
                            {"patches", c.patches},
                            {"live", c.error.empty()},
                            {"error", c.error}});
        }
        j["constructions"] = std::move(made);
        json trims = json::array();
        for (const Trimmed& t : trimmed)
            trims.push_back({{"surface", surfaceRefName(t.ref)},
                             {"loops", t.loops},
                             {"holes", t.holes},
                             {"area", t.area},
                             {"trimmedArea", t.trimmedArea},
                             {"error", t.error}});
        j["trimmed"] = std::move(trims);
        json edges = json::array();
        for (const TrimEdgeGap& g : trimEdges)
            edges.push_back(
                {{"curve", "c" + std::to_string(g.curve)}, {"a", surfaceRefName(g.a)}, {"b", surfaceRefName(g.b)}, {"gap", g.gap}});
        j["trimEdges"] = std::move(edges);
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
    std::cout << "  joins       " << doc.joins.size() << "  (C0 " << byKind[0] << ", C1 " << byKind[1] << ", G1 " << byKind[2] << ", C2 "
              << byKind[3] << ", G2 " << byKind[4] << ")\n";
    if (bounds.empty)
        std::cout << "  bounds      (empty)\n";
    else
        std::cout << "  bounds      min " << vec(bounds.min) << "  max " << vec(bounds.max) << "  (control points)\n";
    if (!surface.empty)
        std::cout << "  surface     min " << vec(surface.min) << "  max " << vec(surface.max) << "  (the surface at level "
                  << kSurfaceBoundsLevel << ")\n";
    std::cout << "  model size  " << fmt("%.6g", bounds.empty ? 0.0 : bounds.diagonal()) << "  (bounding-box diagonal)\n";
    std::cout << "  unit        " << lengthUnitName(doc.unit) << ", " << (doc.camera.zUp ? "+Z" : "+Y") << " up\n";
    std::cout << "  largest C0 gap            " << fmt("%.3g", worst.c0Gap) << "\n";
    std::cout << "  largest C1 residual       " << fmt("%.3g", worst.c1Residual) << "  (C1/G1/C2/G2 joins)\n";
    std::cout << "  largest C2 residual       " << fmt("%.3g", worst.c2Residual) << "  (C2/G2 joins)\n";
    std::cout << "  largest seam normal angle " << fmt("%.3g", worst.normalAngleDeg) << " deg\n";
    std::cout << "  largest curvature dev.    " << fmt("%.3g", worst.curvatureDeviationPct) << " %  (C2/G2 joins)\n";
    std::cout << "  out of tolerance          " << outOfTolerance << " joins  (position " << fmt("%.3g", doc.tolerances.position)
              << ", angle " << fmt("%.3g", doc.tolerances.angleDeg) << " deg, curvature " << fmt("%.3g", doc.tolerances.curvaturePct)
              << " %)\n";
    std::cout << "  max constraint residual   " << fmt("%.3g", residual) << "  (" << fmt("%.3g", residual / size)
              << " x model size; edits keep it <= 1e-6)\n";

    for (size_t i = 0; i < doc.curves.size(); ++i) {
        const BezierCurve& c = doc.curves[i];
        std::cout << "  curve c" << i << "  " << curveSegmentCount(c) << " segment" << (curveSegmentCount(c) == 1 ? "" : "s")
                  << (curveClosed(c) ? ", closed" : ", open") << (rational(c) ? ", rational" : "") << "  \"" << printable(c.name) << "\"\n";
    }
    for (const Trimmed& t : trimmed)
        std::cout << "  trimmed " << (t.ref.net ? "net " : "patch ") << t.ref.index << "  " << t.loops << " loop"
                  << (t.loops == 1 ? "" : "s") << " (" << t.holes << " hole" << (t.holes == 1 ? "" : "s") << "), area "
                  << fmt("%.9g", t.trimmedArea) << " of " << fmt("%.9g", t.area)
                  << (t.error.empty() ? "" : ", trim kept its last shape: " + printable(t.error)) << "\n";
    for (const TrimEdgeGap& g : trimEdges)
        std::cout << "  trim edge c" << g.curve << " between " << surfaceRefName(g.a) << " and " << surfaceRefName(g.b) << ": gap "
                  << fmt("%.3g", g.gap) << "\n";
    for (size_t k = 0; k < live.constructions.size(); ++k) {
        const Construction& c = live.constructions[k];
        std::cout << "  " << constructionLabel(live, k) << ": " << c.patches.size() << " patches, "
                  << (c.error.empty() ? "live" : "inputs do not fit: " + printable(c.error)) << "\n";
    }

    if (!opt.noJoins && !report.empty()) {
        std::cout << "\n  join  patch edge  patch edge  rev  cont   alpha      C0 gap     C1 resid   normal deg  curv dev %  out\n";
        for (const JoinContinuity& c : report) {
            const Join& jn = doc.joins[c.join];
            char line[200];
            std::string out;
            for (const std::string& n : failureNames(toleranceFailures(c, jn.continuity, doc.tolerances)))
                out += (out.empty() ? "" : ",") + n;
            std::snprintf(line, sizeof line, "  %4zu  %5u %-4s  %5u %-4s  %-3s  %-4s %9.6g  %9.3g  %9.3g  %9.3g  %9.3g  %s\n", c.join,
                          jn.patchA, std::string(edgeName(jn.edgeA)).c_str(), jn.patchB, std::string(edgeName(jn.edgeB)).c_str(),
                          jn.reversed ? "yes" : "no", std::string(continuityName(jn.continuity)).c_str(), jn.alpha, c.c0Gap, c.c1Residual,
                          c.normalAngleDeg, c.curvatureDeviationPct, out.empty() ? "-" : out.c_str());
            std::cout << line;
        }
    }
    return 0;
}

}  // namespace

void registerInfoCommand(CLI::App& app, Action& run) {
    const auto [cmd, opt] =
        addSubcommand<InfoOptions>(app, run, "info", "Print counts, bounds, joins and measured continuity of a document", runInfo);
    cmd->add_option("file", opt->file, "Document (" + formatList(FormatUse::Load, ", ") + ")")->required();
    cmd->add_flag("--json", opt->json, "Machine-readable output (JSON)");
    cmd->add_option("--samples", opt->samples, "Samples per seam for the continuity report")->default_val(32)->check(CLI::Range(1, 4096));
    cmd->add_flag("--no-joins", opt->noJoins, "Omit the per-join table");
    addCadReadOptions(cmd);
    cmd->add_flag(
        "--partial", opt->partial,
        "Take a STEP/IGES file that comes in incomplete (faces skipped) as far as it comes; otherwise such a file is refused (exit 2)");
}

}  // namespace pw::app

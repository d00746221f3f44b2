// The native .patchwork JSON format (docs/FILE_FORMAT.md): writing with round-trip exact numbers
// and reading with full validation; every error names the source and the JSON field path.
#include "core/io/patchwork_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "core/base/errors.hpp"
#include "core/base/json_guard.hpp"
#include "core/base/json_reader.hpp"
#include "core/base/limits.hpp"
#include "core/io/construction_format.hpp"
#include "core/io/trim_format.hpp"
#include "core/model/settings.hpp"

namespace pw {
inline namespace io {

using nlohmann::json;

namespace {

using json_reader::at;
using json_reader::Reader;

// ---------------------------------------------------------------------------------------------
// Writing

// A float as the double with the shortest decimal form that still reads back as the same float
// (0.4f is written "0.4", not "0.4000000059604645"); the float's exact double value otherwise.
json floatJson(float f) {
    char buf[32];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, f);
    if (ec == std::errc()) {
        double d = 0;
        auto r = std::from_chars(buf, ptr, d);
        if (r.ec == std::errc() && static_cast<float>(d) == f) return d;
    }
    return static_cast<double>(f);
}

template <size_t N>
json floatArray(const std::array<float, N>& a) {
    json out = json::array();
    for (float f : a) out.push_back(floatJson(f));
    return out;
}

json tessJson(const TessSettings& t) {
    json j{{"outer", floatArray(t.outer)},
           {"inner", floatArray(t.inner)},
           {"linked", t.linked},
           {"spacing", spacingName(t.spacing)},
           {"adaptive", adaptiveName(t.adaptive)},
           {"distanceNear", floatJson(t.distanceNear)},
           {"distanceFar", floatJson(t.distanceFar)},
           {"targetPixels", floatJson(t.targetPixels)},
           {"maxLevel", floatJson(t.maxLevel)},
           {"cullBackfaces", t.cullBackfaces},
           {"cullOffscreen", t.cullOffscreen}};
    if (t.isolineLevels != TessSettings{}.isolineLevels) j["isoline"] = floatArray(t.isolineLevels);  // older files stay as they were
    if (t.cullFar) j["cullFar"] = true;
    const TessSettings defaults;  // the notes' distance variants: written only when chosen, so older files stay as they were
    if (t.distanceCurve != defaults.distanceCurve) j["distanceCurve"] = distanceCurveName(t.distanceCurve);
    if (t.distanceExponents != defaults.distanceExponents) j["distanceExponents"] = floatArray(t.distanceExponents);
    if (t.distanceFrom != defaults.distanceFrom) j["distanceFrom"] = distanceFromName(t.distanceFrom);
    if (!t.heightDetail) j["heightDetail"] = false;  // written only when off: older files stay as they were // likewise
    return j;
}

json displayJson(const DisplaySettings& d) {
    json j{{"shading", shadingName(d.shading)},  {"showGrid", d.showGrid},
           {"showWireframe", d.showWireframe},   {"showNormals", d.showNormals},
           {"showBoundaries", d.showBoundaries}, {"normalLength", floatJson(d.normalLength)},
           {"lightDir", floatArray(d.lightDir)}, {"background", floatArray(d.background)}};
    if (d.showIsocurves) j["showIsocurves"] = true;
    if (d.showCombs) j["showCombs"] = true;
    if (d.combScale != 1.0f) j["combScale"] = floatJson(d.combScale);
    if (d.combDensity != 16) j["combDensity"] = d.combDensity;
    if (d.domainUpperLeft) j["domainOrigin"] = domainOriginName(true);  // older files stay as they were
    return j;
}

json cameraJson(const Camera& c) {
    return json{{"target", {c.target[0], c.target[1], c.target[2]}},
                {"distance", c.distance},
                {"yawDeg", c.yawDeg},
                {"pitchDeg", c.pitchDeg},
                {"fovYDeg", c.fovYDeg},
                {"orthographic", c.orthographic},
                {"zUp", c.zUp}};
}

json displacementJson(const DisplacementSettings& d) {
    json j{{"map", d.map}, {"scale", floatJson(d.scale)}, {"bias", floatJson(d.bias)}, {"mapping", displacementMappingName(d.mapping)}};
    if (d.rect) j["rect"] = {(*d.rect)[0], (*d.rect)[1], (*d.rect)[2], (*d.rect)[3]};
    return j;
}

// A patch's, net's or triangle's own displacement: [scale, bias].
void putOverride(json& o, const std::optional<DisplacementOverride>& d) {
    if (d) o["displacement"] = {floatJson(d->scale), floatJson(d->bias)};
}

// ---------------------------------------------------------------------------------------------
// Reading

constexpr double kMinLevel = limits::kMinTessLevel, kMaxLevel = limits::kMaxTessLevel;

template <size_t N>
void readFloats(const Reader& r, const json& v, const std::string& path, std::array<float, N>& out, double lo, double hi) {
    r.fixedArray(v, path, N);
    for (size_t i = 0; i < N; ++i) out[i] = r.floatValue(v[i], at(path, i), lo, hi);
}

// A number or numbers of the settings table (core/model/settings.hpp), in the row's range: the
// panel, the `set` command and this reader accept the same values.
template <class T>
void readSetting(const Reader& r, const json& v, const std::string& path, std::string_view key, T& out) {
    const Setting& s = setting(key);
    if constexpr (std::is_same_v<T, float>)
        out = r.floatValue(v, path, s.min, s.max);
    else if constexpr (std::is_same_v<T, int>)
        out = int(r.numberInRange(v, path, s.min, s.max));
    else
        readFloats(r, v, path, out, s.min, s.max);
}

TessSettings readTess(const Reader& r, const json& v, const std::string& path) {
    r.object(v, path);
    TessSettings t;
    auto number = [&](const char* field, auto& out) {
        r.optional(v, path, field, [&](const json& x, const std::string& p) { readSetting(r, x, p, "tess." + std::string(field), out); });
    };
    number("outer", t.outer);
    number("inner", t.inner);
    r.optional(v, path, "linked", [&](const json& x, const std::string& p) { t.linked = r.boolean(x, p); });
    r.optional(v, path, "spacing", [&](const json& x, const std::string& p) {
        t.spacing = r.named<Spacing>(x, p, parseSpacing, "equal, fractional_odd, fractional_even, pow2");
    });
    r.optional(v, path, "adaptive", [&](const json& x, const std::string& p) {
        t.adaptive = r.named<AdaptiveMode>(x, p, parseAdaptive, "none, distance, screen, orientation");
    });
    number("distanceNear", t.distanceNear);
    number("distanceFar", t.distanceFar);
    r.optional(v, path, "distanceCurve", [&](const json& x, const std::string& p) {
        t.distanceCurve = r.named<DistanceCurve>(x, p, parseDistanceCurve, "linear, pow2");
    });
    number("distanceExponents", t.distanceExponents);
    r.optional(v, path, "distanceFrom", [&](const json& x, const std::string& p) {
        t.distanceFrom = r.named<DistanceFrom>(x, p, parseDistanceFrom, "edges, centre, edges-inner-centre");
    });
    number("targetPixels", t.targetPixels);
    number("maxLevel", t.maxLevel);
    r.optional(v, path, "cullBackfaces", [&](const json& x, const std::string& p) { t.cullBackfaces = r.boolean(x, p); });
    r.optional(v, path, "cullOffscreen", [&](const json& x, const std::string& p) { t.cullOffscreen = r.boolean(x, p); });
    r.optional(v, path, "cullFar", [&](const json& x, const std::string& p) { t.cullFar = r.boolean(x, p); });
    r.optional(v, path, "heightDetail", [&](const json& x, const std::string& p) { t.heightDetail = r.boolean(x, p); });
    r.optional(v, path, "isoline", [&](const json& x, const std::string& p) { readSetting(r, x, p, "tess.isoline", t.isolineLevels); });
    return t;
}

DisplaySettings readDisplay(const Reader& r, const json& v, const std::string& path) {
    r.object(v, path);
    DisplaySettings d;
    r.optional(v, path, "shading", [&](const json& x, const std::string& p) {
        d.shading = r.named<ShadingMode>(x, p, parseShading, "lit, normal, patch, uv, zebra, gauss, mean, level");
    });
    r.optional(v, path, "showGrid", [&](const json& x, const std::string& p) { d.showGrid = r.boolean(x, p); });
    r.optional(v, path, "showWireframe", [&](const json& x, const std::string& p) { d.showWireframe = r.boolean(x, p); });
    r.optional(v, path, "showNormals", [&](const json& x, const std::string& p) { d.showNormals = r.boolean(x, p); });
    r.optional(v, path, "showBoundaries", [&](const json& x, const std::string& p) { d.showBoundaries = r.boolean(x, p); });
    r.optional(v, path, "showIsocurves", [&](const json& x, const std::string& p) { d.showIsocurves = r.boolean(x, p); });
    r.optional(v, path, "showCombs", [&](const json& x, const std::string& p) { d.showCombs = r.boolean(x, p); });
    r.optional(v, path, "domainOrigin", [&](const json& x, const std::string& p) {
        d.domainUpperLeft = r.named<bool>(x, p, parseDomainOrigin, "lower-left, upper-left");
    });
    auto number = [&](const char* field, auto& out) {
        r.optional(v, path, field,
                   [&](const json& x, const std::string& p) { readSetting(r, x, p, "display." + std::string(field), out); });
    };
    number("combScale", d.combScale);
    number("combDensity", d.combDensity);
    number("normalLength", d.normalLength);
    number("lightDir", d.lightDir);
    number("background", d.background);
    return d;
}

DisplacementSettings readDisplacement(const Reader& r, const json& v, const std::string& path) {
    r.object(v, path);
    DisplacementSettings d;
    r.optional(v, path, "map", [&](const json& x, const std::string& p) { d.map = r.string(x, p); });
    r.optional(v, path, "scale", [&](const json& x, const std::string& p) { readSetting(r, x, p, "displacement.scale", d.scale); });
    r.optional(v, path, "bias", [&](const json& x, const std::string& p) { readSetting(r, x, p, "displacement.bias", d.bias); });
    r.optional(v, path, "mapping", [&](const json& x, const std::string& p) {
        d.mapping = r.named<DisplacementMapping>(x, p, parseDisplacementMapping, "patch, planar");
    });
    r.optional(v, path, "rect", [&](const json& x, const std::string& p) {
        r.fixedArray(x, p, 4);
        std::array<double, 4> rect{};
        for (size_t i = 0; i < 4; ++i) rect[i] = i < 2 ? r.coordinate(x[i], at(p, i)) : r.numberInRange(x[i], at(p, i), 0, 1e9, true);
        d.rect = rect;
    });
    return d;
}

void readOverride(const Reader& r, const json& o, const std::string& path, std::optional<DisplacementOverride>& out) {
    r.optional(o, path, "displacement", [&](const json& x, const std::string& p) {
        if (x.is_null()) return;
        std::array<float, 2> sb{};
        readFloats(r, x, p, sb, -1e9, 1e9);
        out = DisplacementOverride{sb[0], sb[1]};
    });
}

Camera readCamera(const Reader& r, const json& v, const std::string& path) {
    r.object(v, path);
    Camera c;
    r.optional(v, path, "target", [&](const json& x, const std::string& p) {
        r.fixedArray(x, p, 3);
        for (size_t i = 0; i < 3; ++i) c.target[i] = r.coordinate(x[i], at(p, i));
    });
    r.optional(v, path, "distance", [&](const json& x, const std::string& p) { c.distance = r.numberInRange(x, p, 0, 1e12, true); });
    r.optional(v, path, "yawDeg", [&](const json& x, const std::string& p) { c.yawDeg = r.numberInRange(x, p, -1e6, 1e6); });
    r.optional(v, path, "pitchDeg", [&](const json& x, const std::string& p) { c.pitchDeg = r.numberInRange(x, p, -1e6, 1e6); });
    r.optional(v, path, "fovYDeg",
               [&](const json& x, const std::string& p) { c.fovYDeg = r.numberInRange(x, p, 0, limits::kMaxFovYDeg, true); });
    r.optional(v, path, "orthographic", [&](const json& x, const std::string& p) { c.orthographic = r.boolean(x, p); });
    r.optional(v, path, "zUp", [&](const json& x, const std::string& p) { c.zUp = r.boolean(x, p); });
    return c;
}

constexpr const char* kBases = "bezier, bspline, catmull-rom";

}  // namespace

json documentToJson(const Document& doc) {
    json j = json::object();
    j["format"] = "patchwork";
    j["version"] = Document::kFormatVersion;
    j["name"] = doc.name;
    if (doc.unit != LengthUnit::Metre) j["unit"] = lengthUnitName(doc.unit);  // metres unless it says otherwise

    json points = json::array();
    for (const Vec3& p : doc.points) points.push_back(json::array({p.x, p.y, p.z}));
    j["points"] = std::move(points);
    if (!doc.weights.empty()) {  // rational documents only: one weight per point
        json weights = json::array();
        for (uint32_t i = 0; i < doc.points.size(); ++i) weights.push_back(pointWeight(doc, i));
        j["weights"] = std::move(weights);
    }

    json patches = json::array();
    for (const Patch& p : doc.patches) {
        json o{{"idx", p.idx}, {"basis", basisName(p.basis)}, {"tension", p.tension}, {"name", p.name}};
        if (p.tessOverride) o["tess"] = floatArray(*p.tessOverride);
        if (p.hidden) o["hidden"] = true;
        putOverride(o, p.displacement);
        if (!p.trims.empty()) o["trims"] = trimsJson(p.trims);
        patches.push_back(std::move(o));
    }
    j["patches"] = std::move(patches);

    json surfaces = json::array();
    for (const Surface& s : doc.surfaces) {
        surfaces.push_back(json{{"rows", s.rows},
                                {"cols", s.cols},
                                {"idx", s.idx},
                                {"basis", basisName(s.basis)},
                                {"tension", s.tension},
                                {"closedU", s.closedU},
                                {"closedV", s.closedV},
                                {"keepC1", s.keepC1},
                                {"name", s.name}});
        if (s.hidden) surfaces.back()["hidden"] = true;
        putOverride(surfaces.back(), s.displacement);
        if (!s.trims.empty()) surfaces.back()["trims"] = trimsJson(s.trims);
    }
    j["surfaces"] = std::move(surfaces);

    json joins = json::array();
    for (const Join& jn : doc.joins) {
        joins.push_back(json{{"a", jn.patchA},
                             {"edgeA", edgeName(jn.edgeA)},
                             {"b", jn.patchB},
                             {"edgeB", edgeName(jn.edgeB)},
                             {"reversed", jn.reversed},
                             {"continuity", continuityName(jn.continuity)},
                             {"alpha", jn.alpha}});
        if (jn.beta2 != 0.0) joins.back()["beta2"] = jn.beta2;
        if (jn.shear != std::array<double, 3>{}) joins.back()["shear"] = jn.shear;
        if (jn.alphaEnd != 0.0) joins.back()["alpha_end"] = jn.alphaEnd;
        if (jn.fitted) joins.back()["fitted"] = true;
        if (jn.fitted && jn.fittedSpan != std::array<double, 2>{0.0, 1.0}) joins.back()["fitted_span"] = jn.fittedSpan;
    }
    j["joins"] = std::move(joins);

    // Cubic Bézier triangles: only written when there are some, so that documents without them
    // serialise exactly as before.
    if (!doc.triangles.empty()) {
        json triangles = json::array();
        for (const TrianglePatch& t : doc.triangles) {
            json o{{"idx", t.idx}, {"name", t.name}};
            if (t.tessOverride) o["tess"] = floatArray(*t.tessOverride);
            if (t.hidden) o["hidden"] = true;
            putOverride(o, t.displacement);
            triangles.push_back(std::move(o));
        }
        j["triangles"] = std::move(triangles);
    }
    if (!doc.curves.empty()) {
        json curves = json::array();
        for (const BezierCurve& c : doc.curves) {
            curves.push_back(json{{"idx", c.idx}, {"name", c.name}});
            if (c.hidden) curves.back()["hidden"] = true;
            if (c.link) curves.back()["link"] = curveLinkJson(*c.link);
        }
        j["curves"] = std::move(curves);
    }
    if (!doc.constructions.empty()) j["constructions"] = constructionsJson(doc);

    j["tess"] = tessJson(doc.tess);
    j["display"] = displayJson(doc.display);
    j["camera"] = cameraJson(doc.camera);
    if (doc.displacement != DisplacementSettings{})
        j["displacement"] = displacementJson(doc.displacement);  // older files stay as they were
    if (doc.tolerances != ContinuityTolerances{})
        j["tolerances"] =
            json{{"position", doc.tolerances.position}, {"angle", doc.tolerances.angleDeg}, {"curvature", doc.tolerances.curvaturePct}};
    return j;
}

Document documentFromJson(const json& j, const std::string& sourceName, const std::string& fieldPrefix) {
    const Reader r(sourceName, fieldPrefix);
    if (!j.is_object()) r.fail("", "a Patchwork document must be a JSON object, found " + Reader::describe(j));

    // Identification and version come first, so that a newer file gets the version message.
    const json& format = *r.member(j, "", "format", true);
    if (!format.is_string() || format.get<std::string>() != "patchwork")
        r.fail("format", "not a Patchwork document (expected \"format\": \"patchwork\")");
    const json& version = *r.member(j, "", "version", true);
    if (!version.is_number_integer()) r.wrongType(version, "version", "an integer");
    const bool negative = !version.is_number_unsigned() && version.get<int64_t>() < 0;
    const uint64_t v = negative ? 0 : version.get<uint64_t>();
    if (v > static_cast<uint64_t>(Document::kFormatVersion))
        r.fail("version", "was written by a newer Patchwork (format version " + std::to_string(v) + "); this build reads version " +
                              std::to_string(Document::kFormatVersion));
    if (negative || v < 1)
        r.fail("version", "format version " + version.dump() + " is not valid (this build reads version " +
                              std::to_string(Document::kFormatVersion) + ")");

    Document doc;
    r.optional(j, "", "name", [&](const json& x, const std::string& p) { doc.name = r.string(x, p); });
    r.optional(j, "", "unit", [&](const json& x, const std::string& p) {
        const auto unit = parseLengthUnit(r.string(x, p));
        if (!unit) r.fail(p, "unknown length unit " + x.dump() + " (mm, cm, m or in)");
        doc.unit = *unit;
    });

    // Pool.
    const json& points = r.array(*r.member(j, "", "points", true), "points", limits::kMaxPoints, "points");
    doc.points.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const std::string p = at("points", i);
        const json& xyz = r.fixedArray(points[i], p, 3);
        for (int c = 0; c < 3; ++c) doc.points[i][c] = r.coordinate(xyz[c], at(p, c));
    }
    const uint64_t nPoints = doc.points.size();
    if (const json* wv = r.member(j, "", "weights", false)) {
        const json& weights = r.array(*wv, "weights", limits::kMaxPoints, "weights");
        if (weights.size() != nPoints)
            r.fail("weights", "has " + std::to_string(weights.size()) + " entries; the document has " + std::to_string(nPoints) +
                                  " points (one weight each)");
        doc.weights.resize(weights.size());
        for (size_t i = 0; i < weights.size(); ++i) {
            doc.weights[i] = r.numberInRange(weights[i], at("weights", i), 0.0, kMaxWeight, true);
        }
        trimWeights(doc.weights);
    }

    // Patches.
    const json& patches = r.array(*r.member(j, "", "patches", true), "patches", limits::kMaxPatches, "patches");
    doc.patches.resize(patches.size());
    for (size_t i = 0; i < patches.size(); ++i) {
        const std::string path = at("patches", i);
        const json& o = r.object(patches[i], path);
        Patch& patch = doc.patches[i];
        const json& idx = r.fixedArray(*r.member(o, path, "idx", true), at(path, "idx"), 16);
        for (size_t k = 0; k < 16; ++k)
            patch.idx[k] = static_cast<uint32_t>(r.index(idx[k], at(at(path, "idx"), k), nPoints, "point index"));
        r.optional(o, path, "basis", [&](const json& x, const std::string& p) { patch.basis = r.named<Basis>(x, p, parseBasis, kBases); });
        r.optional(o, path, "tension", [&](const json& x, const std::string& p) { patch.tension = r.numberInRange(x, p, -1e3, 1e3); });
        r.optional(o, path, "name", [&](const json& x, const std::string& p) { patch.name = r.string(x, p); });
        r.optional(o, path, "hidden", [&](const json& x, const std::string& p) { patch.hidden = r.boolean(x, p); });
        r.optional(o, path, "tess", [&](const json& x, const std::string& p) {
            if (x.is_null()) return;
            std::array<float, 6> levels{};
            readFloats(r, x, p, levels, kMinLevel, kMaxLevel);
            patch.tessOverride = levels;
        });
        readOverride(r, o, path, patch.displacement);
        r.optional(o, path, "trims", [&](const json& x, const std::string& p) { readTrims(r, x, p, patch.trims); });
    }

    // Surfaces.
    uint64_t windows = doc.patches.size();
    if (const json* sv = r.member(j, "", "surfaces", false)) {
        const json& surfaces = r.array(*sv, "surfaces", limits::kMaxPatches, "surfaces");
        doc.surfaces.resize(surfaces.size());
        for (size_t i = 0; i < surfaces.size(); ++i) {
            const std::string path = at("surfaces", i);
            const json& o = r.object(surfaces[i], path);
            Surface& s = doc.surfaces[i];
            s.rows =
                static_cast<uint32_t>(r.index(*r.member(o, path, "rows", true), at(path, "rows"), limits::kMaxNetSide + 1, "row count"));
            s.cols =
                static_cast<uint32_t>(r.index(*r.member(o, path, "cols", true), at(path, "cols"), limits::kMaxNetSide + 1, "column count"));
            if (s.rows < 1) r.fail(at(path, "rows"), "a net needs at least 1 row");
            if (s.cols < 1) r.fail(at(path, "cols"), "a net needs at least 1 column");
            r.optional(o, path, "basis", [&](const json& x, const std::string& p) { s.basis = r.named<Basis>(x, p, parseBasis, kBases); });
            r.optional(o, path, "tension", [&](const json& x, const std::string& p) { s.tension = r.numberInRange(x, p, -1e3, 1e3); });
            r.optional(o, path, "closedU", [&](const json& x, const std::string& p) { s.closedU = r.boolean(x, p); });
            r.optional(o, path, "closedV", [&](const json& x, const std::string& p) { s.closedV = r.boolean(x, p); });
            r.optional(o, path, "name", [&](const json& x, const std::string& p) { s.name = r.string(x, p); });
            r.optional(o, path, "hidden", [&](const json& x, const std::string& p) { s.hidden = r.boolean(x, p); });
            r.optional(o, path, "trims", [&](const json& x, const std::string& p) { readTrims(r, x, p, s.trims); });
            const size_t n = static_cast<size_t>(s.rows) * s.cols;
            const std::string ip = at(path, "idx");
            const json& idx = r.fixedArray(*r.member(o, path, "idx", true), ip, n);
            s.idx.resize(n);
            for (size_t k = 0; k < n; ++k) s.idx[k] = static_cast<uint32_t>(r.index(idx[k], at(ip, k), nPoints, "point index"));
            r.optional(o, path, "keepC1", [&](const json& x, const std::string& p) { s.keepC1 = r.boolean(x, p); });
            readOverride(r, o, path, s.displacement);
            const uint32_t step = netStep(s.basis);
            windows += netWindowCount(s.rows, s.closedV, step) * netWindowCount(s.cols, s.closedU, step);
            if (windows > limits::kMaxPatches)
                r.fail(path, "patches and surface windows exceed the limit of " + std::to_string(limits::kMaxPatches));
        }
    }

    // Joins.
    if (const json* jv = r.member(j, "", "joins", false)) {
        const json& joins = r.array(*jv, "joins", limits::kMaxJoins, "joins");
        doc.joins.resize(joins.size());
        for (size_t i = 0; i < joins.size(); ++i) {
            const std::string path = at("joins", i);
            const json& o = r.object(joins[i], path);
            Join& jn = doc.joins[i];
            // A side whose edge is a triangle's (e0, e1, e2) indexes the triangles (read below; their
            // array's length bounds the index here, its contents are checked there).
            constexpr const char* kEdges = "u0, v0, u1, v1 (a patch's) or e0, e1, e2 (a triangle's)";
            const json* tv = j.contains("triangles") ? &j["triangles"] : nullptr;
            const size_t triangleCount = tv && tv->is_array() ? tv->size() : 0;
            jn.edgeA = r.named<Edge>(*r.member(o, path, "edgeA", true), at(path, "edgeA"), parseJoinEdge, kEdges);
            jn.edgeB = r.named<Edge>(*r.member(o, path, "edgeB", true), at(path, "edgeB"), parseJoinEdge, kEdges);
            const auto side = [&](const char* key, Edge e) {
                return static_cast<uint32_t>(r.index(*r.member(o, path, key, true), at(path, key),
                                                     isTriangleEdge(e) ? triangleCount : doc.patches.size(),
                                                     isTriangleEdge(e) ? "triangle index" : "patch index"));
            };
            jn.patchA = side("a", jn.edgeA);
            jn.patchB = side("b", jn.edgeB);
            r.optional(o, path, "reversed", [&](const json& x, const std::string& p) { jn.reversed = r.boolean(x, p); });
            r.optional(o, path, "continuity", [&](const json& x, const std::string& p) {
                jn.continuity = r.named<Continuity>(x, p, parseContinuity, "C0, C1, G1, C2, G2");
            });
            r.optional(o, path, "alpha", [&](const json& x, const std::string& p) { jn.alpha = r.numberInRange(x, p, 0, 1e6, true); });
            r.optional(o, path, "beta2", [&](const json& x, const std::string& p) { jn.beta2 = r.numberInRange(x, p, -1e6, 1e6, false); });
            r.optional(o, path, "shear", [&](const json& x, const std::string& p) {
                for (size_t k = 0; k < 3; ++k) jn.shear[k] = r.numberInRange(r.fixedArray(x, p, 3)[k], at(p, k), -1e6, 1e6, false);
            });
            r.optional(o, path, "alpha_end",
                       [&](const json& x, const std::string& p) { jn.alphaEnd = r.numberInRange(x, p, 0, 1e6, true); });
            r.optional(o, path, "fitted", [&](const json& x, const std::string& p) { jn.fitted = r.boolean(x, p); });
            r.optional(o, path, "fitted_span", [&](const json& x, const std::string& p) {
                for (size_t k = 0; k < 2; ++k) jn.fittedSpan[k] = r.numberInRange(r.fixedArray(x, p, 2)[k], at(p, k), 0, 1, false);
                if (!(jn.fittedSpan[0] < jn.fittedSpan[1])) r.fail(p, "the part [t0, t1] needs t0 < t1");
            });
            if (joinHasTriangle(jn) && jn.continuity != Continuity::C0 && jn.continuity != Continuity::G1)
                r.fail(at(path, "continuity"), "a join with a triangle's edge is C0 or G1");
            if (jn.shear != std::array<double, 3>{} && jn.continuity != Continuity::G1)
                r.fail(at(path, "shear"), "only a G1 join leans along its seam");
            if (jn.alphaEnd != 0.0 && jn.continuity != Continuity::G1)
                r.fail(at(path, "alpha_end"), "only a G1 join's ratio varies along its seam");
            if (jn.fitted && (jn.continuity != Continuity::G1 || joinHasTriangle(jn)))
                r.fail(at(path, "fitted"), "only a G1 join between patch edges is fitted");
            if (!jn.fitted && jn.fittedSpan != std::array<double, 2>{0.0, 1.0})
                r.fail(at(path, "fitted_span"), "only a fitted join is restricted to a part of its first edge");
            if (jn.patchA == jn.patchB && jn.edgeA == jn.edgeB) r.fail(path, "a join cannot connect an edge to itself");
        }
    }

    // Cubic Bézier triangles (optional).
    if (const json* tv = r.member(j, "", "triangles", false)) {
        const json& triangles =
            r.array(*tv, "triangles", limits::kMaxPatches - std::min<uint64_t>(windows, limits::kMaxPatches), "triangles");
        doc.triangles.resize(triangles.size());
        for (size_t i = 0; i < triangles.size(); ++i) {
            const std::string path = at("triangles", i);
            const json& o = r.object(triangles[i], path);
            TrianglePatch& t = doc.triangles[i];
            const std::string ip = at(path, "idx");
            const json& idx = r.fixedArray(*r.member(o, path, "idx", true), ip, 10);
            for (size_t k = 0; k < 10; ++k) t.idx[k] = static_cast<uint32_t>(r.index(idx[k], at(ip, k), nPoints, "point index"));
            r.optional(o, path, "name", [&](const json& x, const std::string& p) { t.name = r.string(x, p); });
            r.optional(o, path, "hidden", [&](const json& x, const std::string& p) { t.hidden = r.boolean(x, p); });
            r.optional(o, path, "tess", [&](const json& x, const std::string& p) {
                if (x.is_null()) return;
                std::array<float, 4> levels{};
                readFloats(r, x, p, levels, kMinLevel, kMaxLevel);
                t.tessOverride = levels;
            });
            readOverride(r, o, path, t.displacement);
        }
    }

    // Cubic Bézier curves (optional).
    if (const json* cv = r.member(j, "", "curves", false)) {
        const json& curves = r.array(*cv, "curves", limits::kMaxPatches, "curves");
        doc.curves.resize(curves.size());
        for (size_t i = 0; i < curves.size(); ++i) {
            const std::string path = at("curves", i);
            const json& o = r.object(curves[i], path);
            BezierCurve& c = doc.curves[i];
            const std::string ip = at(path, "idx");
            const json& idx = r.array(*r.member(o, path, "idx", true), ip, 3 * limits::kMaxPatches + 1, "points");
            if (!validCurveLength(idx.size())) r.fail(ip, "a curve has 3n + 1 points (4, 7, 10, ...), not " + std::to_string(idx.size()));
            c.idx.resize(idx.size());
            for (size_t k = 0; k < idx.size(); ++k) c.idx[k] = static_cast<uint32_t>(r.index(idx[k], at(ip, k), nPoints, "point index"));
            r.optional(o, path, "name", [&](const json& x, const std::string& p) { c.name = r.string(x, p); });
            r.optional(o, path, "hidden", [&](const json& x, const std::string& p) { c.hidden = r.boolean(x, p); });
            r.optional(o, path, "link", [&](const json& x, const std::string& p) { c.link = readCurveLink(r, x, p); });
        }
    }
    checkTrimReferences(r, doc);

    if (const json* v = r.member(j, "", "constructions", false)) readConstructions(r, *v, doc);
    if (const json* v = r.member(j, "", "tess", false)) doc.tess = readTess(r, *v, "tess");
    if (const json* v = r.member(j, "", "display", false)) doc.display = readDisplay(r, *v, "display");
    if (const json* v = r.member(j, "", "camera", false)) doc.camera = readCamera(r, *v, "camera");
    if (const json* v = r.member(j, "", "displacement", false)) doc.displacement = readDisplacement(r, *v, "displacement");
    if (const json* v = r.member(j, "", "tolerances", false)) {
        r.object(*v, "tolerances");
        ContinuityTolerances& t = doc.tolerances;
        auto positive = [&](const char* key, double& out) {
            r.optional(*v, "tolerances", key, [&](const json& x, const std::string& p) { out = r.numberInRange(x, p, 0, 1e9, true); });
        };
        positive("position", t.position);
        positive("angle", t.angleDeg);
        positive("curvature", t.curvaturePct);
    }
    if (const auto tp = weightedTrianglePoint(doc))
        r.fail(at("weights", (*tp)[1]), "point " + std::to_string((*tp)[1]) + " belongs to triangle " + std::to_string((*tp)[0]) +
                                            "; Bézier triangles take no weights (every weight of their points must be 1)");
    return doc;
}

std::string serializeDocument(const Document& doc) {
    // Readable layout: one top-level field per line, one pool point / patch / join per line.
    const json j = documentToJson(doc);
    auto dump = [](const json& v) { return v.dump(-1, ' ', false, json::error_handler_t::replace); };
    std::string out = "{\n";
    bool first = true;
    for (const char* key : {"format", "version", "name", "unit", "points", "weights", "patches", "surfaces", "joins", "triangles", "curves",
                            "constructions", "tess", "display", "camera", "displacement", "tolerances"}) {
        auto it = j.find(key);
        if (it == j.end()) continue;
        if (!first) out += ",\n";
        first = false;
        out += "  \"";
        out += key;
        out += "\": ";
        if (it->is_array() && !it->empty()) {
            out += "[\n";
            for (size_t i = 0; i < it->size(); ++i) {
                out += "    ";
                out += dump((*it)[i]);
                out += i + 1 < it->size() ? ",\n" : "\n";
            }
            out += "  ]";
        } else {
            out += dump(*it);
        }
    }
    out += "\n}\n";
    return out;
}

Document parseDocument(std::string_view text, const std::string& sourceName) {
    const json j = parseJsonGuarded(text, sourceName);
    if (!j.is_object()) {
        // Locate the offending top-level value: its first character.
        const size_t first = text.find_first_not_of(" \t\r\n");
        throw InputError(sourceName, "a Patchwork document must be a JSON object, found " + Reader::describe(j),
                         lineAt(text, first == std::string_view::npos ? 0 : first));
    }
    return documentFromJson(j, sourceName);
}

}  // namespace io
}  // namespace pw

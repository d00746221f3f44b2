#include "core/io/trim_format.hpp"

#include <nlohmann/json.hpp>

#include "core/base/limits.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"

namespace pw {
inline namespace io {

using json_reader::at;
using nlohmann::json;

namespace {
constexpr size_t kMaxLoopPoints = 3 * 4096 + 1;
constexpr size_t kMaxLoops = 4096;

json surfaceJson(const SurfaceRef& s) { return surfaceRefName(s); }
SurfaceRef readSurface(const json_reader::Reader& r, const json& v, const std::string& path) {
    const std::string w = r.string(v, path);
    SurfaceRef s;
    std::string digits = w;
    if (!digits.empty() && digits[0] == 'n') {
        s.net = true;
        digits.erase(0, 1);
    }
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
        r.fail(path, "expected a surface: a patch number (\"3\") or a net (\"n0\")");
    s.index = uint32_t(std::stoul(digits));
    return s;
}
std::array<double, 3> readVector(const json_reader::Reader& r, const json& v, const std::string& path) {
    const json& a = r.fixedArray(v, path, 3);
    std::array<double, 3> out{};
    for (size_t k = 0; k < 3; ++k) out[k] = r.numberInRange(a[k], at(path, k), -1e6, 1e6);
    return out;
}
}  // namespace

json trimsJson(const std::vector<TrimLoop>& loops) {
    json out = json::array();
    for (const TrimLoop& l : loops) {
        json uv = json::array();
        for (const UV& p : l.uv) uv.push_back(json::array({p[0], p[1]}));
        json o{{"uv", std::move(uv)}};
        if (l.hole) o["hole"] = true;
        if (l.curve >= 0) o["curve"] = l.curve;
        if (l.direction != std::array<double, 3>{0, 0, 0}) o["direction"] = l.direction;
        if (!l.error.empty()) o["error"] = l.error;
        out.push_back(std::move(o));
    }
    return out;
}

void readTrims(const json_reader::Reader& r, const json& v, const std::string& path, std::vector<TrimLoop>& loops) {
    const json& arr = r.array(v, path, kMaxLoops, "trim loops");
    loops.resize(arr.size());
    for (size_t i = 0; i < arr.size(); ++i) {
        const std::string lp = at(path, i);
        const json& o = r.object(arr[i], lp);
        TrimLoop& l = loops[i];
        const std::string up = at(lp, "uv");
        const json& uv = r.array(*r.member(o, lp, "uv", true), up, kMaxLoopPoints, "points");
        l.uv.resize(uv.size());
        for (size_t k = 0; k < uv.size(); ++k) {
            const json& p = r.fixedArray(uv[k], at(up, k), 2);
            l.uv[k] = {r.numberInRange(p[0], at(at(up, k), size_t(0)), -1.0, 2.0),
                       r.numberInRange(p[1], at(at(up, k), size_t(1)), -1.0, 2.0)};
        }
        r.optional(o, lp, "hole", [&](const json& x, const std::string& p) { l.hole = r.boolean(x, p); });
        r.optional(o, lp, "curve",
                   [&](const json& x, const std::string& p) { l.curve = int32_t(r.index(x, p, limits::kMaxPatches, "curve")); });
        r.optional(o, lp, "direction", [&](const json& x, const std::string& p) { l.direction = readVector(r, x, p); });
        r.optional(o, lp, "error", [&](const json& x, const std::string& p) { l.error = r.string(x, p); });
    }
    if (const std::string why = trimLoopsProblem(loops); !why.empty()) r.fail(path, why);
}

json curveLinkJson(const CurveLink& l) {
    json o{{"kind", l.kind == CurveLinkKind::Intersect ? "intersect" : "project"}, {"a", surfaceJson(l.a)}};
    if (l.kind == CurveLinkKind::Intersect) {
        o["b"] = surfaceJson(l.b);
        o["branch"] = l.branch;
    } else {
        o["source"] = l.source;
        if (l.direction != std::array<double, 3>{0, 0, 0}) o["direction"] = l.direction;
    }
    if (!l.error.empty()) o["error"] = l.error;
    return o;
}

CurveLink readCurveLink(const json_reader::Reader& r, const json& v, const std::string& path) {
    const json& o = r.object(v, path);
    CurveLink l;
    const std::string kind = r.string(*r.member(o, path, "kind", true), at(path, "kind"));
    if (kind == "intersect")
        l.kind = CurveLinkKind::Intersect;
    else if (kind == "project")
        l.kind = CurveLinkKind::Project;
    else
        r.fail(at(path, "kind"), "expected \"intersect\" or \"project\", found \"" + printable(kind) + "\"");
    l.a = readSurface(r, *r.member(o, path, "a", true), at(path, "a"));
    if (l.kind == CurveLinkKind::Intersect) {
        l.b = readSurface(r, *r.member(o, path, "b", true), at(path, "b"));
        r.optional(o, path, "branch", [&](const json& x, const std::string& p) { l.branch = uint32_t(r.index(x, p, 1u << 20, "branch")); });
    } else {
        l.source = int32_t(r.index(*r.member(o, path, "source", true), at(path, "source"), limits::kMaxPatches, "curve"));
        r.optional(o, path, "direction", [&](const json& x, const std::string& p) { l.direction = readVector(r, x, p); });
    }
    r.optional(o, path, "error", [&](const json& x, const std::string& p) { l.error = r.string(x, p); });
    return l;
}

void checkTrimReferences(const json_reader::Reader& r, const Document& doc) {
    auto loops = [&](const std::vector<TrimLoop>& ls, const std::string& path) {
        for (size_t i = 0; i < ls.size(); ++i)
            if (ls[i].curve >= 0 && size_t(ls[i].curve) >= doc.curves.size())
                r.fail(at(at(at(path, "trims"), i), "curve"), "curve " + std::to_string(ls[i].curve) +
                                                                  " does not exist (the document has " + std::to_string(doc.curves.size()) +
                                                                  " curves)");
    };
    for (size_t p = 0; p < doc.patches.size(); ++p) loops(doc.patches[p].trims, at("patches", p));
    for (size_t s = 0; s < doc.surfaces.size(); ++s) loops(doc.surfaces[s].trims, at("surfaces", s));
    for (size_t c = 0; c < doc.curves.size(); ++c) {
        const auto& l = doc.curves[c].link;
        if (!l) continue;
        const std::string path = at(at("curves", c), "link");
        if (!surfaceExists(doc, l->a)) r.fail(at(path, "a"), "surface " + surfaceRefName(l->a) + " does not exist");
        if (l->kind == CurveLinkKind::Intersect && !surfaceExists(doc, l->b))
            r.fail(at(path, "b"), "surface " + surfaceRefName(l->b) + " does not exist");
        if (l->kind == CurveLinkKind::Project && (l->source < 0 || size_t(l->source) >= c))
            r.fail(at(path, "source"), "a projection follows an earlier curve; curve " + std::to_string(l->source) + " is not one");
    }
}

}  // namespace io
}  // namespace pw

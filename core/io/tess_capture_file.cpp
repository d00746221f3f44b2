#include "core/io/tess_capture_file.hpp"

#include <charconv>
#include <cstdlib>
#include <map>

#include "core/base/file_io.hpp"
#include "core/base/json_guard.hpp"
#include "core/base/json_reader.hpp"

namespace pw {
inline namespace io {

namespace {

using json_reader::at;
using nlohmann::json;

constexpr const char* kFormat = "patchwork-tessellation-capture";
constexpr int kVersion = 1;
constexpr size_t kMaxPatterns = 4096;
constexpr size_t kMaxNumbers = size_t{1} << 22;  // 64 x 64 quads at every set of a file, many times over

// The float as the double with the fewest decimals that reads back to it: the file says 0.6
// where the float is 0.60000002384185791.
double shortest(float f) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, f);
    return std::strtod(std::string(buf, r.ptr).c_str(), nullptr);
}

}  // namespace

const TessPattern* TessCaptureFile::find(DomainKind kind, Spacing spacing, const DomainLevels& levels) const {
    for (const TessPattern& p : patterns)
        if (p.sameSet(kind, spacing, levels)) return &p;
    return nullptr;
}

std::string writeTessCaptureFile(const TessCaptureFile& f) {
    // One capture a line: the arrays of numbers stay on one line each.
    std::string out = "{\n  \"format\": " + json(kFormat).dump() + ",\n  \"version\": " + std::to_string(kVersion) + ",\n";
    out += "  \"device\": " + json(f.device).dump() + ",\n  \"driver\": " + json(f.driver).dump() +
           ",\n  \"vulkan\": " + json(f.vulkan).dump() + ",\n  \"captures\": [\n";
    for (size_t i = 0; i < f.patterns.size(); ++i) {
        const TessPattern& p = f.patterns[i];
        nlohmann::ordered_json c;  // domain, spacing and levels first, as a reader looks for them
        c["domain"] = domainName(p.kind);
        c["spacing"] = spacingName(p.spacing);
        c["outer"] = nlohmann::ordered_json::array();
        c["inner"] = nlohmann::ordered_json::array();
        for (int k = 0; k < outerLevelCount(p.kind); ++k) c["outer"].push_back(shortest(p.levels.outer[size_t(k)]));
        for (int k = 0; k < innerLevelCount(p.kind); ++k) c["inner"].push_back(shortest(p.levels.inner[size_t(k)]));
        // Each distinct point once, the primitives as indices into them (in the order emitted).
        std::map<std::array<float, 2>, size_t> index;
        c["points"] = nlohmann::ordered_json::array();
        c["primitives"] = nlohmann::ordered_json::array();
        for (const auto& q : p.uv) {
            auto [it, added] = index.emplace(q, index.size());
            if (added) {
                c["points"].push_back(shortest(q[0]));
                c["points"].push_back(shortest(q[1]));
            }
            c["primitives"].push_back(it->second);
        }
        out += "    " + c.dump() + (i + 1 < f.patterns.size() ? ",\n" : "\n");
    }
    return out + "  ]\n}\n";
}

TessCaptureFile readTessCaptureFile(const std::string& text, const std::string& source) {
    const json root = parseJsonGuarded(text, source);
    const json_reader::Reader r(source);
    r.object(root, "");
    const std::string format = r.string(*r.member(root, "", "format", true), "format");
    if (format != kFormat) r.fail("format", "'" + format + "' is not a tessellation capture (expected '" + kFormat + "')");
    const uint64_t version = r.index(*r.member(root, "", "version", true), "version", 1000, "version");
    if (version != kVersion) r.fail("version", "version " + std::to_string(version) + " is not supported (this Patchwork reads 1)");
    TessCaptureFile f;
    f.device = r.string(*r.member(root, "", "device", true), "device");
    r.optional(root, "", "driver", [&](const json& v, const std::string& p) { f.driver = r.string(v, p); });
    r.optional(root, "", "vulkan", [&](const json& v, const std::string& p) { f.vulkan = r.string(v, p); });
    const json& caps = r.array(*r.member(root, "", "captures", true), "captures", kMaxPatterns, "captures");
    size_t numbers = 0;
    for (size_t i = 0; i < caps.size(); ++i) {
        const std::string path = at("captures", i);
        const json& c = r.object(caps[i], path);
        TessPattern p;
        p.kind = r.named<DomainKind>(*r.member(c, path, "domain", true), at(path, "domain"), parseDomain, "quad, tri, isoline");
        p.spacing = r.named<Spacing>(*r.member(c, path, "spacing", true), at(path, "spacing"), parseSpacing,
                                     "equal, fractional_odd, fractional_even, pow2");
        const auto levels = [&](const char* key, float* out, size_t n) {
            const json& a = r.fixedArray(*r.member(c, path, key, true), at(path, key), n);
            for (size_t k = 0; k < n; ++k) out[k] = r.floatValue(a[k], at(at(path, key), k), 0.0, limits::kMaxTessLevel);
        };
        p.levels.outer = {0, 0, 0, 0};
        p.levels.inner = {0, 0};
        levels("outer", p.levels.outer.data(), size_t(outerLevelCount(p.kind)));
        levels("inner", p.levels.inner.data(), size_t(innerLevelCount(p.kind)));
        const std::string pp = at(path, "points"), pr = at(path, "primitives");
        const json& pts = r.array(*r.member(c, path, "points", true), pp, kMaxNumbers, "numbers");
        const json& prims = r.array(*r.member(c, path, "primitives", true), pr, kMaxNumbers, "indices");
        numbers += pts.size() + prims.size();
        if (numbers > kMaxNumbers) r.fail(path, "the file holds more than " + std::to_string(kMaxNumbers) + " numbers");
        if (pts.size() % 2) r.fail(pp, "expected u, v pairs, found " + std::to_string(pts.size()) + " numbers");
        if (prims.size() % size_t(p.vertsPerPrimitive()))
            r.fail(pr, std::to_string(prims.size()) + " indices are not whole primitives of " + std::to_string(p.vertsPerPrimitive()));
        std::vector<std::array<float, 2>> points(pts.size() / 2);
        for (size_t k = 0; k < points.size(); ++k) {
            points[k] = {r.floatValue(pts[2 * k], at(pp, 2 * k), -1e-4, 1.0001),
                         r.floatValue(pts[2 * k + 1], at(pp, 2 * k + 1), -1e-4, 1.0001)};
            if (p.kind == DomainKind::Triangle && points[k][0] + points[k][1] > 1.0001f)
                r.fail(at(pp, 2 * k), "u + v is " + json_reader::Reader::shortNumber(points[k][0] + points[k][1]) +
                                          ", outside the triangle domain (u + v <= 1)");
        }
        p.uv.reserve(prims.size());
        for (size_t k = 0; k < prims.size(); ++k) p.uv.push_back(points[r.index(prims[k], at(pr, k), points.size(), "point")]);
        if (f.find(p.kind, p.spacing, p.levels)) r.fail(path, describeSet(p.kind, p.spacing, p.levels) + " is captured twice");
        f.patterns.push_back(std::move(p));
    }
    return f;
}

TessCaptureFile loadTessCaptureFile(const std::filesystem::path& path) { return readTessCaptureFile(readFileLimited(path), path.string()); }

}  // namespace io
}  // namespace pw

#include "hostile/hostile_files.hpp"

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <utility>

#include "core/base/file_io.hpp"
#include "core/io/glb_container.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/net_ops.hpp"
#include "core/ops/patch_ops.hpp"

namespace pw::hostile {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A .patchwork seed with every kind of content: patches with a join, a net, triangles and a curve.
std::string richDocument() {
    Document d;
    addFlatPatch(d, Vec3(0.0), 1.0);
    addFlatPatch(d, Vec3(1.0, 0.0, 0.0), 1.0);
    joinEdges(d, 0, Edge::U1, 1, Edge::U0, Continuity::C1);
    addNetSurface(d, 4, 5, NetShape::Tube, Basis::BSpline, Vec3(0.0, 3.0, 0.0), 1.0);
    addTriangle(d, Vec3(-2.0, 0.0, 0.0), 1.0);
    addCurve(d, Vec3(0.0, -2.0, 0.0), 1.0);
    return serializeDocument(d);
}

std::vector<std::string> dictionary(const fs::path& repository, const std::string& format) {
    std::vector<std::string> tokens;
    std::ifstream in(repository / "fuzz" / (format + ".dict"));
    for (std::string line; std::getline(in, line);) {
        if (line.size() < 2 || line.front() != '"') continue;
        const std::string body = line.substr(1, line.size() - 2);
        std::string token;
        for (size_t i = 0; i < body.size(); ++i) {
            if (body[i] != '\\' || i + 1 == body.size()) {
                token += body[i];
            } else if (body[i + 1] == 'x' && i + 3 < body.size()) {
                token += static_cast<char>(std::stoi(body.substr(i + 2, 2), nullptr, 16));
                i += 3;
            } else {
                const char c = body[++i];
                token += c == 'n' ? '\n' : c == 'r' ? '\r' : c == 't' ? '\t' : c;
            }
        }
        tokens.push_back(token);
    }
    return tokens;
}

std::string mutate(std::string s, std::mt19937& rng, const std::vector<std::string>& dict) {
    auto pick = [&](size_t n) { return n == 0 ? size_t(0) : std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
    const int rounds = 1 + int(pick(3));
    for (int r = 0; r < rounds && !s.empty(); ++r) {
        const size_t at = pick(s.size());
        const size_t span = 1 + pick(std::min<size_t>(64, s.size() - at));
        switch (pick(6)) {
            case 0:
                s.resize(at);
                break;  // truncate
            case 1:
                s[at] = static_cast<char>(s[at] ^ (1 << pick(8)));
                break;  // flip a bit
            case 2:
                s.erase(at, span);
                break;  // delete
            case 3:
                s.insert(at, s.substr(at, span));
                break;  // duplicate
            case 4:
                s.insert(at, dict[pick(dict.size())]);
                break;  // splice a token
            default:
                s.replace(at, span, dict[pick(dict.size())]);
                break;
        }
    }
    return s;
}

using JsonCase = std::pair<std::string, std::function<void(json&)>>;

// glTF breakage the structure check must report with this field.
std::vector<JsonCase> structuralCases() {
    return {
        {"asset", [](json& g) { g.erase("asset"); }},
        {"asset.version", [](json& g) { g["asset"]["version"] = 2; }},
        {"scene", [](json& g) { g["scene"] = 5; }},
        {"scenes[0].nodes[0]", [](json& g) { g["scenes"][0]["nodes"] = {"a"}; }},
        {"scenes[0].nodes[0]", [](json& g) { g["scenes"][0]["nodes"] = {9}; }},
        {"nodes", [](json& g) { g["nodes"] = 3; }},
        {"nodes[0]", [](json& g) { g["nodes"][0] = 1; }},
        {"nodes[0].mesh", [](json& g) { g["nodes"][0]["mesh"] = 99; }},
        {"nodes[0].children[0]", [](json& g) { g["nodes"][0]["children"] = {1}; }},
        {"nodes[0].matrix",
         [](json& g) {
             g["nodes"][0]["matrix"] = json::array({1, 0, 0});
         }},
        {"nodes[0].rotation[2]",
         [](json& g) {
             g["nodes"][0]["rotation"] = {0, 0, "x", 1};
         }},
        {"nodes[0].camera", [](json& g) { g["nodes"][0]["camera"] = 0; }},
        {"meshes[0].primitives", [](json& g) { g["meshes"][0]["primitives"] = json::array(); }},
        {"meshes[0].primitives[0]", [](json& g) { g["meshes"][0]["primitives"][0] = "tri"; }},
        {"meshes[0].primitives[0].attributes", [](json& g) { g["meshes"][0]["primitives"][0].erase("attributes"); }},
        {"meshes[0].primitives[0].attributes.POSITION", [](json& g) { g["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 999; }},
        {"meshes[0].primitives[0].attributes.NORMAL", [](json& g) { g["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 1.5; }},
        {"meshes[0].primitives[0].indices", [](json& g) { g["meshes"][0]["primitives"][0]["indices"] = -1; }},
        {"meshes[0].primitives[0].material", [](json& g) { g["meshes"][0]["primitives"][0]["material"] = 4; }},
        {"meshes[0].primitives[0].mode", [](json& g) { g["meshes"][0]["primitives"][0]["mode"] = 9; }},
        {"accessors[0].componentType", [](json& g) { g["accessors"][0]["componentType"] = 1; }},
        {"accessors[0].componentType", [](json& g) { g["accessors"][0].erase("componentType"); }},
        {"accessors[1].count", [](json& g) { g["accessors"][1]["count"] = 0; }},
        {"accessors[1].count", [](json& g) { g["accessors"][1]["count"] = 4294967297.5; }},
        {"accessors[2].type", [](json& g) { g["accessors"][2]["type"] = "VEC5"; }},
        {"accessors[2].bufferView", [](json& g) { g["accessors"][2]["bufferView"] = 99; }},
        {"accessors[3].byteOffset", [](json& g) { g["accessors"][3]["byteOffset"] = -4; }},
        {"accessors[0].min[1]", [](json& g) { g["accessors"][0]["min"][1] = nullptr; }},
        {"bufferViews[0].buffer", [](json& g) { g["bufferViews"][0]["buffer"] = 7; }},
        {"bufferViews[0].byteLength", [](json& g) { g["bufferViews"][0].erase("byteLength"); }},
        {"bufferViews[1].byteStride", [](json& g) { g["bufferViews"][1]["byteStride"] = 6; }},
        {"bufferViews[1].target", [](json& g) { g["bufferViews"][1]["target"] = 1; }},
        {"buffers[0].byteLength", [](json& g) { g["buffers"][0]["byteLength"] = 0; }},
        {"buffers[0].byteLength", [](json& g) { g["buffers"][0]["byteLength"] = "12"; }},
        {"materials", [](json& g) { g["materials"] = json::object(); }},
        {"images[0]", [](json& g) { g["images"] = {1}; }},
        {"asset.extras.patchwork.points[0]", [](json& g) { g["asset"]["extras"]["patchwork"]["points"][0] = "p"; }},
        {"asset.extras.patchwork.patches[1].idx[3]", [](json& g) { g["asset"]["extras"]["patchwork"]["patches"][1]["idx"][3] = 1e9; }},
        {"asset.extras.patchwork", [](json& g) { g["asset"]["extras"]["patchwork"] = json::array(); }},
    };
}

// Cases that only make sense for one container.
std::vector<JsonCase> gltfOnlyCases() {
    return {
        {"buffers[0].uri", [](json& g) { g["buffers"][0]["uri"] = "../../etc/passwd"; }},
        {"buffers[0].uri", [](json& g) { g["buffers"][0].erase("uri"); }},
        {"buffers[0].uri", [](json& g) { g["buffers"][0]["uri"] = g["buffers"][0]["uri"].get<std::string>() + "AAAA"; }},
        {"buffers[0].uri", [](json& g) { g["buffers"][0]["uri"] = g["buffers"][0]["uri"].get<std::string>().substr(0, 60) + "*"; }},
    };
}

// STEP text with its first `from` replaced by `to` (unchanged when absent).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    if (const size_t at = text.find(from); at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// The hostile CAD values, each in the good seed: STEP numbers, knots and entity sizes.
std::vector<std::pair<std::string, std::string>> stepCases(const std::string& step) {
    const std::string point = "CARTESIAN_POINT('',(0.,0.,0.));";
    std::string many = "CARTESIAN_POINT('',(";
    for (int i = 0; i < 200'001; ++i) many += "0.,";
    many += "0.));";
    std::vector<std::pair<std::string, std::string>> out;
    // Each of these is refused by the value check (core/io/cad_values) before OpenCASCADE reads.
    for (const std::string v : {"inf", "nan", "1.E309", "-1.E999", "1.E308", "-inf", "1.0D999"})
        out.emplace_back("value-" + v, replaced(step, point, "CARTESIAN_POINT('',(" + v + ",0.,0.));"));
    out.emplace_back("digits", replaced(step, point, "CARTESIAN_POINT('',(0." + std::string(10'000, '3') + ",0.,0.));"));
    out.emplace_back("many-values", replaced(step, point, many));
    out.emplace_back("knots-1e308", replaced(step, "(4,4),(0.,1.)", "(4,4),(0.,1.E308)"));
    out.emplace_back("degree-huge", replaced(step, "B_SPLINE_SURFACE_WITH_KNOTS('',3,3,", "B_SPLINE_SURFACE_WITH_KNOTS('',99999999,3,"));
    return out;
}

}  // namespace

std::vector<HostileFile> generateHostileFiles(const fs::path& dir, const GenerateOptions& options) {
    std::vector<HostileFile> files;
    const fs::path good = options.repository / "tests" / "corpus" / "good";
    auto add = [&](const std::string& name, const std::string& bytes, HostileFile f = {}) {
        writeFileAtomic(dir / name, bytes);
        f.file = dir / name;
        const std::string ext = f.file.extension().string();
        f.cad = ext == ".step" || ext == ".igs";
        files.push_back(f);
    };
    const std::string gltf = readFileLimited(good / "teacup-l1.gltf");
    const std::string glb = readFileLimited(good / "teaspoon-l1.glb");
    const GlbParts glbParts = splitGlb(glb, "seed");
    int n = 0;
    for (const auto& [field, apply] : structuralCases()) {
        json g = json::parse(gltf);
        apply(g);
        add("struct" + std::to_string(n) + ".gltf", g.dump(1), {.expectField = field, .mustRefuse = true});
        json b = json::parse(glbParts.json);
        apply(b);
        add("struct" + std::to_string(n++) + ".glb", joinGlb(b.dump(), glbParts.rest), {.expectField = field, .mustRefuse = true});
    }
    for (const auto& [field, apply] : gltfOnlyCases()) {
        json g = json::parse(gltf);
        apply(g);
        add("struct" + std::to_string(n++) + ".gltf", g.dump(1), {.expectField = field, .mustRefuse = true});
    }
    struct Seed {
        std::string name, format, bytes;
    };
    std::vector<Seed> seeds = {
        {"teapot.bpt", "bpt", readFileLimited(options.repository / "data" / "teapot.bpt")},
        {"teaspoon.bpt", "bpt", readFileLimited(options.repository / "data" / "teaspoon.bpt")},
        {"teacup.patchwork", "patchwork", readFileLimited(good / "teacup.patchwork")},
        {"rich.patchwork", "patchwork", richDocument()},
        {"teacup.gltf", "gltf", gltf},
        {"teaspoon.glb", "gltf", glb},
    };
    if (options.cad) {
        const std::string step = readFileLimited(good / "flat.step"), iges = readFileLimited(good / "flat.igs");
        seeds.push_back({"flat.step", "cad_values", step});
        seeds.push_back({"flat.igs", "cad_values", iges});
        for (const auto& [name, text] : stepCases(step)) add("cad-" + name + ".step", text, {.mustRefuse = true});
        // IGES: the first parameter-section record (column 73 'P') made a B-spline surface entity
        // whose first value is hostile, the record's 64 columns kept.
        size_t record = 0;
        while (record < iges.size() && !(iges.size() > record + 72 && iges[record + 72] == 'P')) record = iges.find('\n', record) + 1;
        if (record < iges.size())
            for (const std::string v : {"1.0D999", "inf", "1.E13", "-1.E309"}) {
                std::string text = iges, params = "128," + v + ";";
                params.resize(64, ' ');
                text.replace(record, 64, params);
                add("cad-pole-" + v + ".igs", text, {.mustRefuse = true});
            }
    }
    // Counts beyond the limits, refused from the header.
    std::string onePatch = "3 3\n";
    for (int k = 0; k < 16; ++k) onePatch += std::to_string(k % 4) + " " + std::to_string(k / 4) + " 0\n";
    for (const char* count : {"300000", "1000000", "1000001", "99999999999999999999999", "-1", "0x10"})
        add(std::string("count-") + count + ".bpt", std::string(count) + "\n" + onePatch, {.mustRefuse = true});
    if (options.large) {
        // A million identical patches (100 MB): refused at line 1 in well under a second.
        std::string text = "1000000\n";
        text.reserve(101'000'000);
        for (int p = 0; p < 1'000'000; ++p) text += onePatch;
        add("large-million-identical.bpt", text, {.mustRefuse = true, .large = true});
        // 62 500 patches on a grid, each with its own points: read, joined (124 000 joins), in seconds.
        text = "62500\n";
        char buf[64];
        for (int a = 0; a < 250; ++a)
            for (int b = 0; b < 250; ++b) {
                text += "3 3\n";
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j) {
                        std::snprintf(buf, sizeof buf, "%.6f %.6f 0\n", b + j / 3.0, a + i / 3.0);
                        text += buf;
                    }
            }
        add("large-grid-62500.bpt", text, {.large = true});
    }
    std::mt19937 rng(20261125);
    for (const Seed& seed : seeds) {
        const auto dict = dictionary(options.repository, seed.format);
        const std::string ext = fs::path(seed.name).extension().string();
        for (int i = 0; i < options.mutationsPerSeed; ++i) {
            // GLB: mostly the JSON chunk, re-wrapped so the container stays valid; sometimes raw bytes.
            std::string bytes;
            if (ext == ".glb" && i % 4 != 0) {
                const GlbParts p = splitGlb(seed.bytes, "seed");
                bytes = joinGlb(mutate(std::string(p.json), rng, dict), p.rest);
            } else {
                bytes = mutate(seed.bytes, rng, dict);
            }
            add("m" + std::to_string(i) + "-" + seed.name, bytes);
        }
    }
    return files;
}

}  // namespace pw::hostile

#include "core/io/gltf_import.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/json_guard.hpp"
#include "core/io/glb_container.hpp"
#include "core/io/gltf_structure.hpp"
#include "core/io/patchwork_format.hpp"

namespace pw {
inline namespace io {

namespace {

// Files exported before the document was spliced in as text went through tinygltf's writer, which
// drops empty objects and nulls from extras and writes an empty array as null. Put them back where
// the native format has a container or a null, using documentToJson of a document with one of
// everything as the template of the keys.
void restoreDroppedEmpties(nlohmann::json& j, const nlohmann::json& tmpl) {
    if (!j.is_object() || !tmpl.is_object()) return;
    for (auto it = tmpl.begin(); it != tmpl.end(); ++it) {
        const nlohmann::json& t = it.value();
        auto found = j.find(it.key());
        if (found == j.end() || found->is_null()) {
            if (t.is_array()) {
                j[it.key()] = nlohmann::json::array();
            } else if (t.is_object()) {
                nlohmann::json o = nlohmann::json::object();
                restoreDroppedEmpties(o, t);
                j[it.key()] = std::move(o);
            } else if (t.is_null()) {
                j[it.key()] = nullptr;
            }
            // A missing scalar was not dropped by tinygltf: documentFromJson reports it.
        } else if (found->is_object()) {
            restoreDroppedEmpties(*found, t);
        } else if (found->is_array() && t.is_array() && !t.empty() && t.front().is_object()) {
            for (nlohmann::json& e : *found) restoreDroppedEmpties(e, t.front());
        }
    }
}

const nlohmann::json& documentTemplate() {
    static const nlohmann::json tmpl = [] {
        Document d;
        d.points.assign(16, Vec3(0.0));
        d.patches.emplace_back();
        Surface s;
        s.idx.assign(16, 0);
        d.surfaces.push_back(s);
        d.joins.emplace_back();
        return documentToJson(d);
    }();
    return tmpl;
}

// The "patchwork" extras and where they are: asset.extras, a scene's extras, or the top level's.
std::pair<nlohmann::json*, std::string> findPatchworkExtras(nlohmann::json& gltf) {
    auto look = [](nlohmann::json& owner) -> nlohmann::json* {
        if (!owner.is_object()) return nullptr;
        const auto extras = owner.find("extras");
        if (extras == owner.end() || !extras->is_object()) return nullptr;
        const auto p = extras->find("patchwork");
        return p == extras->end() ? nullptr : &*p;
    };
    if (const auto a = gltf.find("asset"); a != gltf.end())
        if (auto* v = look(*a)) return {v, "asset.extras.patchwork"};
    if (const auto sc = gltf.find("scenes"); sc != gltf.end() && sc->is_array())
        for (size_t i = 0; i < sc->size(); ++i)
            if (auto* v = look((*sc)[i])) return {v, "scenes[" + std::to_string(i) + "].extras.patchwork"};
    if (auto* v = look(gltf)) return {v, "extras.patchwork"};
    return {nullptr, {}};
}

// Import needs only the extras: external buffers and images are refused, images not decoded.
bool refuseExternalFile(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
    if (err) *err += "external file '" + path + "' not read (Patchwork glTF files are self-contained)";
    return false;
}
bool fileNeverExists(const std::string&, void*) { return false; }
std::string keepPath(const std::string& path, void*) { return path; }
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; }

}  // namespace

Document importPatchworkGltf(const std::filesystem::path& path, std::optional<ExportOptions>* exportOptions) {
    return parsePatchworkGltf(readFileLimited(path), path.string(), exportOptions);
}

namespace {
// `owned`: the string `data` views, released once the reader's input is made.
Document parseGltf(std::string_view data, std::string* owned, const std::string& name, std::optional<ExportOptions>* exportOptions) {
    tinygltf::TinyGLTF loader;
    tinygltf::FsCallbacks fs{};
    fs.FileExists = fileNeverExists;
    fs.ExpandFilePath = keepPath;
    fs.ReadWholeFile = refuseExternalFile;
    fs.WriteWholeFile = nullptr;
    loader.SetFsCallbacks(fs);
    loader.SetImageLoader(skipImage, nullptr);
    const bool binary = data.size() >= 4 && std::memcmp(data.data(), "glTF", 4) == 0;
    const char* kind = binary ? "binary (.glb)" : "JSON (.gltf)";
    // Our own pass first, guarded: the glTF reader recurses without a depth limit, and reads integers
    // as 32 bits (an index 2^32 + 1 would become 1).
    const GlbParts glb = binary ? splitGlb(data, name) : GlbParts{data, {}};
    nlohmann::json gltf = parseJsonGuarded(glb.json, name);
    if (!gltf.is_object()) throw InputError(name, std::string("not a valid glTF ") + kind + " file: the JSON is not an object");
    checkGltfStructure(gltf, name, binary, binary ? binChunkBytes(glb.rest, name) : 0);

    // The document leaves the DOM here; the glTF reader then checks the rest of the structure
    // (asset, accessors, views, chunks) without it: its own DOM of a million patches took 4 GB.
    auto [extras, field] = findPatchworkExtras(gltf);
    std::optional<ExportOptions> options;
    if (const auto a = gltf.find("asset"); a != gltf.end() && a->is_object())
        if (const auto x = a->find("extras"); x != a->end() && x->is_object())
            if (const auto o = x->find("patchworkExport"); o != x->end()) options = exportOptionsFromJson(*o, name);
    nlohmann::json json;
    if (extras) {
        json = std::move(*extras);
        *extras = nlohmann::json::object();
    }
    // The glTF reader copies the BIN chunk into its buffer and reads nothing of it: the buffer's
    // size and every view and accessor against it were checked above, and the document is in the
    // extras. So it gets a stub of the chunk (its first 4 bytes, the buffer said to be that long):
    // a large .glb is then held once while it is read, not three times.
    std::string_view after = glb.rest;
    std::string stub;
    const auto buffers = gltf.find("buffers");
    if (const size_t binBytes = binary ? binChunkBytes(glb.rest, name) : 0;
        binBytes > 4 && buffers != gltf.end() && buffers->is_array() && !buffers->empty()) {
        nlohmann::json& buffer = buffers->front();  // checked above: an object with an integer byteLength
        if (!buffer.contains("uri")) {
            buffer["byteLength"] = std::min<int64_t>(buffer.at("byteLength").get<int64_t>(), 4);
            const uint32_t length = 4;
            stub.append(reinterpret_cast<const char*>(&length), 4);
            stub.append(glb.rest.substr(4, 4));  // the chunk type: BIN
            stub.append(glb.rest.substr(8, 4));
            after = glb.rest.substr(8 + binBytes);  // chunks after the BIN chunk, as stored
        }
    }
    const std::string rest = binary ? joinGlb(gltf.dump(), std::vector<std::string_view>{stub, after}) : gltf.dump();
    if (owned) {  // `data` and `glb` are not used again
        owned->clear();
        owned->shrink_to_fit();
    }
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(rest.data()),
                                                  static_cast<unsigned int>(rest.size()), "")
                    : loader.LoadASCIIFromString(&model, &err, &warn, rest.data(), static_cast<unsigned int>(rest.size()), "");
    } catch (const std::exception& e) {
        throw InputError(name, std::string("not a valid glTF ") + kind + " file: the glTF reader stopped on it (" + e.what() + ")");
    }
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        for (char& c : err)
            if (c == '\n') c = ' ';
        throw InputError(name, std::string("not a valid glTF ") + kind + " file" + (err.empty() ? std::string() : ": " + err));
    }

    if (!extras)
        throw InputError(name,
                         "not a Patchwork glTF: it has no patchwork extras (only files exported by Patchwork "
                         "can be imported as patches)",
                         0, "asset.extras.patchwork");
    if (!json.is_object()) throw InputError(name, "the patchwork extras are not an object", 0, field);
    restoreDroppedEmpties(json, documentTemplate());
    Document doc = documentFromJson(json, name, field);
    if (exportOptions) *exportOptions = options;
    return doc;
}
}  // namespace

Document parsePatchworkGltf(std::string_view data, const std::string& name, std::optional<ExportOptions>* exportOptions) {
    return parseGltf(data, nullptr, name, exportOptions);
}

Document parsePatchworkGltf(std::string&& data, const std::string& name, std::optional<ExportOptions>* exportOptions) {
    std::string owned = std::move(data);
    return parseGltf(owned, &owned, name, exportOptions);
}

}  // namespace io
}  // namespace pw

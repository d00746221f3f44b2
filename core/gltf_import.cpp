#include "core/gltf_import.hpp"

#include <tiny_gltf.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <string>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/patchwork_format.hpp"

namespace pw {

namespace {

// tinygltf::Value → nlohmann::json (ints stay integers, reals stay doubles).
nlohmann::json toJson(const tinygltf::Value& v) {
    switch (v.Type()) {
        case tinygltf::BOOL_TYPE: return v.Get<bool>();
        case tinygltf::INT_TYPE: return v.Get<int>();
        case tinygltf::REAL_TYPE: return v.Get<double>();
        case tinygltf::STRING_TYPE: return v.Get<std::string>();
        case tinygltf::ARRAY_TYPE: {
            nlohmann::json a = nlohmann::json::array();
            for (const tinygltf::Value& e : v.Get<tinygltf::Value::Array>()) a.push_back(toJson(e));
            return a;
        }
        case tinygltf::OBJECT_TYPE: {
            nlohmann::json o = nlohmann::json::object();
            for (const auto& [key, e] : v.Get<tinygltf::Value::Object>()) o[key] = toJson(e);
            return o;
        }
        default: return nullptr;
    }
}

// tinygltf drops empty arrays, empty objects and nulls from extras when it reads them (and writes
// an empty array as null). Put them back where the native format has a container or a null, using
// documentToJson of a document with one of everything as the template of the keys.
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

const tinygltf::Value* findPatchworkExtras(const tinygltf::Model& model) {
    auto look = [](const tinygltf::Value& extras) -> const tinygltf::Value* {
        if (!extras.IsObject() || !extras.Has("patchwork")) return nullptr;
        return &extras.Get("patchwork");
    };
    if (const auto* v = look(model.asset.extras)) return v;
    for (const tinygltf::Scene& s : model.scenes)
        if (const auto* v = look(s.extras)) return v;
    return look(model.extras);
}

// Import needs only the extras: external buffers and images are refused, images not decoded.
bool refuseExternalFile(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
    if (err) *err += "external file '" + path + "' not read (Patchwork glTF files are self-contained)";
    return false;
}
bool fileNeverExists(const std::string&, void*) { return false; }
std::string keepPath(const std::string& path, void*) { return path; }
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

}  // namespace

Document importPatchworkGltf(const std::filesystem::path& path) {
    return parsePatchworkGltf(readFileLimited(path), path.string());
}

Document parsePatchworkGltf(std::string_view data, const std::string& name) {
    tinygltf::TinyGLTF loader;
    tinygltf::FsCallbacks fs{};
    fs.FileExists = fileNeverExists;
    fs.ExpandFilePath = keepPath;
    fs.ReadWholeFile = refuseExternalFile;
    fs.WriteWholeFile = nullptr;
    loader.SetFsCallbacks(fs);
    loader.SetImageLoader(skipImage, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const bool binary = data.size() >= 4 && std::memcmp(data.data(), "glTF", 4) == 0;
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(data.data()),
                                             static_cast<unsigned int>(data.size()), "")
               : loader.LoadASCIIFromString(&model, &err, &warn, data.data(), static_cast<unsigned int>(data.size()), "");
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        for (char& c : err)
            if (c == '\n') c = ' ';
        throw InputError(name, std::string("not a valid glTF ") + (binary ? "binary (.glb)" : "JSON (.gltf)") + " file" +
                                   (err.empty() ? std::string() : ": " + err));
    }

    const tinygltf::Value* extras = findPatchworkExtras(model);
    if (!extras)
        throw InputError(name, "not a Patchwork glTF: it has no patchwork extras (only files exported by Patchwork "
                               "can be imported as patches)");
    if (!extras->IsObject()) throw InputError(name, "the patchwork extras are not an object", 0, "asset.extras.patchwork");
    nlohmann::json json = toJson(*extras);
    restoreDroppedEmpties(json, documentTemplate());
    return documentFromJson(json, name);
}

}  // namespace pw

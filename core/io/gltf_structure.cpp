#include "core/io/gltf_structure.hpp"

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <string_view>

#include "core/base/errors.hpp"
#include "core/base/json_reader.hpp"

namespace pw {
inline namespace io {

namespace {

using nlohmann::json;

using json_reader::at;  // "path[3]" and "path.key"

std::string found(const json& v) {
    std::string text = v.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return text;
}

// Decoded size of base64 text, or -1 when it holds anything but the alphabet and end padding.
int64_t base64Bytes(std::string_view text) {
    size_t n = text.size();
    while (n > 0 && text[n - 1] == '=' && text.size() - n < 2) --n;
    for (size_t i = 0; i < n; ++i) {
        const char c = text[i];
        const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '/';
        if (!ok) return -1;
    }
    return static_cast<int64_t>(n * 3 / 4);
}

class Checker {
public:
    Checker(const json& root, const std::string& name) : root_(root), name_(name) {}

    [[noreturn]] void fail(const std::string& field, const std::string& what) const { throw InputError(name_, what, 0, field); }

    // The array `key` of the root (empty when absent), each element checked to be an object.
    const json& array(const char* key) const {
        static const json empty = json::array();
        const auto it = root_.find(key);
        if (it == root_.end()) return empty;
        if (!it->is_array()) fail(key, "expected an array, found " + found(*it));
        for (size_t i = 0; i < it->size(); ++i)
            if (!(*it)[i].is_object()) fail(at(key, i), "expected an object, found " + found((*it)[i]));
        return *it;
    }

    // obj[key] as an integer in [lo, hi]; nullptr when absent and optional.
    const json* integer(const json& obj, const char* key, const std::string& path, int64_t lo, int64_t hi, bool required = false) const {
        const auto it = obj.find(key);
        const std::string field = at(path, key);
        if (it == obj.end()) {
            if (required) fail(field, "required (glTF 2.0) but missing");
            return nullptr;
        }
        checkInteger(*it, field, lo, hi);
        return &*it;
    }

    void checkInteger(const json& v, const std::string& field, int64_t lo, int64_t hi) const {
        bool inRange = false;
        if (v.is_number_unsigned()) {
            const uint64_t u = v.get<uint64_t>();
            inRange = u <= static_cast<uint64_t>(hi) && (lo <= 0 || u >= static_cast<uint64_t>(lo));
        } else if (v.is_number_integer()) {
            inRange = v.get<int64_t>() >= lo && v.get<int64_t>() <= hi;
        }
        if (!inRange) fail(field, "expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", found " + found(v));
    }

    // obj[key] as an index into the root array `into`.
    void index(const json& obj, const char* key, const std::string& path, const char* into, bool required = false) const {
        const size_t n = sizeOf(into);
        const auto it = obj.find(key);
        if (it != obj.end() && n == 0) fail(at(path, key), std::string("refers to ") + into + ", but the file has none");
        integer(obj, key, path, 0, static_cast<int64_t>(n) - 1, required);
    }

    void enumOf(const json& obj, const char* key, const std::string& path, std::initializer_list<int64_t> allowed, bool required) const {
        const json* v = integer(obj, key, path, INT64_MIN, INT64_MAX, required);
        if (v && std::find(allowed.begin(), allowed.end(), v->get<int64_t>()) == allowed.end())
            fail(at(path, key), "not one of glTF 2.0's values for it, found " + found(*v));
    }

    void numbers(const json& obj, const char* key, const std::string& path, size_t count) const {
        const auto it = obj.find(key);
        if (it == obj.end()) return;
        const std::string field = at(path, key);
        if (!it->is_array() || (count != 0 && it->size() != count))
            fail(field, count ? "expected an array of " + std::to_string(count) + " numbers, found " + found(*it)
                              : "expected an array of numbers, found " + found(*it));
        for (size_t i = 0; i < it->size(); ++i)
            if (!(*it)[i].is_number()) fail(at(field, i), "expected a number, found " + found((*it)[i]));
    }

    void indices(const json& obj, const char* key, const std::string& path, const char* into) const {
        const auto it = obj.find(key);
        if (it == obj.end()) return;
        const std::string field = at(path, key);
        if (!it->is_array()) fail(field, "expected an array of indices into " + std::string(into) + ", found " + found(*it));
        const int64_t n = static_cast<int64_t>(sizeOf(into));
        for (size_t i = 0; i < it->size(); ++i) checkInteger((*it)[i], at(field, i), 0, n - 1);
    }

    const json& string(const json& obj, const char* key, const std::string& path, bool required) const {
        static const json none;
        const auto it = obj.find(key);
        if (it == obj.end()) {
            if (required) fail(at(path, key), "required (glTF 2.0) but missing");
            return none;
        }
        if (!it->is_string()) fail(at(path, key), "expected a string, found " + found(*it));
        return *it;
    }

private:
    size_t sizeOf(const char* key) const {
        const auto it = root_.find(key);
        return it != root_.end() && it->is_array() ? it->size() : 0;
    }

    const json& root_;
    const std::string& name_;
};

void checkBuffers(const Checker& c, bool binary, size_t binBytes) {
    const json& buffers = c.array("buffers");
    for (size_t i = 0; i < buffers.size(); ++i) {
        const json& b = buffers[i];
        const std::string path = at("buffers", i);
        const int64_t length = c.integer(b, "byteLength", path, 1, INT64_MAX, true)->get<int64_t>();
        const json& uri = c.string(b, "uri", path, !(binary && i == 0));
        if (uri.is_null()) {
            if (binBytes == 0) c.fail(path, "refers to the GLB's BIN chunk, but the file has none");
            if (static_cast<uint64_t>(length) > binBytes)
                c.fail(path + ".byteLength", std::to_string(length) + " bytes, but the BIN chunk holds " + std::to_string(binBytes));
            continue;
        }
        const std::string& text = uri.get_ref<const std::string&>();
        const size_t comma = text.find(',');
        const std::string_view head = std::string_view(text).substr(0, comma == std::string::npos ? 0 : comma + 1);
        if (head != "data:application/octet-stream;base64," && head != "data:application/gltf-buffer;base64,")
            c.fail(path + ".uri", found(uri) + " is not an embedded base64 buffer (Patchwork glTF files are self-contained)");
        const int64_t bytes = base64Bytes(std::string_view(text).substr(comma + 1));
        if (bytes < 0) c.fail(path + ".uri", "the base64 data holds a character outside base64");
        if (bytes != length)
            c.fail(path + ".uri", "decodes to " + std::to_string(bytes) + " bytes, but byteLength is " + std::to_string(length));
    }
}

void checkViewsAndAccessors(const Checker& c) {
    const json& views = c.array("bufferViews");
    for (size_t i = 0; i < views.size(); ++i) {
        const std::string path = at("bufferViews", i);
        c.index(views[i], "buffer", path, "buffers", true);
        c.integer(views[i], "byteLength", path, 1, INT64_MAX, true);
        c.integer(views[i], "byteOffset", path, 0, INT64_MAX);
        if (const json* s = c.integer(views[i], "byteStride", path, 4, 252); s && s->get<int64_t>() % 4 != 0)
            c.fail(path + ".byteStride", "expected a multiple of 4, found " + found(*s));
        c.enumOf(views[i], "target", path, {34962, 34963}, false);
    }
    const json& accessors = c.array("accessors");
    for (size_t i = 0; i < accessors.size(); ++i) {
        const json& a = accessors[i];
        const std::string path = at("accessors", i);
        c.index(a, "bufferView", path, "bufferViews");
        c.integer(a, "byteOffset", path, 0, INT64_MAX);
        c.enumOf(a, "componentType", path, {5120, 5121, 5122, 5123, 5125, 5126}, true);
        c.integer(a, "count", path, 1, INT64_MAX, true);
        const json& type = c.string(a, "type", path, true);
        static const char* const kTypes[] = {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
        if (std::none_of(std::begin(kTypes), std::end(kTypes), [&](const char* t) { return type == t; }))
            c.fail(path + ".type", "not one of SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4, found " + found(type));
        c.numbers(a, "min", path, 0);
        c.numbers(a, "max", path, 0);
    }
}

void checkSceneGraph(const Checker& c, const json& root) {
    const json& meshes = c.array("meshes");
    for (size_t i = 0; i < meshes.size(); ++i) {
        const std::string path = at("meshes", i);
        const auto prims = meshes[i].find("primitives");
        if (prims == meshes[i].end() || !prims->is_array() || prims->empty())
            c.fail(path + ".primitives", "expected an array of at least one primitive");
        for (size_t j = 0; j < prims->size(); ++j) {
            const json& p = (*prims)[j];
            const std::string pp = at(path + ".primitives", j);
            if (!p.is_object()) c.fail(pp, "expected an object, found " + found(p));
            const auto attrs = p.find("attributes");
            if (attrs == p.end() || !attrs->is_object()) c.fail(pp + ".attributes", "expected an object of accessor indices");
            for (auto it = attrs->begin(); it != attrs->end(); ++it) c.index(*attrs, it.key().c_str(), pp + ".attributes", "accessors");
            c.index(p, "indices", pp, "accessors");
            c.index(p, "material", pp, "materials");
            c.integer(p, "mode", pp, 0, 6);
        }
    }
    const json& nodes = c.array("nodes");
    for (size_t i = 0; i < nodes.size(); ++i) {
        const std::string path = at("nodes", i);
        c.indices(nodes[i], "children", path, "nodes");
        c.index(nodes[i], "mesh", path, "meshes");
        c.index(nodes[i], "camera", path, "cameras");
        c.index(nodes[i], "skin", path, "skins");
        c.numbers(nodes[i], "matrix", path, 16);
        c.numbers(nodes[i], "translation", path, 3);
        c.numbers(nodes[i], "rotation", path, 4);
        c.numbers(nodes[i], "scale", path, 3);
    }
    const json& scenes = c.array("scenes");
    for (size_t i = 0; i < scenes.size(); ++i) c.indices(scenes[i], "nodes", at("scenes", i), "nodes");
    c.index(root, "scene", "", "scenes");
}

}  // namespace

void checkGltfStructure(const json& gltf, const std::string& name, bool binary, size_t binBytes) {
    const Checker c(gltf, name);
    const auto asset = gltf.find("asset");
    if (asset == gltf.end()) c.fail("asset", "required (glTF 2.0) but missing");
    if (!asset->is_object()) c.fail("asset", "expected an object, found " + found(*asset));
    c.string(*asset, "version", "asset", true);
    for (const char* key : {"animations", "cameras", "images", "materials", "samplers", "skins", "textures"}) c.array(key);
    checkBuffers(c, binary, binBytes);
    checkViewsAndAccessors(c);
    checkSceneGraph(c, gltf);
}

}  // namespace io
}  // namespace pw

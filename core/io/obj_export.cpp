// OBJ + MTL export (obj_export.hpp): the welded mesh, positions and normals deduplicated by value.
#include "core/io/obj_export.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <unordered_map>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/up_axis.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/io/gltf_export.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/trim/trim_mesh.hpp"

namespace pw {
inline namespace io {

namespace {

// A line of a keyword and N numbers with 9 significant digits (floats round-trip): std::to_chars
// writes what printf's "%.9g" writes, without its format parsing (a quarter of an export's time).
template <size_t N>
void putFloats(std::string& out, const char* keyword, const std::array<float, N>& v) {
    char buf[16 + N * 24];
    size_t at = std::strlen(keyword);
    std::memcpy(buf, keyword, at);
    for (float x : v) {
        buf[at++] = ' ';
        at = size_t(std::to_chars(buf + at, buf + sizeof buf, double(x), std::chars_format::general, 9).ptr - buf);
    }
    buf[at++] = '\n';
    out.append(buf, at);
}

// " N" for each of `ids` (1-based OBJ indices), `sep` between the parts of one corner.
void putIds(std::string& out, std::initializer_list<uint32_t> ids, char sep) {
    char buf[40];
    char* at = buf;
    *at++ = ' ';
    bool first = true;
    for (uint32_t id : ids) {
        if (!first) *at++ = sep;
        first = false;
        at = std::to_chars(at, buf + sizeof buf, id).ptr;
    }
    out.append(buf, size_t(at - buf));
}

// Hash and equality by value (0 and -0 are one value, as for std::less on the arrays before).
template <typename T>
struct ValueHash {
    size_t operator()(const T& v) const {
        size_t h = 0;
        for (float x : v) {
            float y = x + 0.0f;  // -0 -> +0
            uint32_t bits;
            std::memcpy(&bits, &y, 4);
            h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
        }
        return h ^ (h >> 29);
    }
};

// 1-based ids of distinct values, in order of first appearance, and the values to write.
template <typename T>
std::vector<uint32_t> dedupe(const std::vector<T>& values, std::vector<T>& distinct) {
    std::unordered_map<T, uint32_t, ValueHash<T>> seen;
    seen.reserve(values.size());
    std::vector<uint32_t> id(values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        auto [it, fresh] = seen.emplace(values[i], uint32_t(distinct.size() + 1));
        if (fresh) distinct.push_back(values[i]);
        id[i] = it->second;
    }
    return id;
}

// A window is a patch's (its name, or patch_N) or a net's (surface_S_ROW_COL).
std::string groupName(const Document& doc, const PatchInstance& w) {
    if (w.patch >= 0) {
        const std::string& name = doc.patches[size_t(w.patch)].name;
        return name.empty() ? "patch_" + std::to_string(w.patch) : name;
    }
    return "surface_" + std::to_string(w.surface) + "_" + std::to_string(w.windowRow) + "_" + std::to_string(w.windowCol);
}

}  // namespace

ObjFiles exportObjText(const Document& doc, int requestedLevel, const std::string& mtlName, ObjExportStats* stats,
                       TriangleMesh* displayed) {
    const int level = resolveExportLevel(doc, requestedLevel);
    ObjExportStats st;
    st.level = level;
    st.asDisplayed = displayed != nullptr;
    const bool turn = doc.camera.zUp;
    auto up = [&](const std::array<float, 3>& p) { return turn ? zUpToYUp(p) : p; };

    TriangleMesh mesh = displayed ? std::move(*displayed) : tessellateTrimmed(doc, level);
    for (auto& p : mesh.positions) p = up(p);
    for (auto& n : mesh.normals) n = up(n);
    std::vector<std::array<float, 3>> positions, normals;
    std::vector<std::array<float, 2>> uvs;
    const std::vector<uint32_t> vid = dedupe(mesh.positions, positions);
    const std::vector<uint32_t> nid = dedupe(mesh.normals, normals);
    const std::vector<uint32_t> tid = dedupe(mesh.uvs, uvs);

    ObjFiles f;
    std::string& o = f.obj;
    o.reserve(positions.size() * 40 + normals.size() * 40 + uvs.size() * 28 + mesh.indices.size() * 12 + 1024);
    o += "# Patchwork " + std::string(doc.name.empty() ? "document" : doc.name) +
         (displayed ? std::string(", as displayed (the GPU's tessellation)") : ", level " + std::to_string(level)) + "\n";
    o += "# lengths in " + std::string(lengthUnitName(doc.unit)) + " (the document's unit; OBJ has none)\n";
    if (turn) o += "# Z-up document written +Y up: (x, y, z) -> (x, z, -y)\n";
    o += "mtllib " + mtlName + "\n";
    for (const auto& p : positions) putFloats(o, "v", p);
    for (const auto& t : uvs) putFloats(o, "vt", t);
    for (const auto& n : normals) putFloats(o, "vn", n);

    // Curve samples come after the surface's positions.
    std::vector<std::vector<uint32_t>> curveIds;
    uint32_t nextId = uint32_t(positions.size()) + 1;
    for (const BezierCurve& c : doc.curves) {
        std::vector<uint32_t> ids;
        for (const Vec3& q : sampleCurve(doc, c, level)) {
            const auto p = up({float(q.x), float(q.y), float(q.z)});
            putFloats(o, "v", p);
            ids.push_back(nextId++);
        }
        curveIds.push_back(std::move(ids));
    }

    // Each material named after the first group it applies to: assimp reads a `usemtl` before any
    // group or object as a mesh with nothing to attach to (an error in its log) when the MTL has
    // more than one material.
    bool surfaceMaterial = false;
    auto faces = [&](const MeshRange& r, const std::string& name) {
        if (r.indexCount == 0) return;
        o += "g " + name + "\n";
        if (!surfaceMaterial) o += "usemtl patchwork_surface\n", surfaceMaterial = true;
        ++st.groups;
        for (uint32_t i = r.firstIndex; i < r.firstIndex + r.indexCount; i += 3) {
            o += 'f';
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t v = mesh.indices[i + k];
                putIds(o, {vid[v], tid[v], nid[v]}, '/');
            }
            o += '\n';
        }
    };
    const std::vector<PatchInstance> windows = expandPatches(doc);
    for (size_t w = 0; w < mesh.perWindow.size(); ++w) faces(mesh.perWindow[w], groupName(doc, windows[w]));
    for (size_t t = 0; t < mesh.perTriangle.size(); ++t)
        faces(mesh.perTriangle[t], doc.triangles[t].name.empty() ? "triangle_" + std::to_string(t) : doc.triangles[t].name);
    for (size_t c = 0; c < curveIds.size(); ++c) {
        o += "g curve_" + std::to_string(c) + (c == 0 ? "\nusemtl patchwork_curves\nl" : "\nl");
        for (uint32_t id : curveIds[c]) putIds(o, {id}, ' ');
        o += '\n';
        st.lineSegments += curveIds[c].size() - 1;
    }

    f.mtl =
        "# Patchwork materials\n"
        "newmtl patchwork_surface\nKa 0 0 0\nKd 0.8 0.8 0.8\nKs 0.2 0.2 0.2\nNs 50\nd 1\nillum 2\n";
    if (!curveIds.empty()) f.mtl += "\nnewmtl patchwork_curves\nKa 0 0 0\nKd 0.85 0.45 0.1\nKs 0 0 0\nd 1\nillum 0\n";

    st.positions = positions.size();
    st.normals = normals.size();
    st.uvs = uvs.size();
    st.triangles = mesh.indices.size() / 3;
    st.bytes = f.obj.size() + f.mtl.size();
    if (stats) *stats = st;
    return f;
}

ObjExportStats exportObj(const Document& doc, const std::filesystem::path& path, int level, TriangleMesh* displayed) {
    if (lowerExtension(path) != ".obj") throw OutputError(path.string(), "an OBJ export needs the extension .obj");
    std::filesystem::path mtl = path;
    mtl.replace_extension(".mtl");
    ObjExportStats stats;
    ObjFiles files;
    try {
        files = exportObjText(doc, level, mtl.filename().string(), &stats, displayed);
    } catch (const std::bad_alloc&) {
        throw OutputError(path.string(), "not enough memory for the mesh at level " + std::to_string(resolveExportLevel(doc, level)));
    }
    // The MTL first; if the OBJ then fails, the MTL goes back to what it was.
    std::error_code ec;
    const bool hadMtl = std::filesystem::exists(mtl, ec);
    const std::string oldMtl = hadMtl ? readFileLimited(mtl) : std::string();
    writeFileAtomic(mtl, files.mtl);
    try {
        writeFileAtomic(path, files.obj);
    } catch (...) {
        if (hadMtl)
            writeFileAtomic(mtl, oldMtl);
        else
            std::filesystem::remove(mtl, ec);
        throw;
    }
    return stats;
}

}  // namespace io
}  // namespace pw

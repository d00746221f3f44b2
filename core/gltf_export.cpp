// glTF 2.0 export through tinygltf (DESIGN §5): the welded mesh in one buffer (POSITION, NORMAL,
// TEXCOORD_0, indices; optional control cage as LINES), one scene, one node, one mesh, one
// material, and the editable document in asset.extras.patchwork.
#include "core/gltf_export.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <stdexcept>

#include "core/bezier_curve.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/glb_container.hpp"
#include "core/limits.hpp"
#include "core/mesh_tessellate.hpp"
#include "core/patchwork_format.hpp"

namespace pw {

namespace {

// The document goes into asset.extras.patchwork as JSON text spliced into tinygltf's output in
// place of a marker: converting it to tinygltf::Value (and back to JSON inside tinygltf) took
// ~12 GB for a million patches. The marker carries a random part, so no name can collide with it.
std::string extrasMarker() {
    std::random_device rd;
    return "@patchwork-document-" + std::to_string(rd()) + "-" + std::to_string(rd()) + "@";
}

// Replaces the quoted marker in the JSON (of a .gltf, or the JSON chunk of a .glb, whose lengths
// and padding are rebuilt) with `documentJson`.
std::string spliceExtras(const std::string& file, bool binary, const std::string& marker, const std::string& documentJson) {
    auto splice = [&](std::string_view json) {
        const std::string quoted = "\"" + marker + "\"";
        const size_t at = json.find(quoted);
        if (at == std::string_view::npos) throw std::logic_error("glTF export: the extras marker is missing");
        std::string out(json.substr(0, at));
        out += documentJson;
        out += json.substr(at + quoted.size());
        return out;
    };
    if (!binary) return splice(file);
    const GlbParts parts = splitGlb(file, "(glb)");
    return joinGlb(splice(parts.json), parts.rest);
}

size_t align4(size_t n) { return (n + 3) & ~size_t{3}; }

// Appends a block to the buffer (4-byte aligned) and a bufferView over it; returns the view index.
int addView(tinygltf::Model& model, const void* data, size_t bytes, int target) {
    std::vector<unsigned char>& buf = model.buffers[0].data;
    const size_t offset = align4(buf.size());
    buf.resize(offset, 0);
    const auto* bytesIn = static_cast<const unsigned char*>(data);
    buf.insert(buf.end(), bytesIn, bytesIn + bytes);  // no zero-fill of the large blocks
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = bytes;
    view.target = target;
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size()) - 1;
}

int addAccessor(tinygltf::Model& model, int view, size_t byteOffset, int componentType, int type, size_t count) {
    tinygltf::Accessor acc;
    acc.bufferView = view;
    acc.byteOffset = byteOffset;
    acc.componentType = componentType;
    acc.type = type;
    acc.count = count;
    model.accessors.push_back(acc);
    return static_cast<int>(model.accessors.size()) - 1;
}

// POSITION needs min and max; they are computed from the stored floats, so they match exactly.
void setMinMax(tinygltf::Accessor& acc, const std::vector<std::array<float, 3>>& positions) {
    std::array<float, 3> lo = positions.front(), hi = positions.front();
    for (const auto& p : positions)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    acc.minValues = {lo[0], lo[1], lo[2]};
    acc.maxValues = {hi[0], hi[1], hi[2]};
}

// Index data as the smallest component type that holds every index (65535 is avoided: it is the
// primitive-restart value).
int addIndexView(tinygltf::Model& model, const std::vector<uint32_t>& indices, size_t vertexCount, int& componentType,
                 size_t& componentSize) {
    if (vertexCount <= 65535) {
        std::vector<uint16_t> small(indices.begin(), indices.end());
        componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        componentSize = 2;
        return addView(model, small.data(), small.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    }
    componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    componentSize = 4;
    return addView(model, indices.data(), indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
}

std::string documentName(const Document& doc) { return doc.name.empty() ? std::string("Patchwork") : doc.name; }

}  // namespace

int resolveExportLevel(const Document& doc, int requested) {
    double level = requested;
    if (requested <= 0) {
        float m = doc.tess.inner[0];
        for (float f : doc.tess.outer) m = std::max(m, f);
        m = std::max(m, doc.tess.inner[1]);
        level = std::isfinite(m) ? std::ceil(static_cast<double>(m)) : 1.0;
    }
    return static_cast<int>(std::clamp(level, 1.0, static_cast<double>(limits::kMaxExportLevel)));
}

std::string exportGltfBytes(const Document& doc, bool binary, const GltfExportOptions& options, GltfExportStats* stats) {
    const int level = resolveExportLevel(doc, options.level);
    GltfExportStats st;
    st.level = level;

    // What Patchwork writes it must read back: refuse before tessellating when the document's JSON
    // and the mesh (base64 in a .gltf) could pass the file limit (measured exactly again once
    // serialised).
    const std::string documentJson = documentToJson(doc).dump();
    const double meshFactor = binary ? 1.0 : 4.0 / 3.0, room = double(limits::kMaxFileBytes) - double(documentJson.size());
    if (const MeshBound bound = meshBound(doc, level); bound.bytes * meshFactor > room) {
        const int fits = room > 0 ? highestLevelWithin(doc, room / meshFactor) : 0;
        throw std::length_error("at level " + std::to_string(level) + " the file could take " +
                                std::to_string((uint64_t(bound.bytes * meshFactor) + documentJson.size()) >> 20) + " MiB, more than the " +
                                std::to_string(limits::kMaxFileBytes >> 20) + " MiB Patchwork reads back; " +
                                (fits > 0 ? "use --tess " + std::to_string(fits) + " or lower" : "the document is too large to export"));
    }

    tinygltf::Model model;
    const std::string marker = extrasMarker();
    model.asset.version = "2.0";
    model.asset.generator = "Patchwork";
    {
        tinygltf::Value::Object extras;
        extras.emplace("patchwork", tinygltf::Value(marker));
        model.asset.extras = tinygltf::Value(std::move(extras));
    }
    model.buffers.emplace_back();

    tinygltf::Mesh gmesh;
    gmesh.name = documentName(doc);
    const CageLines cage = options.cage ? controlCage(doc) : CageLines{};
    const size_t cageBytes = cage.positions.size() * 12 + cage.indices.size() * 4 + 16;

    // The surface: shared POSITION / NORMAL / TEXCOORD_0, and per window (or merged) triangle lists.
    {
        TriangleMesh mesh = tessellateDocument(doc, level);
        st.triangles = mesh.indices.size() / 3;
        st.vertices = mesh.positions.size();
        if (!mesh.indices.empty()) {
            const size_t nv = mesh.positions.size();
            model.buffers[0].data.reserve(nv * 32 + mesh.indices.size() * 4 + cageBytes + 64);
            const int posView = addView(model, mesh.positions.data(), nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
            const int nrmView = addView(model, mesh.normals.data(), nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
            const int uvView = addView(model, mesh.uvs.data(), nv * 8, TINYGLTF_TARGET_ARRAY_BUFFER);
            const int posAcc = addAccessor(model, posView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
            setMinMax(model.accessors[posAcc], mesh.positions);
            const int nrmAcc = addAccessor(model, nrmView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
            const int uvAcc = addAccessor(model, uvView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, nv);
            int componentType = 0;
            size_t componentSize = 0;
            const int idxView = addIndexView(model, mesh.indices, nv, componentType, componentSize);

            tinygltf::Material material;
            material.name = "Patchwork surface";
            material.pbrMetallicRoughness.baseColorFactor = {0.8, 0.8, 0.8, 1.0};
            material.pbrMetallicRoughness.metallicFactor = 0.0;
            material.pbrMetallicRoughness.roughnessFactor = 0.5;
            material.doubleSided = false;
            model.materials.push_back(material);

            auto addPrimitive = [&](size_t firstIndex, size_t count) {
                tinygltf::Primitive prim;
                prim.attributes["POSITION"] = posAcc;
                prim.attributes["NORMAL"] = nrmAcc;
                prim.attributes["TEXCOORD_0"] = uvAcc;
                prim.indices = addAccessor(model, idxView, firstIndex * componentSize, componentType, TINYGLTF_TYPE_SCALAR, count);
                prim.material = 0;
                prim.mode = TINYGLTF_MODE_TRIANGLES;
                gmesh.primitives.push_back(std::move(prim));
            };
            if (options.merge) {
                addPrimitive(0, mesh.indices.size());
            } else {
                for (const MeshRange& r : mesh.perWindow)
                    if (r.indexCount > 0) addPrimitive(r.firstIndex, r.indexCount);
                for (const MeshRange& r : mesh.perTriangle)
                    if (r.indexCount > 0) addPrimitive(r.firstIndex, r.indexCount);
            }
        }
    }  // the mesh's memory is released here, before serialising

    // The control cage: a LINES primitive with its own positions and no material.
    if (options.cage) {
        st.cageSegments = cage.indices.size() / 2;
        if (!cage.indices.empty()) {
            const size_t nv = cage.positions.size();
            const int posView = addView(model, cage.positions.data(), nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
            const int posAcc = addAccessor(model, posView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
            setMinMax(model.accessors[posAcc], cage.positions);
            int componentType = 0;
            size_t componentSize = 0;
            const int idxView = addIndexView(model, cage.indices, nv, componentType, componentSize);
            tinygltf::Primitive prim;
            prim.attributes["POSITION"] = posAcc;
            prim.indices = addAccessor(model, idxView, 0, componentType, TINYGLTF_TYPE_SCALAR, cage.indices.size());
            prim.mode = TINYGLTF_MODE_LINE;
            gmesh.primitives.push_back(std::move(prim));
        }
    }

    // Bézier curves: one LINE_STRIP each, `level` segments, on one shared position accessor.
    if (!doc.curves.empty()) {
        std::vector<std::array<float, 3>> positions;
        positions.reserve(doc.curves.size() * size_t(level + 1));
        for (const BezierCurve& c : doc.curves)
            for (const Vec3& q : sampleCurve(curvePoints(doc, c), level)) positions.push_back({float(q.x), float(q.y), float(q.z)});
        std::vector<uint32_t> indices(positions.size());
        for (size_t i = 0; i < indices.size(); ++i) indices[i] = uint32_t(i);
        const size_t nv = positions.size();
        const int posView = addView(model, positions.data(), nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
        const int posAcc = addAccessor(model, posView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
        setMinMax(model.accessors[posAcc], positions);
        int componentType = 0;
        size_t componentSize = 0;
        const int idxView = addIndexView(model, indices, nv, componentType, componentSize);
        const size_t perCurve = size_t(level) + 1;
        for (size_t c = 0; c < doc.curves.size(); ++c) {
            tinygltf::Primitive prim;
            prim.attributes["POSITION"] = posAcc;
            prim.indices = addAccessor(model, idxView, c * perCurve * componentSize, componentType, TINYGLTF_TYPE_SCALAR, perCurve);
            prim.mode = TINYGLTF_MODE_LINE_STRIP;
            gmesh.primitives.push_back(std::move(prim));
        }
        st.curveSegments = doc.curves.size() * size_t(level);
    }

    // The buffer's length is a multiple of 4 (GLB chunk alignment); an empty buffer is left out.
    std::vector<unsigned char>& buf = model.buffers[0].data;
    buf.resize(align4(buf.size()), 0);
    if (buf.empty()) model.buffers.clear();

    tinygltf::Node node;
    node.name = documentName(doc);
    // glTF is +Y up: a Z-up document turns -90° about X (+Z to +Y, -Y, its front, to +Z) in the
    // node, so three.js, Blender and assimp show it upright while the vertices stay exactly the
    // document's surface (and the import, which reads the document from the extras, stays exact).
    if (doc.camera.zUp) node.rotation = {-0.70710678118654752, 0.0, 0.0, 0.70710678118654752};
    if (!gmesh.primitives.empty()) {
        model.meshes.push_back(std::move(gmesh));
        node.mesh = 0;
    }
    model.nodes.push_back(std::move(node));
    tinygltf::Scene scene;
    scene.name = documentName(doc);
    scene.nodes = {0};
    model.scenes.push_back(std::move(scene));
    model.defaultScene = 0;

    // Serialise into a string whose capacity is reserved up front (no repeated regrowth).
    const size_t bufferBytes = model.buffers.empty() ? 0 : model.buffers[0].data.size();
    if (bufferBytes > (binary ? size_t{0xF0000000u} : size_t{0xB0000000u}))  // GLB lengths and tinygltf sizes are 32-bit
        throw std::length_error("the mesh would be " + std::to_string(bufferBytes >> 20) +
                                " MiB, more than a glTF file can hold; use a lower level");
    std::string initial;
    initial.reserve((binary ? bufferBytes : bufferBytes / 3 * 4 + 8) + (1u << 20));
    std::ostringstream out(std::move(initial), std::ios::out | std::ios::binary);
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, /*writeBinary=*/binary) || !out)
        throw OutputError(binary ? "(glb)" : "(gltf)", "tinygltf could not serialise the model");
    std::string bytes = spliceExtras(std::move(out).str(), binary, marker, documentJson);
    if (bytes.size() > limits::kMaxFileBytes)
        throw std::length_error("the file would be " + std::to_string(bytes.size() >> 20) + " MiB, more than the " +
                                std::to_string(limits::kMaxFileBytes >> 20) + " MiB Patchwork reads back; use a lower level");
    st.bytes = bytes.size();
    if (stats) *stats = st;
    return bytes;
}

std::string exportGltfBytes(const Document& doc, bool binary, const GltfExportOptions& options) {
    return exportGltfBytes(doc, binary, options, nullptr);
}

GltfExportStats exportGltfWithStats(const Document& doc, const std::filesystem::path& path, const GltfExportOptions& options) {
    const std::string ext = lowerExtension(path);
    if (ext != ".glb" && ext != ".gltf")
        throw OutputError(path.string(), "unknown glTF extension '" + ext + "' (use .gltf or .glb)");
    GltfExportStats stats;
    std::string bytes;
    try {
        bytes = exportGltfBytes(doc, ext == ".glb", options, &stats);
    } catch (const std::length_error& e) {
        throw OutputError(path.string(), e.what());
    } catch (const std::bad_alloc&) {
        throw OutputError(path.string(), "not enough memory for the mesh at level " +
                                             std::to_string(resolveExportLevel(doc, options.level)) + "; use a lower level");
    }
    writeFileAtomic(path, bytes);
    return stats;
}

void exportGltf(const Document& doc, const std::filesystem::path& path, const GltfExportOptions& options) {
    exportGltfWithStats(doc, path, options);
}

}  // namespace pw

// glTF 2.0 export through tinygltf (DESIGN §5): one buffer; a root node (turning a Z-up document
// to glTF's +Y up) with a surface node (one primitive per connected surface, patch, or all, each
// with its own POSITION / NORMAL / TEXCOORD_0 range), a control-cage node and a curves node (LINES,
// unlit); the editable document in asset.extras.patchwork and the options in patchworkExport.
#include "core/io/gltf_export.hpp"

#include "core/io/gltf_import.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"
#include "core/base/json_guard.hpp"
#include "core/base/limits.hpp"
#include "core/base/up_axis.hpp"
#include "core/eval/bezier_curve.hpp"
#include "core/io/glb_container.hpp"
#include "core/io/gltf_import.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/mesh/mesh_split.hpp"
#include "core/mesh/mesh_tessellate.hpp"
#include "core/trim/trim_mesh.hpp"

namespace pw {
inline namespace io {

namespace {

// The document goes into asset.extras.patchwork as JSON text spliced into tinygltf's output in
// place of a marker: converting it to tinygltf::Value (and back to JSON inside tinygltf) took
// ~12 GB for a million patches. The marker carries a random part, so no name can collide with it.
std::string extrasMarker() {
    std::random_device rd;
    return "@patchwork-document-" + std::to_string(rd()) + "-" + std::to_string(rd()) + "@";
}

// Replaces the quoted marker in the JSON (of a .gltf, or of a .glb's JSON chunk) with `documentJson`.
std::string spliceExtras(std::string_view json, const std::string& marker, const std::string& documentJson) {
    const std::string quoted = "\"" + marker + "\"";
    const size_t at = json.find(quoted);
    if (at == std::string_view::npos) throw std::logic_error("glTF export: the extras marker is missing");
    std::string out(json.substr(0, at));
    out += documentJson;
    out += json.substr(at + quoted.size());
    return out;
}

size_t align4(size_t n) { return (n + 3) & ~size_t{3}; }

// The buffer's blocks. A .gltf's are copied into the buffer (base64 in the JSON); a .glb's BIN chunk
// is written straight from them (joinGlb's pieces): the large arrays are borrowed, kept alive until
// then, and copied nowhere else (three copies of the mesh before: the buffer, tinygltf's chunk and
// its stream cost a third of a glb export).
struct BinBlocks {
    bool deferred = false;                                    // a .glb
    size_t size = 0;                                          // bytes so far (blocks at 4-byte offsets)
    std::vector<std::pair<size_t, std::string_view>> blocks;  // deferred: offset, bytes
    std::deque<std::string> owned;                            // deferred: copies of the small blocks
};

// Appends a block to the buffer (4-byte aligned) and a bufferView over it; returns the view index.
// Vertex views give their stride (the validator wants it when several accessors share a view).
// `borrow`: a deferred block refers to `data`, which must outlive the serialisation.
int addView(tinygltf::Model& model, BinBlocks& bin, const void* data, size_t bytes, int target, int stride = 0, bool borrow = false) {
    const size_t offset = align4(bin.size);
    if (bin.deferred) {
        std::string_view block(static_cast<const char*>(data), bytes);
        if (!borrow) block = bin.owned.emplace_back(block);
        bin.blocks.emplace_back(offset, block);
    } else {
        std::vector<unsigned char>& buf = model.buffers[0].data;
        buf.resize(offset, 0);
        const auto* bytesIn = static_cast<const unsigned char*>(data);
        buf.insert(buf.end(), bytesIn, bytesIn + bytes);  // no zero-fill of the large blocks
    }
    bin.size = offset + bytes;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = bytes;
    view.target = target;
    view.byteStride = stride;
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
void setMinMax(tinygltf::Accessor& acc, const std::array<float, 3>* positions, size_t count) {
    std::array<float, 3> lo = positions[0], hi = positions[0];
    for (size_t i = 0; i < count; ++i)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], positions[i][k]);
            hi[k] = std::max(hi[k], positions[i][k]);
        }
    acc.minValues = {lo[0], lo[1], lo[2]};
    acc.maxValues = {hi[0], hi[1], hi[2]};
}

// Index data as the smallest component type that holds every index (65535 is avoided: it is the
// primitive-restart value).
int addIndexView(tinygltf::Model& model, BinBlocks& bin, const std::vector<uint32_t>& indices, size_t vertexCount, int& componentType,
                 size_t& componentSize, bool borrow = false) {
    if (vertexCount <= 65535) {
        std::vector<uint16_t> small(indices.begin(), indices.end());
        componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        componentSize = 2;
        return addView(model, bin, small.data(), small.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    }
    componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    componentSize = 4;
    return addView(model, bin, indices.data(), indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, 0, borrow);
}

std::string documentName(const Document& doc) { return doc.name.empty() ? std::string("Patchwork") : doc.name; }

int addSurfaceMaterial(tinygltf::Model& model, bool doubleSided) {
    tinygltf::Material material;
    material.name = doubleSided ? "Patchwork surface (open, double-sided)" : "Patchwork surface";
    material.pbrMetallicRoughness.baseColorFactor = {0.8, 0.8, 0.8, 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.5;
    material.doubleSided = doubleSided;
    model.materials.push_back(material);
    return static_cast<int>(model.materials.size()) - 1;
}

// Lines are not lit (KHR_materials_unlit; readers without it fall back to the base colour).
int addLineMaterial(tinygltf::Model& model, const std::string& name, std::vector<double> color) {
    tinygltf::Material material;
    material.name = name;
    material.pbrMetallicRoughness.baseColorFactor = std::move(color);
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 1.0;
    material.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object{});
    if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_materials_unlit") == model.extensionsUsed.end())
        model.extensionsUsed.push_back("KHR_materials_unlit");
    model.materials.push_back(material);
    return static_cast<int>(model.materials.size()) - 1;
}

// A mesh of one LINES primitive over its own positions.
tinygltf::Mesh linesMesh(tinygltf::Model& model, BinBlocks& bin, const std::vector<std::array<float, 3>>& positions,
                         const std::vector<uint32_t>& indices, int material) {
    const size_t nv = positions.size();
    const int posView = addView(model, bin, positions.data(), nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int posAcc = addAccessor(model, posView, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
    setMinMax(model.accessors[posAcc], positions.data(), nv);
    int componentType = 0;
    size_t componentSize = 0;
    const int idxView = addIndexView(model, bin, indices, nv, componentType, componentSize);
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = posAcc;
    prim.indices = addAccessor(model, idxView, 0, componentType, TINYGLTF_TYPE_SCALAR, indices.size());
    prim.mode = TINYGLTF_MODE_LINE;
    prim.material = material;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(std::move(prim));
    return mesh;
}

tinygltf::Value exportOptionsValue(const ExportOptions& o) {
    tinygltf::Value::Object v;
    v.emplace("level", tinygltf::Value(o.level));
    v.emplace("primitives", tinygltf::Value(std::string(meshGroupingName(o.primitives))));
    v.emplace("cage", tinygltf::Value(o.cage));
    if (o.asDisplayed) {
        v.emplace("asDisplayed", tinygltf::Value(true));
        v.emplace("viewport", tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(o.viewport[0]), tinygltf::Value(o.viewport[1])}));
        if (o.culledPatches >= 0) v.emplace("culledPatches", tinygltf::Value(int(o.culledPatches)));
    }
    return tinygltf::Value(std::move(v));
}

}  // namespace

std::optional<ExportOptions> exportOptionsFromJson(const nlohmann::json& j, const std::string& source) {
    const std::string at = "asset.extras.patchworkExport";
    if (!j.is_object()) throw InputError(source, "the export options are not an object", 0, at);
    ExportOptions o;
    if (const auto l = j.find("level"); l != j.end()) {
        if (!l->is_number_integer() || l->get<int64_t>() < 0 || l->get<int64_t>() > limits::kMaxExportLevel)
            throw InputError(source, "must be an integer from 0 to " + std::to_string(limits::kMaxExportLevel), 0, at + ".level");
        o.level = l->get<int>();
    }
    if (const auto p = j.find("primitives"); p != j.end()) {
        const auto g = p->is_string() ? parseMeshGrouping(p->get<std::string>()) : std::nullopt;
        if (!g) throw InputError(source, "must be \"surfaces\", \"patches\" or \"single\"", 0, at + ".primitives");
        o.primitives = *g;
    }
    if (const auto c = j.find("cage"); c != j.end()) {
        if (!c->is_boolean()) throw InputError(source, "must be true or false", 0, at + ".cage");
        o.cage = c->get<bool>();
    }
    if (const auto d = j.find("asDisplayed"); d != j.end()) {
        if (!d->is_boolean()) throw InputError(source, "must be true or false", 0, at + ".asDisplayed");
        o.asDisplayed = d->get<bool>();
    }
    if (const auto c = j.find("culledPatches"); c != j.end()) {
        if (!c->is_number_integer() || c->get<int64_t>() < 0 || c->get<int64_t>() > int64_t(limits::kMaxPatches))
            throw InputError(source, "must be an integer from 0 to " + std::to_string(limits::kMaxPatches), 0, at + ".culledPatches");
        o.culledPatches = c->get<int64_t>();
    }
    if (const auto v = j.find("viewport"); v != j.end()) {
        const auto size = [](const nlohmann::json& e) {
            return e.is_number_integer() && e.get<int64_t>() >= 1 && e.get<int64_t>() <= 16384;
        };
        if (!v->is_array() || v->size() != 2 || !size((*v)[0]) || !size((*v)[1]))
            throw InputError(source, "must be [width, height] in pixels, each 1 to 16384", 0, at + ".viewport");
        o.viewport = {(*v)[0].get<int>(), (*v)[1].get<int>()};
    }
    return o;
}

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

namespace {

// A serialised glTF file in pieces: a .glb's header and JSON chunk, then its BIN chunk straight from
// the arrays it was made of (no copy of the file in one string: the writer streams the pieces and
// releases the arrays before reading the file back); a .gltf in one piece.
struct GltfFile {
    bool binary = false;
    std::string head;        // .glb: the header and the JSON chunk; .gltf: the whole file
    std::string chunk;       // .glb: the BIN chunk's header (empty without one)
    size_t bufferBytes = 0;  // .glb: the BIN chunk's data
    SplitMesh mesh;          // the surface arrays the blocks borrow
    BinBlocks bin;

    // Views into this object (made after any move of it).
    std::vector<std::string_view> pieces() const {
        std::vector<std::string_view> out{head};
        if (!binary) return out;
        static const std::string zeros(4, '\0');
        if (bufferBytes > 0) out.push_back(chunk);
        size_t at = 0;
        for (const auto& [offset, block] : bin.blocks) {
            out.emplace_back(zeros.data(), offset - at);
            out.push_back(block);
            at = offset + block.size();
        }
        out.emplace_back(zeros.data(), bufferBytes - at);
        return out;
    }
    size_t size() const {
        size_t n = 0;
        for (std::string_view p : pieces()) n += p.size();
        return n;
    }
};

GltfFile buildGltf(const Document& doc, bool binary, const ExportOptions& options, GltfExportStats* stats, TriangleMesh* displayed) {
    if (options.asDisplayed != (displayed != nullptr))
        throw std::invalid_argument(displayed ? "a displayed mesh without asDisplayed" : "asDisplayed without the displayed mesh");
    const int level = resolveExportLevel(doc, options.level);
    GltfExportStats st;
    st.level = level;

    // What Patchwork writes it must read back: refuse before tessellating when the document's JSON
    // and the mesh (base64 in a .gltf) could pass the file limit (measured exactly again once
    // serialised).
    const std::string documentJson = documentToJson(doc).dump();
    const double meshFactor = binary ? 1.0 : 4.0 / 3.0, room = double(limits::kMaxFileBytes) - double(documentJson.size());
    if (displayed) {
        const double bytes = double(displayed->positions.size()) * 32 + double(displayed->indices.size()) * 4;
        if (bytes * meshFactor > room)
            throw std::length_error("the displayed surface would take " + std::to_string(uint64_t(bytes * meshFactor) >> 20) +
                                    " MiB, more than the " + std::to_string(limits::kMaxFileBytes >> 20) +
                                    " MiB Patchwork reads back; lower the document's levels");
    } else if (const MeshBound bound = meshBound(doc, level); bound.bytes * meshFactor > room) {
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
        ExportOptions used = options;
        used.level = level;
        tinygltf::Value::Object extras;
        extras.emplace("patchwork", tinygltf::Value(marker));
        extras.emplace("patchworkExport", exportOptionsValue(used));
        model.asset.extras = tinygltf::Value(std::move(extras));
    }
    model.buffers.emplace_back();
    GltfFile file;
    file.binary = binary;
    BinBlocks& bin = file.bin;
    bin.deferred = binary;
    SplitMesh& mesh = file.mesh;  // a .glb's BIN chunk is written from it (BinBlocks)

    tinygltf::Node root;
    root.name = documentName(doc);
    // glTF is +Y up: a Z-up document's vertices, normals and lines are turned -90° about X (+Z to
    // +Y, -Y, its front, to +Z; exact, zUpToYUp), not a rotated root node, so that three.js, Blender
    // and assimp show it upright and a reader that drops the nodes' transforms keeps it upright too.
    // glTF lengths are metres: a document in another unit is scaled (lengths only, not normals).
    // The import reads the document from the extras, untouched.
    const bool turn = doc.camera.zUp;
    const auto toMetres = float(metresPer(doc.unit));
    auto turnAll = [&](std::vector<std::array<float, 3>>& v, bool lengths = true) {
        for (auto& p : v) {
            if (turn) p = zUpToYUp(p);
            if (lengths && toMetres != 1.0f)
                for (float& c : p) c *= toMetres;
        }
    };
    model.nodes.push_back(root);
    auto addMeshNode = [&](tinygltf::Mesh&& mesh, const std::string& what) {
        mesh.name = documentName(doc) + " " + what;
        model.meshes.push_back(std::move(mesh));
        tinygltf::Node node;
        node.name = documentName(doc) + " " + what;
        node.mesh = static_cast<int>(model.meshes.size()) - 1;
        model.nodes.push_back(std::move(node));
        model.nodes[0].children.push_back(static_cast<int>(model.nodes.size()) - 1);
    };
    CageLines cage = options.cage ? controlCage(doc) : CageLines{};
    turnAll(cage.positions);

    // The surface: one primitive per group (connected surface, patch, or all), each with its own
    // vertices; open surfaces (a boundary edge anywhere) are double-sided.
    {
        mesh = splitMesh(displayed ? std::move(*displayed) : tessellateTrimmed(doc, level), options.primitives);
        turnAll(mesh.positions);
        turnAll(mesh.normals, false);
        st.triangles = mesh.indices.size() / 3;
        st.vertices = mesh.positions.size();
        st.primitives = mesh.groups.size();
        if (!mesh.indices.empty()) {
            const size_t nv = mesh.positions.size();
            if (!binary)
                model.buffers[0].data.reserve(nv * 32 + mesh.indices.size() * 4 + cage.positions.size() * 12 + cage.indices.size() * 4 +
                                              64);
            const int posView = addView(model, bin, mesh.positions.data(), nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER, 12, true);
            const int nrmView = addView(model, bin, mesh.normals.data(), nv * 12, TINYGLTF_TARGET_ARRAY_BUFFER, 12, true);
            const int uvView = addView(model, bin, mesh.uvs.data(), nv * 8, TINYGLTF_TARGET_ARRAY_BUFFER, 8, true);
            uint32_t largest = 0;
            for (const MeshGroup& g : mesh.groups) largest = std::max(largest, g.vertexCount);
            int componentType = 0;
            size_t componentSize = 0;
            const int idxView = addIndexView(model, bin, mesh.indices, largest, componentType, componentSize, true);
            int material[2] = {-1, -1};  // single-sided, double-sided
            tinygltf::Mesh gmesh;
            for (const MeshGroup& g : mesh.groups) {
                tinygltf::Primitive prim;
                prim.attributes["POSITION"] =
                    addAccessor(model, posView, g.firstVertex * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, g.vertexCount);
                setMinMax(model.accessors.back(), mesh.positions.data() + g.firstVertex, g.vertexCount);
                prim.attributes["NORMAL"] =
                    addAccessor(model, nrmView, g.firstVertex * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, g.vertexCount);
                prim.attributes["TEXCOORD_0"] =
                    addAccessor(model, uvView, g.firstVertex * 8, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, g.vertexCount);
                prim.indices = addAccessor(model, idxView, g.firstIndex * componentSize, componentType, TINYGLTF_TYPE_SCALAR, g.indexCount);
                int& m = material[g.closed ? 0 : 1];
                if (m < 0) m = addSurfaceMaterial(model, !g.closed);
                prim.material = m;
                prim.mode = TINYGLTF_MODE_TRIANGLES;
                gmesh.primitives.push_back(std::move(prim));
                if (!g.closed) ++st.openSurfaces;
            }
            addMeshNode(std::move(gmesh), "surface");
        }
        if (!binary) mesh = SplitMesh{};  // copied into the buffer: released before serialising
    }

    // The control cage: LINES with their own positions and an unlit material, in their own node.
    if (options.cage) {
        st.cageSegments = cage.indices.size() / 2;
        if (!cage.indices.empty())
            addMeshNode(linesMesh(model, bin, cage.positions, cage.indices,
                                  addLineMaterial(model, "Patchwork control cage", {0.25, 0.35, 0.55, 1.0})),
                        "control cage");
    }

    // Bézier curves: `level` segments each, as LINES (pairs), unlit, in their own node.
    if (!doc.curves.empty()) {
        std::vector<std::array<float, 3>> positions;
        std::vector<uint32_t> indices;
        positions.reserve(doc.curves.size() * size_t(level + 1));
        indices.reserve(doc.curves.size() * size_t(level) * 2);
        for (const BezierCurve& c : doc.curves) {
            const auto first = uint32_t(positions.size());
            for (const Vec3& q : sampleCurve(doc, c, level)) positions.push_back({float(q.x), float(q.y), float(q.z)});
            for (uint32_t i = first + 1; i < positions.size(); ++i) indices.insert(indices.end(), {i - 1, i});
        }
        turnAll(positions);
        st.curveSegments = indices.size() / 2;
        addMeshNode(linesMesh(model, bin, positions, indices, addLineMaterial(model, "Patchwork curves", {0.85, 0.45, 0.1, 1.0})),
                    "curves");
    }

    // The buffer's length is a multiple of 4 (GLB chunk alignment); an empty buffer is left out.
    const size_t bufferBytes = align4(bin.size);
    if (!binary) model.buffers[0].data.resize(bufferBytes, 0);
    if (bufferBytes == 0) model.buffers.clear();

    tinygltf::Scene scene;
    scene.name = documentName(doc);
    scene.nodes = {0};
    model.scenes.push_back(std::move(scene));
    model.defaultScene = 0;

    if (bufferBytes > (binary ? size_t{0xF0000000u} : size_t{0xB0000000u}))  // GLB lengths and tinygltf sizes are 32-bit
        throw std::length_error("the mesh would be " + std::to_string(bufferBytes >> 20) +
                                " MiB, more than a glTF file can hold; use a lower level");
    tinygltf::TinyGLTF writer;
    if (binary) {
        // tinygltf writes the JSON (its buffer empty, so no BIN chunk and a byteLength of 0); the
        // buffer's length is set, the document spliced in, and the chunk made of the blocks.
        std::ostringstream out(std::ios::out | std::ios::binary);
        if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/false, /*writeBinary=*/true) || !out)
            throw OutputError("(glb)", "tinygltf could not serialise the model");
        const std::string glb = std::move(out).str();
        nlohmann::json json = parseJsonGuarded(splitGlb(glb, "(glb)").json, "(glb)");
        if (bufferBytes > 0) json.at("buffers").at(0)["byteLength"] = bufferBytes;
        file.bufferBytes = bufferBytes;
        if (bufferBytes > 0) {
            file.chunk.assign(8, '\0');
            const auto put = [&](size_t at, uint32_t v) { std::memcpy(file.chunk.data() + at, &v, 4); };
            put(0, uint32_t(bufferBytes));
            put(4, 0x004E4942u);  // "BIN\0"
        }
        file.head = glbHead(spliceExtras(json.dump(), marker, documentJson), file.chunk.size() + bufferBytes);
    } else {
        // Serialise into a string whose capacity is reserved up front (no repeated regrowth).
        std::string initial;
        initial.reserve(bufferBytes / 3 * 4 + 8 + (1u << 20));
        std::ostringstream out(std::move(initial), std::ios::out | std::ios::binary);
        if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/true, /*writeBinary=*/false) || !out)
            throw OutputError("(gltf)", "tinygltf could not serialise the model");
        file.head = spliceExtras(std::move(out).str(), marker, documentJson);
    }
    const size_t bytes = file.size();
    if (bytes > limits::kMaxFileBytes)
        throw std::length_error("the file would be " + std::to_string(bytes >> 20) + " MiB, more than the " +
                                std::to_string(limits::kMaxFileBytes >> 20) + " MiB Patchwork reads back; use a lower level");
    st.bytes = bytes;
    if (stats) *stats = st;
    return file;
}

}  // namespace

std::string exportGltfBytes(const Document& doc, bool binary, const ExportOptions& options, GltfExportStats* stats,
                            TriangleMesh* displayed) {
    GltfFile file = buildGltf(doc, binary, options, stats, displayed);
    if (!binary) return std::move(file.head);
    std::string bytes;
    bytes.reserve(file.size());
    for (std::string_view piece : file.pieces()) bytes.append(piece);
    return bytes;
}

std::string exportGltfBytes(const Document& doc, bool binary, const ExportOptions& options) {
    return exportGltfBytes(doc, binary, options, nullptr);
}

GltfExportStats exportGltfWithStats(const Document& doc, const std::filesystem::path& path, const ExportOptions& options,
                                    TriangleMesh* displayed) {
    const std::string ext = lowerExtension(path);
    if (ext != ".glb" && ext != ".gltf") throw OutputError(path.string(), "unknown glTF extension '" + ext + "' (use .gltf or .glb)");
    GltfExportStats stats;
    std::optional<GltfFile> file;
    try {
        file.emplace(buildGltf(doc, ext == ".glb", options, &stats, displayed));
    } catch (const std::length_error& e) {
        throw OutputError(path.string(), e.what());
    } catch (const std::bad_alloc&) {
        throw OutputError(path.string(), "not enough memory for the mesh at level " +
                                             std::to_string(resolveExportLevel(doc, options.level)) + "; use a lower level");
    }
    // Read back through the glTF reader: the same patches, surfaces, triangles, curves and joins
    // (buildGltf refused a file beyond the read limit). The mesh is released once the file is
    // written, before it is read.
    auto readBack = [&](const std::filesystem::path& staged) {
        const Document back = parsePatchworkGltf(readFileLimited(staged), path.string());
        if (back.patches.size() != doc.patches.size() || back.surfaces.size() != doc.surfaces.size() ||
            back.triangles.size() != doc.triangles.size() || back.curves.size() != doc.curves.size() ||
            back.joins.size() != doc.joins.size())
            throw InputError(path.string(), "it reads back with different patches or joins");
    };
    const std::vector<std::string_view> pieces = file->pieces();
    writeFileAtomic(path, pieces, readBack, [&] { file.reset(); });
    return stats;
}

void exportGltf(const Document& doc, const std::filesystem::path& path, const ExportOptions& options) {
    exportGltfWithStats(doc, path, options);
}

}  // namespace io
}  // namespace pw

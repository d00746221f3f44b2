#include "core/io/construction_format.hpp"

#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/model/construction_refs.hpp"

namespace pw {
inline namespace io {

using json_reader::at;
using nlohmann::json;

json constructionsJson(const Document& doc) {
    json out = json::array();
    for (const Construction& c : doc.constructions) {
        json inputs = json::array();
        for (const CurveInput& in : c.inputs) inputs.push_back(curveInputName(in));
        json o{{"kind", constructionKindName(c.kind)}, {"inputs", std::move(inputs)}};
        if (c.kind == ConstructionKind::Revolve) o["origin"] = c.origin, o["degrees"] = c.degrees;
        if (c.kind == ConstructionKind::Revolve || c.kind == ConstructionKind::Extrude) o["vector"] = c.vector;
        if (c.kind == ConstructionKind::Loft) o["closed"] = c.closed;
        if (c.kind == ConstructionKind::Loft || c.kind == ConstructionKind::Blend) {
            o["ends"] = {continuityName(c.ends[0]), continuityName(c.ends[1])};
            o["end_alpha"] = c.endAlpha;
        }
        if (c.kind == ConstructionKind::Network) o["u_curves"] = c.split;
        if (c.kind == ConstructionKind::Sweep1 && c.split > 1) o["rail_pieces"] = c.split;
        o["rows"] = c.rows;
        o["cols"] = c.cols;
        o["grid"] = c.grid;
        o["patches"] = c.patches;
        out.push_back(std::move(o));
    }
    return out;
}

void readConstructions(const json_reader::Reader& r, const json& v, Document& doc) {
    const json& list = r.array(v, "constructions", limits::kMaxPatches, "constructions");
    for (size_t k = 0; k < list.size(); ++k) {
        const std::string path = at("constructions", k);
        const json& o = r.object(list[k], path);
        Construction c;
        c.kind = r.named<ConstructionKind>(*r.member(o, path, "kind", true), at(path, "kind"), parseConstructionKind,
                                           "revolve, extrude, loft, edge-surface, sweep1, sweep2, network, blend");
        const std::string ip = at(path, "inputs");
        const json& inputs = r.array(*r.member(o, path, "inputs", true), ip, limits::kMaxPatches, "inputs");
        if (inputs.empty()) r.fail(ip, "a construction needs at least one input");
        for (size_t i = 0; i < inputs.size(); ++i) {
            try {
                c.inputs.push_back(parseCurveInput(doc, r.string(inputs[i], at(ip, i))));
            } catch (const EditError& e) {
                r.fail(at(ip, i), e.what());
            }
        }
        const auto vec3 = [&](const char* key, std::array<double, 3>& out) {
            r.optional(o, path, key, [&](const json& x, const std::string& p) {
                const json& a = r.fixedArray(x, p, 3);
                for (size_t i = 0; i < 3; ++i) out[i] = r.coordinate(a[i], at(p, i));
            });
        };
        vec3("origin", c.origin);
        vec3("vector", c.vector);
        r.optional(o, path, "degrees", [&](const json& x, const std::string& p) { c.degrees = r.numberInRange(x, p, 0.0, 360.0, true); });
        r.optional(o, path, "closed", [&](const json& x, const std::string& p) { c.closed = r.boolean(x, p); });
        r.optional(o, path, "ends", [&](const json& x, const std::string& p) {
            const json& a = r.fixedArray(x, p, 2);
            for (size_t i = 0; i < 2; ++i) {
                c.ends[i] = r.named<Continuity>(a[i], at(p, i), parseContinuity, "C0, G1, G2");
                if (c.ends[i] == Continuity::C1 || c.ends[i] == Continuity::C2) r.fail(at(p, i), "an end is C0 (G0), G1 or G2");
            }
        });
        r.optional(o, path, "end_alpha", [&](const json& x, const std::string& p) {
            const json& a = r.fixedArray(x, p, 2);
            for (size_t i = 0; i < 2; ++i) c.endAlpha[i] = r.numberInRange(a[i], at(p, i), 1e-6, 1e6, false);
        });
        r.optional(o, path, "rail_pieces", [&](const json& x, const std::string& p) {
            c.split = uint32_t(r.index(x, p, kMaxSweepPieces + 1, "pieces a rail segment"));
            if (c.split < 1) r.fail(p, "a rail segment is at least 1 piece");
        });
        r.optional(o, path, "u_curves", [&](const json& x, const std::string& p) {
            c.split = uint32_t(r.index(x, p, c.inputs.size() - 1, "count of U curves"));
            if (c.split < 2) r.fail(p, "a network has at least 2 U curves");
        });
        const auto side = [&](const char* key) {
            const std::string p = at(path, key);
            const auto n = uint32_t(r.index(*r.member(o, path, key, true), p, limits::kMaxNetSide + 1, "net side"));
            if (n < 4 || (n - 1) % 3 != 0) r.fail(p, "a Bézier net side has 3n + 1 points (4, 7, 10, ...), not " + std::to_string(n));
            return n;
        };
        c.rows = side("rows");
        c.cols = side("cols");
        const std::string gp = at(path, "grid");
        const json& grid = r.fixedArray(*r.member(o, path, "grid", true), gp, size_t(c.rows) * c.cols);
        for (size_t i = 0; i < grid.size(); ++i) c.grid.push_back(uint32_t(r.index(grid[i], at(gp, i), doc.points.size(), "point index")));
        const std::string pp = at(path, "patches");
        const uint32_t wr = (c.rows - 1) / 3, wc = (c.cols - 1) / 3;
        const json& patches = r.fixedArray(*r.member(o, path, "patches", true), pp, size_t(wr) * wc);
        for (size_t n = 0; n < patches.size(); ++n) {
            const uint32_t p = uint32_t(r.index(patches[n], at(pp, n), doc.patches.size(), "patch index"));
            for (uint32_t i = 0; i < 4; ++i)
                for (uint32_t j = 0; j < 4; ++j)
                    if (doc.patches[p].idx[i * 4 + j] != c.grid[size_t(3 * (n / wc) + i) * c.cols + 3 * (n % wc) + j])
                        r.fail(at(pp, n),
                               "patch " + std::to_string(p) + " is not window " + std::to_string(n) + " of the construction's net");
            c.patches.push_back(p);
        }
        doc.constructions.push_back(std::move(c));
    }
}

}  // namespace io
}  // namespace pw

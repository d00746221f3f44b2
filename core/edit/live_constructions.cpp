#include "core/edit/live_constructions.hpp"

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/construct/constructions.hpp"
#include "core/model/construction_refs.hpp"
#include "core/solve/constraint_solver.hpp"

namespace pw {
inline namespace edit {

std::vector<uint32_t> withConstructionPoints(const Document& doc, std::vector<uint32_t> driven) {
    if (doc.constructions.empty()) return driven;
    const std::vector<uint32_t> made = constructionFixedPoints(doc);
    driven.insert(driven.end(), made.begin(), made.end());
    std::sort(driven.begin(), driven.end());
    driven.erase(std::unique(driven.begin(), driven.end()), driven.end());
    return driven;
}

std::vector<uint32_t> constructionFixedPoints(const Document& doc) {
    std::vector<uint32_t> out;
    for (const Construction& c : doc.constructions) {
        out.insert(out.end(), c.grid.begin(), c.grid.end());
        for (const CurveInput& in : c.inputs) {
            const std::vector<uint32_t> pts = curveInputPoints(doc, in);
            out.insert(out.end(), pts.begin(), pts.end());
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<std::string> refreshConstructions(Document& doc) {
    if (doc.constructions.empty()) return {};
    const RerunReport r = rerunConstructions(doc);
    std::vector<std::string> notes = r.failed;
    for (const std::string& b : r.baked) notes.push_back(b + ": baked, its patches were rebuilt by hand");
    if (!r.moved.empty() && !doc.joins.empty()) {
        const Projection p = projectConstraints(doc, constructionFixedPoints(doc));
        if (!p.ok()) throw EditError("the surfaces made from curves break joins: " + conflictMessage(p));
    }
    return notes;
}

std::string constructedPointsRefusal(const Document& doc, const std::vector<uint32_t>& points) {
    if (doc.constructions.empty()) return "";
    for (uint32_t i : points) {
        if (!constructedOnly(doc, i)) continue;
        for (size_t k = 0; k < doc.constructions.size(); ++k) {
            const Construction& c = doc.constructions[k];
            if (std::find(c.grid.begin(), c.grid.end(), i) == c.grid.end()) continue;
            std::string inputs;
            for (const CurveInput& in : c.inputs) inputs += (inputs.empty() ? "" : ", ") + curveInputName(in);
            return "point " + std::to_string(i) + " is made by " + constructionLabel(doc, k) + ": move " + inputs + ", or `bake k" +
                   std::to_string(k) + "` to edit the surface's own points";
        }
    }
    return "";
}

}  // namespace edit
}  // namespace pw

#include "core/edit/live_constructions.hpp"

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/construct/constructions.hpp"
#include "core/edit/live_trims.hpp"
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
    if (doc.constructions.empty()) return refreshTrims(doc);
    const RerunReport r = rerunConstructions(doc);
    std::vector<std::string> notes = r.failed;
    for (const std::string& b : r.baked) notes.push_back(b + ": baked, its patches were rebuilt by hand");
    if (!r.moved.empty() && !doc.joins.empty()) {
        const Projection p = projectConstraints(doc, constructionFixedPoints(doc));
        if (!p.ok()) throw EditError("the surfaces made from curves break joins: " + conflictMessage(p));
    }
    const std::vector<std::string> trimNotes = refreshTrims(doc);  // trims follow the surfaces they were made on
    notes.insert(notes.end(), trimNotes.begin(), trimNotes.end());
    return notes;
}

std::string constructedPointsRefusal(const Document& doc, const std::vector<uint32_t>& points) {
    for (size_t c = 0; c < doc.curves.size(); ++c) {  // live curves: made from their surfaces
        const BezierCurve& k = doc.curves[c];
        if (!k.link) continue;
        for (uint32_t i : points)
            if (std::find(k.idx.begin(), k.idx.end(), i) != k.idx.end())
                return "point " + std::to_string(i) + " is made by " +
                       (k.link->kind == CurveLinkKind::Intersect ? "an intersection" : "a projection") + " (curve c" + std::to_string(c) +
                       "): move the surfaces, or `bake c" + std::to_string(c) + "` to edit its points";
    }
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

#include "core/model/construction_refs.hpp"

#include <algorithm>
#include <charconv>

#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"

namespace pw {
inline namespace model {

namespace {
constexpr std::array<std::string_view, 8> kKindNames{"revolve", "extrude", "loft", "edge-surface", "sweep1", "sweep2", "network", "blend"};

bool parseUint(std::string_view s, uint32_t& out) {
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && p == s.data() + s.size() && !s.empty();
}

// Erases the constructions `drop` says and renumbers the indices `fix` is given.
template <class Drop, class Fix>
void dropConstructions(Document& doc, std::vector<std::string>* baked, Drop drop, Fix fix) {
    for (size_t k = doc.constructions.size(); k-- > 0;)
        if (drop(doc.constructions[k])) {
            if (baked) baked->push_back(constructionLabel(doc, k));
            bakeConstruction(doc, k);
        }
    for (Construction& c : doc.constructions) fix(c);
}
}  // namespace

std::string_view constructionKindName(ConstructionKind k) { return enumName(k, kKindNames); }
std::optional<ConstructionKind> parseConstructionKind(std::string_view n) { return parseEnum<ConstructionKind>(n, kKindNames); }

std::string curveInputName(const CurveInput& in) {
    if (in.curve >= 0) return "c" + std::to_string(in.curve);
    return std::to_string(in.patch) + ":" + std::string(edgeName(in.edge));
}

CurveInput parseCurveInput(const Document& doc, const std::string& word) {
    CurveInput in;
    uint32_t n = 0;
    if (word.size() > 1 && (word[0] == 'c' || word[0] == 'C') && parseUint(std::string_view(word).substr(1), n)) {
        if (n >= doc.curves.size())
            throw EditError("curve " + word + " does not exist (the document has " + std::to_string(doc.curves.size()) + " curves)");
        in.curve = int32_t(n);
        return in;
    }
    const size_t colon = word.find(':');
    const auto edge = colon == std::string::npos ? std::nullopt : parseEdge(std::string_view(word).substr(colon + 1));
    if (colon == std::string::npos || !edge || !parseUint(std::string_view(word).substr(0, colon), n))
        throw EditError("expected a curve (c0, c1, ...) or a patch edge (P:u0|u1|v0|v1), got '" + word + "'");
    if (n >= doc.patches.size())
        throw EditError("patch " + std::to_string(n) + " does not exist (the document has " + std::to_string(doc.patches.size()) + ")");
    if (doc.patches[n].basis != Basis::Bezier)
        throw EditError("patch " + std::to_string(n) + " is not a Bézier patch; its edge is no curve");
    in.patch = n;
    in.edge = *edge;
    return in;
}

std::vector<uint32_t> curveInputPoints(const Document& doc, const CurveInput& in) {
    if (in.curve >= 0) return size_t(in.curve) < doc.curves.size() ? doc.curves[size_t(in.curve)].idx : std::vector<uint32_t>{};
    std::vector<uint32_t> out;
    if (in.patch < doc.patches.size())
        for (int k = 0; k < 4; ++k) out.push_back(doc.patches[in.patch].idx[size_t(edgeSlot(in.edge, k))]);
    return out;
}

std::string constructionLabel(const Document& doc, size_t k) {
    const Construction& c = doc.constructions.at(k);
    std::string s = std::string(constructionKindName(c.kind)) + " k" + std::to_string(k) + " from";
    for (size_t i = 0; i < c.inputs.size(); ++i)
        s += (c.kind == ConstructionKind::Network && i == c.split ? " / " : " ") + curveInputName(c.inputs[i]);
    return s;
}

int constructionOfPatch(const Document& doc, uint32_t p) {
    for (size_t k = 0; k < doc.constructions.size(); ++k) {
        const auto& ps = doc.constructions[k].patches;
        if (std::find(ps.begin(), ps.end(), p) != ps.end()) return int(k);
    }
    return -1;
}

bool constructedOnly(const Document& doc, uint32_t i) {
    bool made = false;
    for (const Construction& c : doc.constructions) {
        if (std::find(c.grid.begin(), c.grid.end(), i) != c.grid.end()) made = true;
        for (const CurveInput& in : c.inputs) {
            const std::vector<uint32_t> pts = curveInputPoints(doc, in);
            if (std::find(pts.begin(), pts.end(), i) != pts.end()) return false;
        }
    }
    return made;
}

void bakeConstruction(Document& doc, size_t k) { doc.constructions.erase(doc.constructions.begin() + long(k)); }

void dropPatchFromConstructions(Document& doc, uint32_t p, std::vector<std::string>* baked) {
    dropConstructions(
        doc, baked,
        [&](const Construction& c) {
            if (std::find(c.patches.begin(), c.patches.end(), p) != c.patches.end()) return true;
            return std::any_of(c.inputs.begin(), c.inputs.end(), [&](const CurveInput& in) { return in.curve < 0 && in.patch == p; });
        },
        [&](Construction& c) {
            for (uint32_t& q : c.patches)
                if (q > p) --q;
            for (CurveInput& in : c.inputs)
                if (in.curve < 0 && in.patch > p) --in.patch;
        });
}

void dropCurveFromConstructions(Document& doc, uint32_t cv, std::vector<std::string>* baked) {
    dropConstructions(
        doc, baked,
        [&](const Construction& c) {
            return std::any_of(c.inputs.begin(), c.inputs.end(), [&](const CurveInput& in) { return in.curve == int32_t(cv); });
        },
        [&](Construction& c) {
            for (CurveInput& in : c.inputs)
                if (in.curve > int32_t(cv)) --in.curve;
        });
}

}  // namespace model
}  // namespace pw

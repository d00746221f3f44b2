// Linked selection, inversion, hiding and the shown document (core/select/selection_ops.hpp).
#include "core/select/selection_ops.hpp"

#include <algorithm>
#include <numeric>

namespace pw {
inline namespace select {

namespace {

// Calls f(items, kind) for the four item lists; kind 0 patches, 1 nets, 2 triangles, 3 curves.
template <class Doc, class F>
void forEachList(Doc& doc, F&& f) {
    f(doc.patches, 0);
    f(doc.surfaces, 1);
    f(doc.triangles, 2);
    f(doc.curves, 3);
}

std::vector<uint32_t> sortedUnique(std::vector<uint32_t> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

int selectedItem(const Selection& sel, int kind) {
    return kind == 0 ? sel.patch : kind == 1 ? sel.surface : kind == 2 ? sel.triangle : sel.curve;
}

}  // namespace

bool anyHidden(const Document& doc) {
    bool any = false;
    forEachList(doc, [&](const auto& items, int) {
        for (const auto& it : items) any = any || it.hidden;
    });
    return any;
}

Document visibleDocument(const Document& doc) {
    Document out = doc;
    std::vector<int> newIndex(doc.patches.size(), -1), newTriangle(doc.triangles.size(), -1);
    out.patches.clear();
    for (size_t i = 0; i < doc.patches.size(); ++i)
        if (!doc.patches[i].hidden) newIndex[i] = int(out.patches.size()), out.patches.push_back(doc.patches[i]);
    out.triangles.clear();
    for (size_t i = 0; i < doc.triangles.size(); ++i)
        if (!doc.triangles[i].hidden) newTriangle[i] = int(out.triangles.size()), out.triangles.push_back(doc.triangles[i]);
    const auto renumbered = [&](uint32_t i, Edge e) { return isTriangleEdge(e) ? newTriangle[i] : newIndex[i]; };
    out.joins.clear();
    for (Join j : doc.joins)
        if (renumbered(j.patchA, j.edgeA) >= 0 && renumbered(j.patchB, j.edgeB) >= 0) {
            j.patchA = uint32_t(renumbered(j.patchA, j.edgeA)), j.patchB = uint32_t(renumbered(j.patchB, j.edgeB));
            out.joins.push_back(j);
        }
    std::erase_if(out.surfaces, [](const Surface& s) { return s.hidden; });
    std::erase_if(out.curves, [](const BezierCurve& c) { return c.hidden; });
    // What is shown is drawn or exported, never edited: its surfaces from curves are plain patches
    // (their patch and curve numbers would no longer fit the renumbered lists).
    out.constructions.clear();
    return out;
}

std::vector<bool> visiblePointMask(const Document& doc) {
    std::vector<bool> shown(doc.points.size(), false);
    forEachList(doc, [&](const auto& items, int) {
        for (const auto& it : items)
            if (!it.hidden)
                for (uint32_t p : it.idx)
                    if (p < shown.size()) shown[p] = true;
    });
    return shown;
}

std::vector<uint32_t> linkedPoints(const Document& doc, const std::vector<uint32_t>& selected) {
    // Union-find over pool points: every shown item ties its points together.
    std::vector<uint32_t> parent(doc.points.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](uint32_t a) {
        while (parent[a] != a) a = parent[a] = parent[parent[a]];
        return a;
    };
    forEachList(doc, [&](const auto& items, int) {
        for (const auto& it : items) {
            if (it.hidden || it.idx.empty()) continue;
            const uint32_t root = find(it.idx[0]);
            for (uint32_t p : it.idx) parent[find(p)] = root;
        }
    });
    std::vector<bool> wanted(doc.points.size(), false);
    for (uint32_t p : selected)
        if (p < doc.points.size()) wanted[find(p)] = true;
    const std::vector<bool> shown = visiblePointMask(doc);
    std::vector<uint32_t> out;
    for (uint32_t p = 0; p < doc.points.size(); ++p)
        if (shown[p] && wanted[find(p)]) out.push_back(p);
    return out;
}

std::vector<uint32_t> invertedPoints(const Document& doc, const std::vector<uint32_t>& selected) {
    std::vector<bool> shown = visiblePointMask(doc);
    for (uint32_t p : selected)
        if (p < shown.size()) shown[p] = false;
    std::vector<uint32_t> out;
    for (uint32_t p = 0; p < shown.size(); ++p)
        if (shown[p]) out.push_back(p);
    return out;
}

size_t hideItems(Document& doc, const Selection& sel, const std::vector<uint32_t>& selected, bool unselected) {
    std::vector<bool> in(doc.points.size(), false);
    for (uint32_t p : selected)
        if (p < in.size()) in[p] = true;
    size_t hidden = 0;
    forEachList(doc, [&](auto& items, int kind) {
        for (size_t i = 0; i < items.size(); ++i) {
            auto& it = items[i];
            if (it.hidden) continue;
            const bool all = std::all_of(it.idx.begin(), it.idx.end(), [&](uint32_t p) { return in[p]; });
            const bool any = std::any_of(it.idx.begin(), it.idx.end(), [&](uint32_t p) { return in[p]; });
            const bool covered = selectedItem(sel, kind) == int(i) || all;
            if (unselected ? !any && selectedItem(sel, kind) != int(i) : covered) it.hidden = true, ++hidden;
        }
    });
    return hidden;
}

std::vector<uint32_t> revealItems(Document& doc) {
    std::vector<uint32_t> out;
    forEachList(doc, [&](auto& items, int) {
        for (auto& it : items)
            if (it.hidden) {
                it.hidden = false;
                out.insert(out.end(), it.idx.begin(), it.idx.end());
            }
    });
    return sortedUnique(std::move(out));
}

}  // namespace select
}  // namespace pw

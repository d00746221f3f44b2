#include "core/trim/trim_edits.hpp"

#include <algorithm>

namespace pw {
inline namespace trim {

namespace {
template <class F>
void forEachLoop(Document& doc, F&& f) {
    for (Patch& p : doc.patches)
        for (TrimLoop& l : p.trims) f(l);
    for (Surface& s : doc.surfaces)
        for (TrimLoop& l : s.trims) f(l);
}
}  // namespace

void dropCurveFromTrims(Document& doc, uint32_t c) {
    const int32_t ci = int32_t(c);
    forEachLoop(doc, [&](TrimLoop& l) {
        if (l.curve == ci)
            l.curve = -1;
        else if (l.curve > ci)
            --l.curve;
    });
    for (BezierCurve& k : doc.curves) {
        if (!k.link || k.link->kind != CurveLinkKind::Project) continue;
        if (k.link->source == ci)
            k.link.reset();
        else if (k.link->source > ci)
            --k.link->source;
    }
}

void dropSurfaceFromTrims(Document& doc, const SurfaceRef& s) {
    auto shift = [&](SurfaceRef& r) {
        if (r.net == s.net && r.index > s.index) --r.index;
    };
    for (BezierCurve& k : doc.curves) {
        if (!k.link) continue;
        const bool uses = k.link->a == s || (k.link->kind == CurveLinkKind::Intersect && k.link->b == s);
        if (uses) {
            k.link.reset();
            continue;
        }
        shift(k.link->a);
        shift(k.link->b);
    }
}

void flipTrimsU(std::vector<TrimLoop>& loops) {
    for (TrimLoop& l : loops) {
        for (UV& p : l.uv) p[0] = 1.0 - p[0];
        std::reverse(l.uv.begin(), l.uv.end());
    }
}

void detachTrims(std::vector<TrimLoop>& loops) {
    for (TrimLoop& l : loops) {
        l.curve = -1;
        l.error.clear();
    }
}

bool hasLiveTrims(const Document& doc) {
    for (const BezierCurve& c : doc.curves)
        if (c.link) return true;
    for (const Patch& p : doc.patches)
        for (const TrimLoop& l : p.trims)
            if (l.curve >= 0) return true;
    for (const Surface& s : doc.surfaces)
        for (const TrimLoop& l : s.trims)
            if (l.curve >= 0) return true;
    return false;
}

}  // namespace trim
}  // namespace pw

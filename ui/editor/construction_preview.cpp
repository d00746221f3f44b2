// The live preview of the Surfaces panel (issue 39): while the mouse is over Revolve, Extrude, Loft,
// Edge surface, Sweep1, Sweep2 or Network (or the angle slider moves), the surface that button
// would make is drawn as a wireframe over the view: the command runs on a scratch copy of the
// session, so the preview is exactly what the click makes, and the document, its undo history and
// the status line are untouched. It is made again only when the words or the document change.
#include <imgui.h>

#include "core/select/edge_pick.hpp"
#include "core/trim/curve_on_surface.hpp"
#include "core/trim/surface_domain.hpp"
#include "core/trim/trim_loops.hpp"
#include "ui/editor/editor.hpp"

namespace pw::ui {
inline namespace editor {

namespace {
// Runs commands without a window: nothing written, no messages.
class SilentHost final : public CommandHost {
public:
    void write(const Document&, const std::string&) override {}
};
}  // namespace

void Editor::previewConstruction(const std::vector<std::string>& words) { preview_.asked = words; }

void Editor::updateConstructionPreview() {
    std::vector<std::string> asked = std::exchange(preview_.asked, {});
    if (asked.empty()) {
        if (preview_.doc) wake();  // one more frame without it
        preview_.doc.reset();
        preview_.shown.clear();
        return;
    }
    if (asked == preview_.shown && preview_.version == docVersion_) return;
    preview_.shown = asked;
    preview_.version = docVersion_;
    preview_.doc.reset();
    EditSession scratch;
    scratch.reset(doc_, "");
    scratch.sel = sel_;
    scratch.cursor = session_.cursor;
    scratch.camera = cam_;
    SilentHost host;
    try {
        commands_.run(scratch, host, asked);
    } catch (const std::exception&) {
        return;  // nothing to show; the click reports why
    }
    preview_.firstPatch = doc_.patches.size();
    preview_.doc = std::make_unique<Document>(std::move(scratch.doc));
    wake();
}

void Editor::drawConstructionPreview(const std::function<void(const Vec3&, const Vec3&, unsigned, float)>& line) const {
    if (!preview_.doc) return;
    const Document& d = *preview_.doc;
    // Trims (issue 64): every loop the command would make or change, on its surface; new curves (an intersection's).
    auto loops = [&](const SurfaceRef& ref, const std::vector<TrimLoop>& now, const std::vector<TrimLoop>* was) {
        if (now.empty() || (was && *was == now)) return;
        const DomainSurface surface(d, ref);
        for (const TrimLoop& l : now) {
            const std::vector<glm::dvec2> uv = loopPolyline(l, 12);
            for (size_t k = 0; k < uv.size(); ++k)
                line(surface.evaluate({uv[k].x, uv[k].y}).p, surface.evaluate({uv[(k + 1) % uv.size()].x, uv[(k + 1) % uv.size()].y}).p,
                     IM_COL32(255, 170, 60, 230), 2.0f);
        }
    };
    for (uint32_t p = 0; p < d.patches.size(); ++p)
        loops({false, p}, d.patches[p].trims, p < doc_.patches.size() ? &doc_.patches[p].trims : nullptr);
    for (uint32_t n = 0; n < d.surfaces.size(); ++n)
        loops({true, n}, d.surfaces[n].trims, n < doc_.surfaces.size() ? &doc_.surfaces[n].trims : nullptr);
    for (size_t c = doc_.curves.size(); c < d.curves.size(); ++c) {
        const std::vector<Vec3> pts = sampleCurve(d, d.curves[c]);
        for (size_t k = 0; k + 1 < pts.size(); ++k) line(pts[k], pts[k + 1], IM_COL32(255, 220, 80, 230), 2.0f);
        if (curveClosed(d.curves[c]) && pts.size() > 2) line(pts.back(), pts.front(), IM_COL32(255, 220, 80, 230), 2.0f);
    }
    for (size_t p = preview_.firstPatch; p < d.patches.size(); ++p)
        for (Edge e : {Edge::U0, Edge::V0, Edge::U1, Edge::V1}) {
            const std::vector<Vec3> c = boundaryCurve(d, uint32_t(p), e, 12);
            for (size_t k = 0; k + 1 < c.size(); ++k) line(c[k], c[k + 1], IM_COL32(120, 255, 160, 200), 1.5f);
        }
}

}  // namespace editor
}  // namespace pw::ui

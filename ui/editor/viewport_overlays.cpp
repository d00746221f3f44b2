// The viewport's overlays, drawn with ImGui's background draw list in every pane: the selected
// patch's or triangle's boundary, selected and hovered points, the axis lines of a constrained
// transform, the move gizmo at the pivot (and its hit test), the 3D cursor, the box of a box selection, the axis
// gizmo; and the mode line of a transform. (The ground grid is
// drawn by the renderer, depth-tested.)
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

#include "core/eval/bezier_triangle.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/picking.hpp"
#include "ui/editor/editor.hpp"

namespace pw::ui {
inline namespace editor {

namespace {
constexpr ImU32 kAxisColours[3] = {IM_COL32(230, 60, 60, 230), IM_COL32(60, 210, 60, 230), IM_COL32(70, 120, 255, 230)};
constexpr float kGizmoLengthPx = 80.0f;
constexpr double kGizmoGrabPx = 7.0;

}  // namespace

std::optional<std::array<glm::dvec2, 4>> Editor::gizmoHandles(int width, int height) const {
    if (session_.selectedPoints().empty()) return std::nullopt;
    const Vec3 pivot = mode_ == Interaction::None ? session_.transformPivot() : drag_.anchor();
    const auto p0 = projectToPixel(viewMatrices(cam_, double(width) / std::max(height, 1)), pivot, width, height);
    if (!p0) return std::nullopt;
    std::array<glm::dvec2, 4> out{*p0, *p0, *p0, *p0};
    for (int a = 0; a < 3; ++a) {
        Vec3 axis(0.0);
        axis[a] = 1.0;
        // An arrow as long as the axis shows: full length across the view, short along it.
        if (const auto s = axisOnScreen(cam_, width, height, pivot, axis); s && s->acrossPx > 0.0)
            out[size_t(a + 1)] = *p0 + s->alongPx / s->acrossPx * double(kGizmoLengthPx * window_.uiScale());
    }
    return out;
}

int Editor::gizmoHit(double mx, double my) const {
    const auto [W, H] = viewSize();
    const auto g = gizmoHandles(W, H);
    if (!g) return -1;
    const glm::dvec2 m(mx, my);
    const double r = kGizmoGrabPx * window_.uiScale();
    int best = -1;
    double bestD = r;
    for (int a = 0; a < 3; ++a) {
        // The outer two thirds of an arrow: the centre is the free move's.
        const glm::dvec2 from = (*g)[0] + ((*g)[size_t(a + 1)] - (*g)[0]) / 3.0;
        if (glm::length((*g)[size_t(a + 1)] - (*g)[0]) < 12.0) continue;  // seen end-on
        const double d = segmentDistance(m, from, (*g)[size_t(a + 1)]);
        if (d < bestD) bestD = d, best = a;
    }
    if (best < 0 && glm::length(m - (*g)[0]) < 1.6 * r) best = 3;
    return best;
}

void Editor::drawViewportOverlays() {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const auto rects = teaching_.viewPaneRects(sidePanels_.layout());
    for (size_t i = 0; i < rects.size(); ++i) {
        const auto& r = rects[i];
        // Not under the side panels: their backgrounds are filled before ImGui draws this list.
        const float x0 = std::max(r[0], sidePanels_.layout().left),
                    x1 = std::min(r[0] + r[2], ImGui::GetIO().DisplaySize.x - sidePanels_.layout().right);
        dl->PushClipRect(ImVec2(x0, r[1]), ImVec2(std::max(x0, x1), r[1] + r[3]), true);
        drawPaneOverlays(r, int(i) == teaching_.activePane || !teaching_.viewSplit());
        dl->PopClipRect();
    }

    // A document too heavy for the CPU renderer at its own levels is drawn screen-adaptive: say so.
    if (const auto load = degradedLoad()) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "Heavy for this CPU renderer: %llu patches, %.1f M vertices a frame at level %d. Drawn screen-adaptive "
                      "(8 px a segment); View > Full Detail draws it as set.",
                      (unsigned long long)load->patches, double(load->evaluations) / 1e6, load->segments);
        const float x = float(sidePanels_.layout().left) + 12.0f, y = ImGui::GetIO().DisplaySize.y - 3.2f * ImGui::GetFontSize();
        const float wrap = std::max(ImGui::GetIO().DisplaySize.x - float(sidePanels_.layout().right) - x - 12.0f, 100.0f);
        dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(x, y), IM_COL32(255, 190, 90, 255), text, nullptr, wrap);
    }

    // Mode line.
    if (mode_ == Interaction::Grab || mode_ == Interaction::DragPoints) {
        const std::string hint = "X/Y/Z axis · Shift+X/Y/Z plane · U/V/N slide · Ctrl snap (" + std::string(snapTargetName(session_.snap)) +
                                 ")" + (mode_ == Interaction::Grab ? " · type a value · click/Enter confirm" : "") +
                                 " · Esc/right click cancel";
        const std::string text =
            drag_.status() + (session_.symmetry.on() ? " · symmetry " + symmetryName(session_.symmetry) : "") + "\n" + hint;
        const float x = float(sidePanels_.layout().left) + 12.0f;
        const float wrap = std::max(ImGui::GetIO().DisplaySize.x - float(sidePanels_.layout().right) - x - 12.0f, 100.0f);
        dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(x, 30.0f), IM_COL32(255, 230, 120, 255), text.c_str(), nullptr, wrap);
    }
}

void Editor::drawPaneOverlays(const std::array<float, 4>& pane, bool active) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const ImGuiIO& io = ImGui::GetIO();
    const int W = std::max(int(pane[2]), 1), H = std::max(int(pane[3]), 1);
    const ViewMatrices vm = viewMatrices(cam_, double(W) / H);
    auto proj = [&](const Vec3& p) -> std::optional<glm::dvec2> {
        auto s = projectToPixel(vm, p, W, H);
        if (s) *s += glm::dvec2(pane[0], pane[1]);
        return s;
    };
    auto line = [&](const Vec3& a, const Vec3& b, ImU32 col, float th) {
        const auto pa = proj(a), pb = proj(b);
        if (pa && pb) dl->AddLine(ImVec2(float(pa->x), float(pa->y)), ImVec2(float(pb->x), float(pb->y)), col, th);
    };

    drawJoinOverlay(line);
    drawCurveOverlay(line);
    drawConstructionPreview(line);

    // Joins out of their tolerances (the Continuity panel's red rows), live while dragging: with the
    // Boundaries overlay, which colours joins by kind, these stand out thick in orange.
    if (doc_.display.showBoundaries) {
        size_t drawn = 0;
        for (const JoinContinuity& c : continuity_.report()) {
            if (!continuity_.failures(c.join) || c.join >= doc_.joins.size() || ++drawn > 512) continue;
            const Join& j = doc_.joins[c.join];
            const std::vector<Vec3> curve = boundaryCurve(doc_, j.patchA, j.edgeA);  // a patch's or a triangle's edge
            for (size_t k = 0; k + 1 < curve.size(); ++k) line(curve[k], curve[k + 1], IM_COL32(255, 140, 40, 255), 4.5f);
        }
    }

    // Selected patch: its boundary curves, the highlighted edge (extrude, unjoin) brighter.
    if (sel_.patch >= 0 && sel_.patch < int(doc_.patches.size()))
        for (int e = 0; e < 4; ++e) {
            const bool hl = e == int(lastEdge_);
            const std::vector<Vec3> c = boundaryCurve(doc_, uint32_t(sel_.patch), Edge(e));
            for (size_t k = 0; k + 1 < c.size(); ++k)
                line(c[k], c[k + 1], hl ? IM_COL32(255, 120, 255, 255) : IM_COL32(80, 220, 255, 255), hl ? 4.0f : 2.5f);
        }

    // Selected Bézier triangle: its three boundary curves.
    if (sel_.triangle >= 0 && sel_.triangle < int(doc_.triangles.size())) {
        const Net10 net = gatherTriangleNet(doc_, doc_.triangles[size_t(sel_.triangle)].idx);
        const int n = 24;
        for (int e = 0; e < 3; ++e)
            for (int k = 0; k < n; ++k) {
                // Edge e runs from one corner to the next (u = 0: v to w, v = 0: w to u, w = 0: u to v).
                auto at = [&](int s) {
                    const double t = double(s) / n;
                    const double u = e == 0 ? 0.0 : e == 1 ? t : 1.0 - t, v = e == 0 ? 1.0 - t : e == 1 ? 0.0 : t;
                    return evaluateTriangle(net, u, v).p;
                };
                line(at(k), at(k + 1), IM_COL32(80, 220, 255, 255), 2.5f);
            }
    }

    // Selected and hovered points.
    for (uint32_t p : sel_.points)
        if (p < doc_.points.size())
            if (auto s = proj(doc_.points[p])) dl->AddCircleFilled(ImVec2(float(s->x), float(s->y)), 5.0f, IM_COL32(255, 140, 30, 255));
    if (hovered_ >= 0 && hovered_ < int(doc_.points.size()))
        if (auto s = proj(doc_.points[size_t(hovered_)]))
            dl->AddCircle(ImVec2(float(s->x), float(s->y)), 8.0f, IM_COL32(255, 255, 255, 255), 16, 2.0f);

    // Soft selection's reach during a transform: a circle of its radius around the pivot, in the view
    // plane (the shares fall off along the nets, so this is the reach as the crow flies), and the
    // radius beside it; the wheel changes it.
    if ((mode_ == Interaction::DragPoints || mode_ == Interaction::Grab) && drag_.soft().on) {
        const glm::dvec3 right(vm.view[0][0], vm.view[1][0], vm.view[2][0]);
        const auto c = proj(drag_.anchor()), e = proj(drag_.anchor() + drag_.soft().radius * right);
        softRadiusPixels_ = 0.0f;
        if (c && e) {
            const ImVec2 at(float(c->x), float(c->y));
            const float r = float(glm::length(*e - *c));
            softRadiusPixels_ = r;
            dl->AddCircle(at, r, IM_COL32(255, 200, 80, 200), 64, 1.5f);
            char label[64];
            std::snprintf(label, sizeof label, "soft %.3g (wheel) %zu pts", drag_.soft().radius, drag_.softCount());
            const ImVec2 t(at.x + r * 0.71f + 4.0f, at.y - r * 0.71f - ImGui::GetFontSize()), size = ImGui::CalcTextSize(label);
            dl->AddRectFilled(ImVec2(t.x - 3.0f, t.y - 1.0f), ImVec2(t.x + size.x + 3.0f, t.y + size.y + 1.0f), IM_COL32(0, 0, 0, 150),
                              3.0f);
            dl->AddText(t, IM_COL32(255, 220, 140, 255), label);
        }
    } else {
        softRadiusPixels_ = 0.0f;
    }

    // Axis constraint line (or the plane's two axes) during a transform.
    if ((mode_ == Interaction::DragPoints || mode_ == Interaction::Grab) && drag_.axis() >= 0)
        for (int k = 0; k < 3; ++k) {
            if (drag_.plane() ? k == drag_.axis() : k != drag_.axis()) continue;
            Vec3 a(0.0);
            a[k] = 2.0 * modelSize(doc_);
            line(drag_.anchor() - a, drag_.anchor() + a, kAxisColours[k], 1.5f);
        }

    // The move gizmo at the pivot: arrows along X, Y, Z (drag one to move along it), the centre
    // ring moves in the view plane; a rotation or scale shows its pivot and the mouse's lever.
    if (active && (mode_ == Interaction::None || mode_ == Interaction::Grab || mode_ == Interaction::DragPoints))
        if (const auto g = gizmoHandles(W, H)) {
            const ImVec2 c(float((*g)[0].x) + pane[0], float((*g)[0].y) + pane[1]);
            if (mode_ == Interaction::None) {
                for (int a = 0; a < 3; ++a) {
                    const ImVec2 e(float((*g)[size_t(a + 1)].x) + pane[0], float((*g)[size_t(a + 1)].y) + pane[1]);
                    const bool hot = hoveredGizmo_ == a;
                    dl->AddLine(c, e, hot ? IM_COL32(255, 255, 255, 255) : kAxisColours[a], hot ? 4.0f : 2.5f);
                    dl->AddCircleFilled(e, hot ? 6.0f : 4.5f, hot ? IM_COL32(255, 255, 255, 255) : kAxisColours[a]);
                }
                dl->AddCircle(c, 9.0f, hoveredGizmo_ == 3 ? IM_COL32(255, 255, 255, 255) : IM_COL32(230, 230, 230, 200), 24, 2.0f);
            } else if (drag_.kind() != TransformKind::Move) {
                dl->AddCircleFilled(c, 4.0f, IM_COL32(255, 230, 120, 255));
                dl->AddLine(c, io.MousePos, IM_COL32(255, 230, 120, 160), 1.0f);
            }
        }

    // The 3D cursor: where new items appear, the mirror plane's point and a pivot.
    if (const auto c = proj(session_.cursor)) {
        const ImVec2 p(float(c->x), float(c->y));
        dl->AddCircle(p, 9.0f, IM_COL32(230, 60, 60, 230), 24, 2.0f);
        dl->AddCircle(p, 9.0f, IM_COL32(255, 255, 255, 200), 12, 1.0f);
        dl->AddLine(ImVec2(p.x - 14.0f, p.y), ImVec2(p.x - 5.0f, p.y), IM_COL32(20, 20, 20, 230), 1.5f);
        dl->AddLine(ImVec2(p.x + 5.0f, p.y), ImVec2(p.x + 14.0f, p.y), IM_COL32(20, 20, 20, 230), 1.5f);
        dl->AddLine(ImVec2(p.x, p.y - 14.0f), ImVec2(p.x, p.y - 5.0f), IM_COL32(20, 20, 20, 230), 1.5f);
        dl->AddLine(ImVec2(p.x, p.y + 5.0f), ImVec2(p.x, p.y + 14.0f), IM_COL32(20, 20, 20, 230), 1.5f);
    }

    // Box selection rectangle.
    if (mode_ == Interaction::BoxSelect && active) {
        const ImVec2 a{float(pressX_) + pane[0], float(pressY_) + pane[1]}, b = io.MousePos;
        dl->AddRectFilled(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                          IM_COL32(100, 150, 255, 40));
        dl->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                    IM_COL32(120, 170, 255, 200));
    }

    // Axis gizmo: bottom left of the viewport (right of the left panel), or another corner of it
    // where the domain view window is, or none where that covers every corner.
    const float left = pane[0] + (teaching_.viewSplit() ? 0.0f : float(sidePanels_.layout().left));
    const float right = pane[0] + float(W) - (teaching_.viewSplit() ? 0.0f : float(sidePanels_.layout().right));
    const float top = pane[1] + ImGui::GetFrameHeight(), bottom = pane[1] + float(H);
    const std::array<float, 4>& avoid = teaching_.windowRect;
    std::optional<ImVec2> corner;
    for (const ImVec2 c : {ImVec2(left + 60.0f, bottom - 60.0f), ImVec2(right - 60.0f, bottom - 60.0f), ImVec2(right - 60.0f, top + 60.0f),
                           ImVec2(left + 60.0f, top + 60.0f)}) {
        const bool clear = avoid[2] <= 0.0f || c.x + 54.0f < avoid[0] || c.x - 54.0f > avoid[0] + avoid[2] || c.y + 54.0f < avoid[1] ||
                           c.y - 54.0f > avoid[1] + avoid[3];
        if (clear) {
            corner = c;
            break;
        }
    }
    axisGizmoRect_ = {0, 0, 0, 0};
    if (corner) {
        const ImVec2 c = *corner;
        axisGizmoRect_ = {c.x - 52.0f, c.y - 52.0f, 104.0f, 104.0f};
        const float len = 40.0f;
        struct Ax {
            glm::vec3 v;
            ImU32 col;
            const char* name;
        };
        Ax axes[3] = {{glm::vec3(vm.view * glm::vec4(1, 0, 0, 0)), IM_COL32(230, 70, 70, 255), "X"},
                      {glm::vec3(vm.view * glm::vec4(0, 1, 0, 0)), IM_COL32(80, 200, 80, 255), "Y"},
                      {glm::vec3(vm.view * glm::vec4(0, 0, 1, 0)), IM_COL32(80, 130, 255, 255), "Z"}};
        std::sort(axes, axes + 3, [](const Ax& a, const Ax& b) { return a.v.z < b.v.z; });
        dl->AddCircleFilled(c, len + 12.0f, IM_COL32(0, 0, 0, 60));
        for (const Ax& a : axes) {
            const ImVec2 e(c.x + a.v.x * len, c.y - a.v.y * len);
            dl->AddLine(c, e, a.col, 2.5f);
            dl->AddText(ImVec2(e.x - 3.0f, e.y - 7.0f), a.col, a.name);
        }
    }
}

}  // namespace editor
}  // namespace pw::ui

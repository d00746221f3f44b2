// Join by picking's steps (J, Patch > Join by Picking), apart from the window: pick an open edge,
// then the edge to join it to; the join runs at once through the `join` command (C1) as a preview
// whose continuity can be changed (taken back and run again), kept (Apply, Enter) or taken back
// (Cancel, Esc: back to the second pick). Rhino's Join and MatchSrf in one tool. The editor feeds
// it the edge under the mouse and the clicks (ui/editor/join_tool.cpp); ui_test_rules walks its
// states against the real command table.
#pragma once

#include <cstdint>
#include <optional>

#include "core/select/edge_pick.hpp"
#include "ui/panels/panel_context.hpp"

namespace pw::ui {
inline namespace panels {

struct JoinToolState {
    bool on = false;
    std::optional<PatchEdge> first, hover;  // the first pick; the open edge under the mouse
    bool preview = false;                   // the join a-b is applied, waiting for Apply or Cancel
    PatchEdge a, b;
    Continuity continuity = Continuity::C1;
    uint64_t version = 0;  // the session's version right after the preview ran
};

class JoinTool {
public:
    const JoinToolState& state() const { return s_; }
    // On (the first pick next) or off; turning it off keeps a preview.
    void setOn(PanelContext& ctx, bool on);
    void setHover(std::optional<PatchEdge> edge) { s_.hover = edge; }
    // A click on `edge`: the first pick, or the second, which runs the join as a preview. A join
    // the command refuses (its message shown) leaves the first pick for another second pick.
    void pick(PanelContext& ctx, const PatchEdge& edge);
    // In a preview: the join taken back and run again with continuity c.
    void choose(PanelContext& ctx, Continuity c);
    void apply(PanelContext& ctx) { setOn(ctx, false); }
    void cancel(PanelContext& ctx) { endPreview(ctx, false); }  // taken back, to the second pick
    // Esc: a preview is cancelled, a first pick dropped, else the tool closes.
    void back(PanelContext& ctx);
    // Any other edit while the preview shows keeps it (called before each frame's input).
    void followSession(const EditSession& session);

private:
    JoinToolState s_;
    void runPreview(PanelContext& ctx, Continuity c);  // `join a b c`
    void endPreview(PanelContext& ctx, bool keep);
};

}  // namespace panels
}  // namespace pw::ui

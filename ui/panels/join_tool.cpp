#include "ui/panels/join_tool.hpp"

#include <string>

namespace pw::ui {
inline namespace panels {

void JoinTool::setOn(PanelContext& ctx, bool on) {
    if (s_.preview) endPreview(ctx, true);
    s_ = JoinToolState{};
    s_.on = on;
    if (on) ctx.host().status("Join: click an open edge of the first patch");
    ctx.wake();
}

void JoinTool::pick(PanelContext& ctx, const PatchEdge& edge) {
    if (!s_.on || s_.preview) return;
    if (!s_.first) {
        s_.first = edge;
        ctx.host().status("Join: " + patchEdgeName(edge) + " picked; click the edge to join it to (Esc: back)");
        return;
    }
    s_.a = *s_.first;
    s_.b = edge;
    runPreview(ctx, Continuity::C1);
}

void JoinTool::choose(PanelContext& ctx, Continuity c) {
    if (!s_.preview || s_.continuity == c) return;
    endPreview(ctx, false);
    runPreview(ctx, c);
}

void JoinTool::back(PanelContext& ctx) {
    if (s_.preview)
        endPreview(ctx, false);
    else if (s_.first)
        s_.first.reset();
    else
        setOn(ctx, false);
}

void JoinTool::followSession(const EditSession& session) {
    if (s_.preview && session.version() != s_.version) {
        s_.preview = false;
        s_.first.reset();
    }
}

void JoinTool::runPreview(PanelContext& ctx, Continuity c) {
    const size_t before = ctx.session().doc.joins.size();
    ctx.runCommand({"join", patchEdgeName(s_.a), patchEdgeName(s_.b), std::string(continuityName(c))});
    s_.hover.reset();
    if (ctx.session().doc.joins.size() != before + 1) {  // refused: the message is shown; pick the second edge again
        s_.first = s_.a;
        return;
    }
    s_.first.reset();
    s_.preview = true;
    s_.continuity = c;
    s_.version = ctx.session().version();
}

void JoinTool::endPreview(PanelContext& ctx, bool keep) {
    if (!s_.preview) return;
    s_.preview = false;
    if (keep) {
        ctx.host().status("Joined " + patchEdgeName(s_.a) + " and " + patchEdgeName(s_.b) + " " +
                          std::string(continuityName(s_.continuity)));
        return;
    }
    if (ctx.session().version() == s_.version) ctx.runCommand({"undo"});
    s_.first = s_.a;  // back to the second pick
}

}  // namespace panels
}  // namespace pw::ui

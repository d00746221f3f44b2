// `set KEY VALUE...`: any row of the settings table (core/model/settings.hpp) — tessellation and
// display settings — checked against the row's range or choices, one undo step named by the row's
// label. The Tessellation and Display panels run it (as a live preview while a slider moves, then
// once for the undo step), so no panel writes the document itself.
#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/model/settings.hpp"

namespace pw {
inline namespace commands {

namespace {

std::string settingKeys() {
    std::string keys;
    for (const Setting& s : settings()) keys += (keys.empty() ? "" : ", ") + std::string(s.key);
    return keys;
}

// `set KEY VALUE...`: the words after the key are the row's values, checked by the settings table.
void execSet(CommandContext& ctx) {
    const Setting* s = findSetting(ctx.word(0));
    if (!s) throw EditError("no setting named '" + ctx.word(0) + "'; keys: " + settingKeys());
    const std::vector<double> values = parseSettingValues(*s, ctx.rest(1));
    if (ctx.preview) {
        s->set(ctx.session.doc, values);
        ctx.session.changedSettings();
        return;
    }
    ctx.session.apply(
        std::string(s->label), [&](Document& d) { s->set(d, values); }, false);
}

}  // namespace

void addSettingCommands(CommandTable& t) {
    using namespace arg;
    t.add({.name = "set",
           .label = "Set a Setting",
           .forms = {{word("KEY"), many(word("VALUE"))}},
           .help = "Set a tessellation or display setting by its file name (" + settingKeys() +
                   "): numbers within the setting's range, on|off, or one of its choices",
           .previewable = true,
           .exec = execSet});
}

}  // namespace commands
}  // namespace pw

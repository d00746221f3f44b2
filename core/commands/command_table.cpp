#include "core/commands/command_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace pw {

void CommandTable::add(Command c) {
    if (find(c.name)) throw std::logic_error("command '" + c.name + "' is defined twice");
    commands_.push_back(std::move(c));
}

const Command* CommandTable::find(std::string_view name) const {
    for (const Command& c : commands_)
        if (c.name == name) return &c;
    return nullptr;
}

std::vector<std::string> CommandTable::menus() const {
    std::vector<std::string> out;
    for (const Command& c : commands_)
        if (!c.menu.empty() && std::find(out.begin(), out.end(), c.menu) == out.end()) out.push_back(c.menu);
    return out;
}

std::vector<std::string> splitCommandWords(std::string_view line) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false, quoted = false;
    for (char ch : line) {
        if (ch == '"') {
            quoted = !quoted;
            inWord = true;
        } else if (!quoted && (ch == ' ' || ch == '\t' || ch == '\r')) {
            if (inWord) words.push_back(std::move(word));
            word.clear();
            inWord = false;
        } else {
            word += ch;
            inWord = true;
        }
    }
    if (quoted) throw EditError("a quote is not closed");
    if (inWord) words.push_back(std::move(word));
    return words;
}

void CommandTable::run(EditSession& session, CommandHost& host, std::string_view line, bool guarded) const {
    run(session, host, splitCommandWords(line), guarded);
}

void CommandTable::preview(EditSession& session, CommandHost& host, const std::vector<std::string>& words) const {
    if (words.empty()) return;
    const Command* c = find(words.front());
    if (!c || !c->previewable) throw EditError("'" + (words.front()) + "' cannot be previewed");
    CommandContext ctx{*c, session, host, std::vector<std::string>(words.begin() + 1, words.end()), true, true};
    try {
        c->run(ctx);
    } catch (const EditError& e) {
        throw EditError(c->name + ": " + e.what());
    }
}

void CommandTable::run(EditSession& session, CommandHost& host, const std::vector<std::string>& words, bool guarded) const {
    if (words.empty()) return;
    const Command* c = find(words.front());
    if (!c) throw EditError("unknown command '" + words.front() + "' (the F1 help and the palette list every command)");
    if (c->windowOnly && !host.hasWindow()) throw EditError("'" + c->name + "' needs the editor window");
    if (!isEnabled(*c, session)) throw EditError("'" + c->name + "' is not available now: " + c->help);
    CommandContext ctx{*c, session, host, std::vector<std::string>(words.begin() + 1, words.end()), guarded};
    try {
        c->run(ctx);
    } catch (const EditError& e) {
        throw EditError(c->name + ": " + e.what());
    }
    for (const std::string& note : session.takeNotes()) host.note(note);
}

void CommandTable::runScript(EditSession& session, CommandHost& host, std::string_view script, const std::string& scriptName) const {
    int lineNo = 0;
    size_t pos = 0;
    while (pos <= script.size()) {
        const size_t end = std::min(script.find('\n', pos), script.size());
        std::string_view line = script.substr(pos, end - pos);
        ++lineNo;
        pos = end + 1;
        if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        size_t start = 0;
        while (start <= line.size()) {
            const size_t semi = std::min(line.find(';', start), line.size());
            const std::string_view one = line.substr(start, semi - start);
            start = semi + 1;
            try {
                run(session, host, one);
            } catch (const InputError& e) {
                throw InputError(scriptName, e.what(), lineNo);
            } catch (const OutputError& e) {
                throw InputError(scriptName, e.what(), lineNo);
            } catch (const std::exception& e) {
                throw InputError(scriptName, e.what(), lineNo);
            }
        }
        if (end == script.size()) break;
    }
}

double commandNumber(const std::string& word, const char* what) {
    double v = 0.0;
    const char* b = word.data();
    const char* e = b + word.size();
    if (!word.empty() && *b == '+') ++b;
    const auto [ptr, ec] = std::from_chars(b, e, v);
    if (ec != std::errc() || ptr != e || !std::isfinite(v) || std::abs(v) > limits::kMaxCoordinate)
        throw EditError(std::string(what) + ": expected a finite number, got '" + word + "'");
    return v;
}

int axisIndex(const std::string& word) {
    if (word == "x" || word == "X") return 0;
    if (word == "y" || word == "Y") return 1;
    if (word == "z" || word == "Z") return 2;
    throw EditError("expected an axis X, Y or Z, got '" + word + "'");
}

uint32_t commandIndex(const std::string& word, size_t count, const char* what) {
    uint64_t v = 0;
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
    if (ec != std::errc() || ptr != word.data() + word.size())
        throw EditError(std::string(what) + ": expected an index, got '" + word + "'");
    if (v >= count) throw EditError(std::string(what) + " " + word + " does not exist (the document has " + std::to_string(count) + ")");
    return uint32_t(v);
}

Command windowToggle(const char* name, const char* label, const char* menu, WindowToggle which, std::vector<std::string> keys,
                     const char* help) {
    return {.name = name,
            .label = label,
            .menu = menu,
            .help = help,
            .bindings = {{"", "", std::move(keys)}},
            .windowOnly = true,
            .checked = [which](const EditSession&, const CommandHost& h) { return h.toggled(which); },
            .run = [which](CommandContext& ctx) { ctx.host.toggle(which); }};
}

void expectArgs(const CommandContext& ctx, size_t min, size_t max) {
    const size_t n = ctx.args.size();
    if (n >= min && n <= max) return;
    std::string want = min == max ? std::to_string(min) : std::to_string(min) + " to " + std::to_string(max);
    throw EditError("expected " + want + " argument" + (max == 1 ? "" : "s") + ", got " + std::to_string(n) +
                    " (usage: " + ctx.command.name + (ctx.command.usage.empty() ? "" : " " + ctx.command.usage) + ")");
}

CommandTable makeCommandTable() {
    CommandTable t;
    addFileCommands(t);
    addSelectCommands(t);
    addModelCommands(t);
    addPrimitiveCommands(t);
    addViewCommands(t);
    addSettingCommands(t);
    addDisplacementCommands(t);
    addConstructCommands(t);
    return t;
}

}  // namespace pw

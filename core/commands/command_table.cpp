#include "core/commands/command_table.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace pw {
inline namespace commands {

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

namespace {

std::string argUsage(const CommandArg& a) {
    if (!a.shown.empty()) return a.shown;
    std::string text;
    switch (a.type) {
        case ArgType::Choice:
            for (const std::string& c : a.choices) text += (text.empty() ? "" : "|") + c;
            break;
        case ArgType::Axis:
            text = "X|Y|Z";
            break;
        case ArgType::Edge:
            text = a.name == "EDGE" ? "u0|v0|u1|v1" : a.name;
            break;
        default:
            text = a.name;
    }
    return a.repeated ? text + "..." : text;
}

std::string formUsage(const CommandForm& form) {
    std::string out;
    size_t open = 0;
    for (const CommandArg& a : form) {
        if (!out.empty()) out += ' ';
        if (a.optional) out += '[', ++open;
        out += argUsage(a);
    }
    return out + std::string(open, ']');
}

// The value of `word` as argument `a`, or the reason it is not one.
std::optional<ArgValue> checkArg(const CommandArg& a, const std::string& word, const Document& doc, std::string& why) {
    ArgValue v;
    try {
        switch (a.type) {
            case ArgType::Word:
                break;  // "" clears a name
            case ArgType::Path:
                if (word.empty()) throw EditError(a.name + ": expected a file name, got nothing");
                break;
            case ArgType::Number:
                v.number = commandNumber(word, a.name.c_str());
                break;
            case ArgType::Count: {
                double k = 0.0;
                const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), k);
                if (ec != std::errc() || ptr != word.data() + word.size() || !(k >= 0.0 && k <= double(limits::kMaxPoints)) ||
                    k != std::floor(k))
                    throw EditError(a.name + ": expected a whole number, got '" + word + "'");
                v.index = uint32_t(k);
                v.number = k;
                break;
            }
            case ArgType::Choice: {
                const auto same = [&](const std::string& c) {
                    return a.anyCase ? std::equal(c.begin(), c.end(), word.begin(), word.end(),
                                                  [](char x, char y) { return std::tolower(uint8_t(x)) == std::tolower(uint8_t(y)); })
                                     : c == word;
                };
                const auto it = std::find_if(a.choices.begin(), a.choices.end(), same);
                if (it == a.choices.end()) {
                    std::string list;
                    for (size_t i = 0; i < a.choices.size(); ++i)
                        list += (i == 0 ? "" : i + 1 == a.choices.size() ? " or " : ", ") + a.choices[i];
                    throw EditError("expected " + list + ", got '" + word + "'");
                }
                v.index = uint32_t(it - a.choices.begin());
                break;
            }
            case ArgType::Axis:
                v.index = uint32_t(axisIndex(word));
                break;
            case ArgType::Edge: {
                const auto e = parseEdge(word);
                if (!e) throw EditError("expected an edge u0, v0, u1 or v1, got '" + word + "'");
                v.index = uint32_t(*e);
                break;
            }
            case ArgType::Patch:
                v.index = commandIndex(word, doc.patches.size(), "patch");
                break;
            case ArgType::Triangle:
                v.index = commandIndex(word, doc.triangles.size(), "triangle");
                break;
            case ArgType::Curve:
                v.index = commandIndex(word, doc.curves.size(), "curve");
                break;
            case ArgType::Net:
                v.index = commandIndex(word, doc.surfaces.size(), "net");
                break;
        }
    } catch (const EditError& e) {
        why = e.what();
        return std::nullopt;
    }
    return v;
}

// The number of words a form takes: [fewest, most].
std::pair<size_t, size_t> formArity(const CommandForm& form) {
    size_t least = 0;
    for (const CommandArg& a : form) least += a.optional ? 0 : 1;
    const bool open = !form.empty() && form.back().repeated;
    return {least, open ? std::numeric_limits<size_t>::max() : form.size()};
}

}  // namespace

std::string commandUsage(const Command& c) {
    if (c.forms.size() == 2 && c.forms[0].empty()) return "[" + formUsage(c.forms[1]) + "]";
    std::string out;
    for (const CommandForm& f : c.forms) out += (out.empty() ? "" : " | ") + formUsage(f);
    return out;
}

bool commandNeedsWords(const Command& c) {
    return !c.forms.empty() && std::all_of(c.forms.begin(), c.forms.end(), [](const CommandForm& f) { return formArity(f).first > 0; });
}

// Fits the context's words to the first of the command's forms that takes them; otherwise an
// EditError naming the argument (or the count and the usage).
static void bindArgs(CommandContext& ctx) {
    const Command& c = ctx.command;
    const std::vector<CommandForm> none(1);
    const std::vector<CommandForm>& forms = c.forms.empty() ? none : c.forms;
    const size_t n = ctx.args.size();
    std::string bestWhy;  // of the form that fitted the most words before one failed
    size_t fitting = 0, bestDepth = 0;
    for (size_t f = 0; f < forms.size(); ++f) {
        const auto [least, most] = formArity(forms[f]);
        if (n < least || n > most) continue;
        ++fitting;
        std::vector<ArgValue> values;
        std::string why;
        size_t depth = 0;
        for (size_t i = 0; i < n && why.empty(); ++i) {
            const CommandArg& a = forms[f][std::min(i, forms[f].size() - 1)];
            if (const auto v = checkArg(a, ctx.args[i], ctx.session.doc, why)) values.push_back(*v), depth = i + 1;
        }
        if (why.empty()) {
            ctx.form = f;
            ctx.values = std::move(values);
            return;
        }
        if (bestWhy.empty() || depth > bestDepth) bestWhy = why, bestDepth = depth;
    }
    if (fitting > 0) throw EditError(bestWhy);
    size_t least = std::numeric_limits<size_t>::max(), most = 0;
    for (const CommandForm& f : forms) {
        const auto [l, m] = formArity(f);
        least = std::min(least, l), most = std::max(most, m);
    }
    std::string want = least == most                                ? std::to_string(least)
                       : most == std::numeric_limits<size_t>::max() ? "at least " + std::to_string(least)
                       : forms.size() == 1                          ? std::to_string(least) + " to " + std::to_string(most)
                                                                    : "another number of";
    const std::string usage = commandUsage(c);
    throw EditError("expected " + want + " argument" + (most == 1 ? "" : "s") + ", got " + std::to_string(n) + " (usage: " + c.name +
                    (usage.empty() ? "" : " " + usage) + ")");
}

void CommandTable::run(EditSession& session, CommandHost& host, std::string_view line, bool guarded) const {
    run(session, host, splitCommandWords(line), guarded);
}

void CommandTable::preview(EditSession& session, CommandHost& host, const std::vector<std::string>& words) const {
    if (words.empty()) return;
    const Command* c = find(words.front());
    if (!c || !c->previewable) throw EditError("'" + (words.front()) + "' cannot be previewed");
    if (!isEnabled(*c, session)) throw EditError("'" + c->name + "' is not available now: " + c->help);
    CommandContext ctx{*c, session, host, std::vector<std::string>(words.begin() + 1, words.end()), true, true};
    try {
        bindArgs(ctx);
        c->exec(ctx);
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
        bindArgs(ctx);
        c->exec(ctx);
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
    if (ec != std::errc() || ptr != e || !std::isfinite(v))
        throw EditError(std::string(what) + ": expected a finite number, got '" + word + "'");
    if (std::abs(v) > limits::kMaxCoordinate) {
        char msg[160];
        std::snprintf(msg, sizeof msg, "%s: %g is beyond the coordinate limit ±%g and was not applied", what, v, limits::kMaxCoordinate);
        throw EditError(msg);
    }
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
            .exec = [which](CommandContext& ctx) { ctx.host.toggle(which); }};
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
    addItemCommands(t);
    addNetCommands(t);
    addTessCommands(t);
    addTrimCommands(t);
    return t;
}

}  // namespace commands
}  // namespace pw

// Issue 73's randomized edit test: seeded scripts of 20–50 commands (joins, splits, blends, fills,
// revolves, transforms, trims, undo/redo …) on every example, through the command table as
// `patchwork edit` runs them. A refusal is fine; what is accepted must keep the invariants a user
// sees: after every accepted command every join measures within the document's tolerances (as
// `info` measures it), no patch is turned over that was not and no new one is turned over where the
// model had no fold; after each script the document,
// saved and reopened, saves to the same bytes.
// PATCHWORK_RANDOM_EDIT_SCRIPTS sets the scripts per example (default 4: the ctest form);
// scripts/random_edits.sh N runs the long form. A failure names the example, the seed and the
// script up to the command that broke it, so it replays with `patchwork edit FILE -c '…'`.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "core/base/errors.hpp"
#include "core/commands/command_table.hpp"
#include "core/edit/edit_session.hpp"
#include "core/eval/fold_check.hpp"
#include "core/io/document_io.hpp"
#include "core/io/patchwork_format.hpp"
#include "core/solve/continuity_report.hpp"
#include "support.hpp"

using namespace pw;

namespace {

const char* const kTemplates[] = {
    "undo",
    "redo",
    "select patch {p}; move 0 0 {x}",
    "select patch {p}; move {x} 0 0",
    "select patch {p}; rotate Z {a}",
    "select patch {p}; scale {s}",
    "select all; scale {s}",
    "select patch {p}; split u {t}",
    "select patch {p}; split v {t}",
    "split-ring {p} u {t}",
    "join {p}:{e} {q}:{f} {k}",
    "unjoin {p}:{e}",
    "select patch {p}; flip",
    "mirror X",
    "select patch {p}; duplicate",
    "select patch {p}; delete",
    "add-patch",
    "add-curve",
    "fill-hole {p}:{e} {q}:{f}",
    "blend {p}:{e} {q}:{f} {k}",
    "revolve {p}:{e} Z {a}",
    "revolve {p}:{e} X {a}",
    "select patch {p}; extrude {e} {x}",
    "project c{c} {p}",
    "trim {p} c{c} keep",
    "trim {p} c{c} remove",
    "intersect {p} {q}",
    "untrim {p}",
    "bake c{c}",
    "curve-through 0,0,0 1,0,0 1,1,{x}",
    "loft c{c} c{c}",
    "select curve {c}; move 0 {x} 0",
    "select patch {p}; mirror Y",
};

struct Script {
    std::vector<std::string> commands;
    std::string text(size_t upTo) const {
        std::string s;
        for (size_t i = 0; i <= upTo && i < commands.size(); ++i) s += (i ? "; " : "") + commands[i];
        return s;
    }
};

std::string fill(const std::string& pattern, std::mt19937& rng, const Document& doc) {
    auto pick = [&](size_t n) { return std::to_string(std::uniform_int_distribution<size_t>(0, n ? n - 1 : 0)(rng)); };
    auto real = [&](double lo, double hi) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3f", std::uniform_real_distribution<double>(lo, hi)(rng));
        return std::string(buf);
    };
    const char* edges[] = {"u0", "u1", "v0", "v1"};
    const char* conts[] = {"C0", "C1", "G1", "C2", "G2"};
    const int angles[] = {30, 90, 180, 360};
    std::string out;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '{') {
            out += pattern[i];
            continue;
        }
        const char k = pattern[i + 1];
        i += 2;
        switch (k) {
            case 'p':
            case 'q':
                out += pick(doc.patches.size());
                break;
            case 'c':
                out += pick(doc.curves.size());
                break;
            case 'e':
            case 'f':
                out += edges[rng() % 4];
                break;
            case 'k':
                out += conts[rng() % 5];
                break;
            case 'x':
                out += real(-1.0, 1.0);
                break;
            case 't':
                out += real(0.05, 0.95);
                break;
            case 's':
                out += real(0.5, 1.5);
                break;
            case 'a':
                out += std::to_string(angles[rng() % 4]);
                break;
        }
    }
    return out;
}

// The joins out of tolerance, as `info` counts them.
std::vector<std::string> joinsOut(const Document& doc) {
    std::vector<std::string> out;
    for (const JoinContinuity& m : continuityReport(doc))
        if (toleranceFailures(m, doc.joins[m.join].continuity, doc.tolerances)) {
            char buf[200];
            std::snprintf(buf, sizeof buf, "join %zu (%s) gap %.3g, %.3g deg, %.3g %%", m.join,
                          std::string(continuityName(doc.joins[m.join].continuity)).c_str(), m.c0Gap, m.normalAngleDeg,
                          m.curvatureDeviationPct);
            out.push_back(buf);
        }
    return out;
}

int scriptsPerExample() {
    const char* v = std::getenv("PATCHWORK_RANDOM_EDIT_SCRIPTS");
    return v && *v ? std::max(1, std::atoi(v)) : 4;
}

void runRandomScripts(const std::string& example) {
    const CommandTable table = makeCommandTable();
    test::NoWritesHost host;
    const auto dir = test::freshTempDir("random-edits");
    const int scripts = scriptsPerExample();
    const unsigned base = unsigned(std::hash<std::string>{}(example)&0xffff);
    for (int n = 0; n < scripts; ++n) {
        const unsigned seed = base * 1000 + unsigned(n);
        std::mt19937 rng(seed);
        EditSession s;
        s.open((test::dataDir() / example).string());
        const size_t offBefore = joinsOut(s.doc).size();
        Script script;
        const int length = 20 + int(rng() % 31);
        for (int i = 0; i < length; ++i) {
            const std::string line = fill(kTemplates[rng() % std::size(kTemplates)], rng, s.doc);
            script.commands.push_back(line);
            const Document before = s.doc;
            try {
                test::runCommands(table, s, host, line);
            } catch (const EditError&) {
                continue;  // a refusal is fine; anything else fails the test
            }
            const std::string where = example + " seed " + std::to_string(seed) + ": patchwork edit data/" + example + " -c '" +
                                      script.text(script.commands.size() - 1) + "'";
            const std::vector<std::string> off = joinsOut(s.doc);
            ASSERT_LE(off.size(), offBefore) << where << "\n  leaves " << off.size() << " joins out of tolerance, first: " << off[0];
            // No joined patch turned over further, whatever the edit; no join held by folding or
            // collapsing; no new patch turned over where the model had no fold.
            if (before.patches.size() == s.doc.patches.size()) {
                if (before.joins != s.doc.joins) {
                    const std::string fold = foldMadeBy(before, s.doc);
                    ASSERT_TRUE(fold.empty()) << where << "\n  folded " << fold;
                }
                std::vector<bool> joined(s.doc.patches.size(), false);
                for (const Join& j : s.doc.joins)
                    if (quadJoin(j)) joined[j.patchA] = joined[j.patchB] = true;
                for (uint32_t p = 0; p < joined.size(); ++p) {
                    bool moved = before.patches[p].idx != s.doc.patches[p].idx;
                    for (uint32_t i : s.doc.patches[p].idx) moved = moved || before.points[i] != s.doc.points[i];
                    if (joined[p] && moved) {
                        ASSERT_LE(patchShape(s.doc, p).invertedTriangles, patchShape(before, p).invertedTriangles)
                            << where << "\n  turned joined patch " << p << " over";
                    }
                }
            }
            const std::string made = newFoldIn(before, s.doc);
            ASSERT_TRUE(made.empty()) << where << "\n  made " << made;
        }
        // Saved and reopened, it saves to the same bytes.
        const auto file = dir / ("script-" + std::to_string(seed) + ".patchwork");
        saveDocument(s.documentToSave(), file);
        EditSession again;
        again.open(file.string());
        const std::string first = serializeDocument(s.documentToSave()), second = serializeDocument(again.documentToSave());
        ASSERT_EQ(first, second) << example << " seed " << seed << ": the document changes when reopened: patchwork edit data/" << example
                                 << " -c '" << script.text(script.commands.size()) << "'";
    }
}

}  // namespace

class RandomEdits : public ::testing::TestWithParam<std::string> {};

TEST_P(RandomEdits, AcceptedEditsKeepEveryInvariant) { runRandomScripts(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Examples, RandomEdits,
                         ::testing::Values("teapot.bpt", "teacup.bpt", "bottle.patchwork", "bspline_tube.patchwork",
                                           "catmull_rom_net.patchwork", "exact_sphere.patchwork", "fitted_fill.patchwork",
                                           "g2_pair.patchwork", "kettle.patchwork", "l_part.patchwork", "network.patchwork",
                                           "pipe.patchwork", "rounded_box.patchwork", "trimmed_plate.patchwork", "vase.patchwork"),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                             std::string n = i.param.substr(0, i.param.find('.'));
                             return n;
                         });

// Undo/redo: random edit sequences undone completely give back the original document bit for bit,
// and redone completely give the final one; labels, redo truncation and the modified flag.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "core/construct/model_builders.hpp"
#include "core/model/edit_history.hpp"
#include "core/ops/join_ops.hpp"
#include "core/ops/net_ops.hpp"
#include "core/ops/patch_ops.hpp"
#include "core/ops/split_ops.hpp"

using namespace pw;

namespace {

// One of the editor's patch or net operations on a random target; a refused one (EditError)
// leaves the document as it was, like in the editor.
void randomOperation(Document& doc, std::mt19937& rng) {
    Document d = doc;
    const uint32_t np = static_cast<uint32_t>(d.patches.size()), ns = static_cast<uint32_t>(d.surfaces.size());
    const uint32_t p = np ? static_cast<uint32_t>(rng() % np) : 0, s = ns ? static_cast<uint32_t>(rng() % ns) : 0;
    const Edge e = static_cast<Edge>(rng() % 4);
    try {
        if (np > 40 || ns > 4) {  // keep the document small: 10 000 steps keep whole documents
            if (ns > 4)
                deleteNetSurface(d, s);
            else
                deletePatch(d, p);
            doc = std::move(d);
            return;
        }
        switch (rng() % 10) {
            case 0:
                if (np) splitPatch(d, p, rng() % 2 == 0, 0.25 + 0.5 * double(rng() % 3) / 2.0);
                break;
            case 1:
                if (np) extrudeEdge(d, p, e);
                break;
            case 2:
                if (np) flipPatch(d, p);
                break;
            case 3:
                if (np > 1) joinEdges(d, p, e, static_cast<uint32_t>(rng() % np), static_cast<Edge>(rng() % 4), Continuity(rng() % 3));
                break;
            case 4:
                if (!d.joins.empty()) unjoin(d, rng() % d.joins.size());
                break;
            case 5:
                addNetSurface(d, 4 + rng() % 4, 4 + rng() % 4, NetShape(rng() % 3), Basis::BSpline, Vec3(double(rng() % 5)), 2.0);
                break;
            case 6:
                if (ns) insertNetRow(d, s, static_cast<uint32_t>(rng() % (d.surfaces[s].rows + 1)));
                break;
            case 7:
                if (ns) deleteNetColumn(d, s, static_cast<uint32_t>(rng() % d.surfaces[s].cols));
                break;
            case 8:
                if (ns) setNetBasis(d, s, Basis(rng() % 3), 0.5);
                break;
            default:
                if (ns && rng() % 4 == 0)
                    convertNetToPatches(d, s);
                else if (np)
                    duplicatePatch(d, p, Vec3(1.0, 0.0, 0.0));
                break;
        }
    } catch (const EditError&) {
        return;
    }
    doc = std::move(d);
}

// One random edit of the kinds the editor makes: move points, change a setting, add or delete a
// patch, add a join, or a patch or net operation.
void randomEdit(Document& doc, std::mt19937& rng) {
    std::uniform_int_distribution<int> kind(0, 11);
    std::uniform_real_distribution<double> delta(-0.5, 0.5);
    const int k = kind(rng);
    if (k <= 5 && !doc.points.empty()) {
        std::uniform_int_distribution<size_t> pick(0, doc.points.size() - 1);
        const int n = 1 + static_cast<int>(rng() % 4);
        for (int i = 0; i < n; ++i) doc.points[pick(rng)] += Vec3(delta(rng), delta(rng), delta(rng));
    } else if (k == 6) {
        doc.tess.outer[rng() % 4] = static_cast<float>(1 + rng() % 64);
        doc.tess.spacing = static_cast<Spacing>(rng() % 4);
    } else if (k == 7) {
        Patch p;
        const uint32_t base = static_cast<uint32_t>(doc.points.size());
        for (int i = 0; i < 16; ++i) {
            doc.points.push_back(Vec3(i % 4, i / 4, delta(rng)));
            p.idx[i] = base + i;
        }
        p.name = "added";
        doc.patches.push_back(p);
    } else if (k >= 10) {
        randomOperation(doc, rng);
    } else if (k == 8 && doc.patches.size() > 1) {
        // delete the last patch and any join that names it
        const uint32_t last = static_cast<uint32_t>(doc.patches.size() - 1);
        doc.patches.pop_back();
        std::erase_if(doc.joins, [&](const Join& j) { return j.patchA == last || j.patchB == last; });
    } else {
        doc.camera.yawDeg += 10;
        doc.display.showWireframe = !doc.display.showWireframe;
    }
}

}  // namespace

TEST(EditHistory, TenThousandRandomEditsUndoAndRedoBitIdentical) {
    Document doc = makePatchGrid(3, 3);
    const Document original = doc;
    EditHistory history(20000);
    std::mt19937 rng(1234);
    for (int i = 0; i < 10000; ++i) {
        const Document before = doc;
        randomEdit(doc, rng);
        history.commit(before, doc, "edit " + std::to_string(i));
    }
    const Document final = doc;
    ASSERT_NE(final, original);
    while (history.canUndo()) history.undo(doc);
    EXPECT_EQ(doc, original);
    EXPECT_EQ(std::memcmp(doc.points.data(), original.points.data(), original.points.size() * sizeof(Vec3)), 0);
    while (history.canRedo()) history.redo(doc);
    EXPECT_EQ(doc, final);
}

TEST(EditHistory, NewEditDropsRedoAndLabelsFollow) {
    Document doc = makePatchGrid(1, 1);
    EditHistory history;
    Document before = doc;
    doc.points[5] += Vec3(1, 0, 0);
    history.commit(before, doc, "Move point");
    before = doc;
    doc.tess.spacing = Spacing::Pow2;
    history.commit(before, doc, "Spacing");
    EXPECT_EQ(history.undoLabel(), "Spacing");
    history.undo(doc);
    EXPECT_EQ(doc.tess.spacing, Spacing::Equal);
    EXPECT_EQ(history.redoLabel(), "Spacing");
    before = doc;
    doc.points[0] += Vec3(0, 1, 0);
    history.commit(before, doc, "Move again");
    EXPECT_FALSE(history.canRedo());
    EXPECT_EQ(history.size(), 2u);
}

TEST(EditHistory, NoOpEditIsNotRecordedAndModifiedFlagTracksSave) {
    Document doc = makePatchGrid(1, 1);
    EditHistory history;
    history.commit(doc, doc, "nothing");
    EXPECT_FALSE(history.canUndo());
    EXPECT_FALSE(history.isModified());
    Document before = doc;
    doc.points[3].z += 0.25;
    history.commit(before, doc, "Move");
    EXPECT_TRUE(history.isModified());
    history.markSaved();
    EXPECT_FALSE(history.isModified());
    history.undo(doc);
    EXPECT_TRUE(history.isModified());
    history.redo(doc);
    EXPECT_FALSE(history.isModified());
}

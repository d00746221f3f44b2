// Issue 19: new patches, nets, triangles, curves and imports appear at the 3D cursor, but never
// inside existing geometry.
#include <gtest/gtest.h>

#include "core/commands/command_table.hpp"
#include "core/edit/edit_session.hpp"
#include "core/io/document_io.hpp"
#include "core/model/placement.hpp"
#include "core/ops/patch_ops.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using namespace pw;

namespace {

class NoWrites final : public CommandHost {
public:
    void write(const Document&, const std::string&) override {}
};

template <class Indices>
Bounds boxOf(const Document& d, const Indices& idx) {
    std::vector<Vec3> pts;
    for (uint32_t i : idx) pts.push_back(d.points[i]);
    return computeBounds(pts);
}

bool apart(const Bounds& a, const Bounds& b) {
    for (int k = 0; k < 3; ++k)
        if (a.max[k] < b.min[k] || b.max[k] < a.min[k]) return true;
    return false;
}

}  // namespace

TEST(Placement, AnItemOnTopOfAnotherMovesRightUntilClear) {
    Document d;
    addFlatPatch(d, Vec3(0.0), 1.0);
    addFlatPatch(d, Vec3(1.05, 0.0, 0.0), 1.0);  // two patches side by side: [-0.5, 1.55] in x
    const size_t first = d.points.size();
    addFlatPatch(d, Vec3(0.2, 0.1, 0.0), 1.0);
    const Vec3 move = moveClearOfExisting(d, first);
    EXPECT_GT(move.x, 0.0);
    EXPECT_EQ(move.y, 0.0);
    EXPECT_EQ(move.z, 0.0);
    const Bounds moved = boxOf(d, d.patches[2].idx);
    EXPECT_TRUE(apart(moved, boxOf(d, d.patches[0].idx)));
    EXPECT_TRUE(apart(moved, boxOf(d, d.patches[1].idx)));
    EXPECT_NEAR(moved.min.x, 1.55 + 0.1, 1e-12);  // just past the rightmost, a tenth of its width apart
}

TEST(Placement, AClearItemStaysAtTheCursor) {
    Document d;
    addFlatPatch(d, Vec3(0.0), 1.0);
    const size_t first = d.points.size();
    addFlatPatch(d, Vec3(0.0, 5.0, 0.0), 1.0);
    EXPECT_EQ(moveClearOfExisting(d, first), Vec3(0.0));
    EXPECT_EQ(moveClearOfExisting(d, d.points.size()), Vec3(0.0));  // nothing new
}

TEST(Placement, AddCommandsAndImportNeverLandInsideTheModel) {
    EditSession s;
    s.newDocument();
    const CommandTable table = makeCommandTable();
    NoWrites host;
    for (const char* c : {"add-patch", "add-net", "add-triangle", "add-curve", "add-patch"}) table.run(s, host, std::string_view(c));
    const fs::path dir = test::freshTempDir("placement");
    saveDocument(s.doc, dir / "copy.patchwork");
    table.run(s, host, std::vector<std::string>{"import", (dir / "copy.patchwork").string()});
    // Every item's box is apart from every other's.
    std::vector<Bounds> boxes;
    for (const auto& p : s.doc.patches) boxes.push_back(boxOf(s.doc, p.idx));
    for (const auto& n : s.doc.surfaces) boxes.push_back(boxOf(s.doc, n.idx));
    for (const auto& t : s.doc.triangles) boxes.push_back(boxOf(s.doc, t.idx));
    for (const auto& c : s.doc.curves) boxes.push_back(boxOf(s.doc, c.idx));
    ASSERT_GE(boxes.size(), 10u);
    for (size_t i = 0; i < boxes.size(); ++i)
        for (size_t j = i + 1; j < boxes.size(); ++j) EXPECT_TRUE(apart(boxes[i], boxes[j])) << i << " and " << j;
    fs::remove_all(dir);
}

// Box selection of the points you can see: the surface rasterised on the CPU hides the points
// behind it, in perspective and orthographic views; points on the surface stay seen; hidden items
// hide nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "core/eval/occlusion.hpp"
#include "core/ops/patch_ops.hpp"

using namespace pw;

namespace {

Camera camera(double pitch, bool ortho) {
    Camera c;
    c.target = {0.0, 0.0, 0.5};
    c.distance = 6.0;
    c.yawDeg = 20.0;
    c.pitchDeg = pitch;
    c.orthographic = ortho;
    return c;
}

std::vector<uint32_t> all(const Document& doc) {
    std::vector<uint32_t> v(doc.points.size());
    std::iota(v.begin(), v.end(), 0u);
    return v;
}

bool has(const std::vector<uint32_t>& v, uint32_t p) { return std::find(v.begin(), v.end(), p) != v.end(); }

}  // namespace

TEST(Occlusion, TheNearerPatchHidesTheFartherOnesPoints) {
    Document doc;
    addFlatPatch(doc, {0, 0, 0}, 2.0);  // below
    addFlatPatch(doc, {0, 0, 1}, 4.0);  // above and larger: covers the lower one seen from above
    for (bool ortho : {false, true}) {
        const auto fromAbove = unoccludedPoints(doc, camera(80.0, ortho), 800, 600, all(doc));
        for (uint32_t i : doc.patches[0].idx) EXPECT_FALSE(has(fromAbove, i)) << "ortho " << ortho;
        for (uint32_t i : doc.patches[1].idx) EXPECT_TRUE(has(fromAbove, i)) << "ortho " << ortho;  // on the surface: seen
        // From below the lower patch is in front; it hides the middle of the upper one only.
        const auto fromBelow = unoccludedPoints(doc, camera(-80.0, ortho), 800, 600, all(doc));
        for (uint32_t i : doc.patches[0].idx) EXPECT_TRUE(has(fromBelow, i));
        EXPECT_FALSE(has(fromBelow, doc.patches[1].idx[5]));
        EXPECT_TRUE(has(fromBelow, doc.patches[1].idx[0]));
    }
    // A hidden patch hides nothing.
    doc.patches[1].hidden = true;
    const auto shown = unoccludedPoints(doc, camera(80.0, false), 800, 600, all(doc));
    for (uint32_t i : doc.patches[0].idx) EXPECT_TRUE(has(shown, i));
}

TEST(Occlusion, ADomesOwnControlPointsAboveItAreSeenAndThoseUnderItAreNot) {
    Document doc;
    addFlatPatch(doc, {0, 0, 0}, 2.0);
    for (int s : {5, 6, 9, 10}) doc.points[doc.patches[0].idx[size_t(s)]].z = 1.0;  // a dome; its inner points float above it
    doc.points.push_back({0.1, 0.1, 0.2});                                          // a loose point inside the dome
    const uint32_t inside = uint32_t(doc.points.size() - 1);
    addFlatPatch(doc, {5, 5, 0}, 0.5);  // give the model its size; far away
    std::vector<uint32_t> cand = all(doc);
    const auto seen = unoccludedPoints(doc, camera(70.0, false), 800, 600, cand);
    for (int s : {5, 6, 9, 10}) EXPECT_TRUE(has(seen, doc.patches[0].idx[size_t(s)]));
    EXPECT_FALSE(has(seen, inside));
    EXPECT_TRUE(unoccludedPoints(doc, camera(70.0, false), 800, 600, {}).empty());
}

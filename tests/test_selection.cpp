// Editor selection rules (click, shift-click, box) and camera navigation (orbit, pan, zoom, frame).
#include <gtest/gtest.h>

#include <cmath>

#include "core/construct/model_builders.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/selection.hpp"

using namespace pw;

TEST(EditorSelection, ClickAndShiftClick) {
    Selection s;
    applyClick(s, 5, false);
    EXPECT_EQ(s.points, std::vector<uint32_t>{5});
    applyClick(s, 2, true);
    EXPECT_EQ(s.points, (std::vector<uint32_t>{2, 5}));
    applyClick(s, 5, true);  // toggles off
    EXPECT_EQ(s.points, std::vector<uint32_t>{2});
    applyClick(s, -1, true);  // shift-click on nothing keeps the selection
    EXPECT_EQ(s.points, std::vector<uint32_t>{2});
    applyClick(s, 7, false);
    EXPECT_EQ(s.points, std::vector<uint32_t>{7});
    applyClick(s, -1, false);
    EXPECT_TRUE(s.points.empty());
}

TEST(EditorSelection, BoxReplacesOrAdds) {
    Selection s;
    s.points = {1, 9};
    applyBox(s, {4, 3, 4}, false);
    EXPECT_EQ(s.points, (std::vector<uint32_t>{3, 4}));
    applyBox(s, {9, 3}, true);
    EXPECT_EQ(s.points, (std::vector<uint32_t>{3, 4, 9}));
    EXPECT_TRUE(s.contains(9));
    EXPECT_FALSE(s.contains(1));
}

TEST(EditorSelection, ClampAndCentroid) {
    Document doc = makePatchGrid(1, 1);
    Selection s;
    s.points = {0, 3, 100};
    s.patch = 4;
    s.curve = 0;  // the grid has no curves (an undone "Add curve")
    clampSelection(s, doc);
    EXPECT_EQ(s.points, (std::vector<uint32_t>{0, 3}));
    EXPECT_EQ(s.patch, -1);
    EXPECT_EQ(s.curve, -1);
    const Vec3 c = selectionCentroid(doc, s);
    EXPECT_NEAR(c.x, 0.5 * (doc.points[0].x + doc.points[3].x), 1e-12);
    s.points.clear();
    s.patch = 0;
    const Bounds b = frameTargetBounds(doc, s);
    EXPECT_FALSE(b.empty);
    EXPECT_NEAR(b.max.x - b.min.x, 1.0, 1e-9);
}

TEST(EditorCamera, OrbitTurnsAndClampsPitch) {
    Camera c;
    c.yawDeg = 0;
    c.pitchDeg = 10;
    orbitCamera(c, 10, 0, 1.0);
    EXPECT_DOUBLE_EQ(c.yawDeg, -10.0);
    orbitCamera(c, 0, 500, 1.0);
    EXPECT_DOUBLE_EQ(c.pitchDeg, 90.0);
    orbitCamera(c, 0, -1000, 1.0);
    EXPECT_DOUBLE_EQ(c.pitchDeg, -90.0);
}

TEST(EditorCamera, PanKeepsTheTargetUnderTheCursor) {
    for (bool ortho : {false, true}) {
        Camera c;
        c.target = {1, 2, 3};
        c.distance = 8;
        c.yawDeg = 30;
        c.pitchDeg = 20;
        c.orthographic = ortho;
        const int W = 1000, H = 700;
        const glm::dvec3 oldTarget(1, 2, 3);
        panCamera(c, 40, -25, H);
        // The old target now appears 40 px right and 25 px up of the centre.
        const auto p = projectToPixel(viewMatrices(c, double(W) / H), oldTarget, W, H);
        ASSERT_TRUE(p);
        EXPECT_NEAR(p->x, W / 2.0 + 40, 0.05) << ortho;
        EXPECT_NEAR(p->y, H / 2.0 - 25, 0.05) << ortho;
    }
}

TEST(EditorCamera, ZoomScalesDistance) {
    Camera c;
    c.distance = 10;
    zoomCamera(c, 1);
    EXPECT_NEAR(c.distance, 8.5, 1e-12);
    zoomCamera(c, -2);
    EXPECT_NEAR(c.distance, 10 / 0.85, 1e-9);
}

TEST(EditorCamera, AxesAreOrthonormal) {
    Camera c;
    c.yawDeg = 33;
    c.pitchDeg = -12;
    Vec3 r, u, f;
    cameraAxes(c, r, u, f);
    EXPECT_NEAR(glm::dot(r, u), 0.0, 1e-6);
    EXPECT_NEAR(glm::dot(r, f), 0.0, 1e-6);
    EXPECT_NEAR(glm::dot(u, f), 0.0, 1e-6);
    EXPECT_GT(u.z, 0.0);  // z-up world: the view's up points up
}

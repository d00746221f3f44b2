// Editor picking maths: rays through pixels, nearest projected point, box selection, ray–surface
// patch picking and the drag helpers (view plane, axis, grid snap).
#include <gtest/gtest.h>

#include <cmath>

#include "core/construct/model_builders.hpp"
#include "core/eval/patch_eval.hpp"
#include "core/model/camera_math.hpp"
#include "core/select/picking.hpp"

using namespace pw;

namespace {

Camera testCamera(bool ortho) {
    Camera c;
    c.target = {1.0, 1.0, 0.0};
    c.distance = 6.0;
    c.yawDeg = 25.0;
    c.pitchDeg = 35.0;
    c.orthographic = ortho;
    return c;
}

double distancePointRay(const Ray& r, const glm::dvec3& p) {
    const glm::dvec3 w = p - r.origin;
    return glm::length(w - r.dir * glm::dot(w, r.dir));
}

}  // namespace

TEST(EditorPicking, RayThroughProjectedPixelHitsThePoint) {
    for (bool ortho : {false, true}) {
        const Camera cam = testCamera(ortho);
        const int W = 1280, H = 720;
        const ViewMatrices vm = viewMatrices(cam, double(W) / H);
        for (const glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(1.5, 0.3, 0.8), glm::dvec3(2, 2, -0.5)}) {
            const auto px = projectToPixel(vm, p, W, H);
            ASSERT_TRUE(px);
            const Ray r = rayThroughPixel(cam, px->x, px->y, W, H);
            EXPECT_NEAR(glm::length(r.dir), 1.0, 1e-12);
            EXPECT_LT(distancePointRay(r, p), 1e-4) << "ortho=" << ortho;
            EXPECT_GT(glm::dot(p - r.origin, r.dir), 0.0);
        }
    }
}

TEST(EditorPicking, PickPointNearestWithinRadius) {
    const Camera cam = testCamera(false);
    const int W = 800, H = 600;
    const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const auto proj = projectPoints(cam, pts, W, H);
    ASSERT_TRUE(proj[1]);
    EXPECT_EQ(pickPoint(cam, pts, proj[1]->x + 2, proj[1]->y - 1, W, H, 8.0), 1);
    EXPECT_EQ(pickPoint(cam, pts, proj[1]->x + 20, proj[1]->y, W, H, 8.0), -1);
    // A masked-out point is never picked.
    const std::vector<bool> used = {true, false, true};
    EXPECT_EQ(pickPoint(cam, pts, proj[1]->x, proj[1]->y, W, H, 8.0, &used), -1);
}

TEST(EditorPicking, PickPointPrefersNearerOfOverlapping) {
    const Camera cam = testCamera(false);
    const glm::dvec3 eye = cameraEye(cam);
    const glm::dvec3 t(cam.target[0], cam.target[1], cam.target[2]);
    // Two points on the same line of sight: the one nearer the eye wins.
    const std::vector<Vec3> pts = {t, eye + (t - eye) * 0.5};
    const auto proj = projectPoints(cam, pts, 640, 480);
    EXPECT_EQ(pickPoint(cam, pts, proj[0]->x, proj[0]->y, 640, 480, 5.0), 1);
}

TEST(EditorPicking, BoxSelection) {
    const Camera cam = testCamera(false);
    const int W = 800, H = 600;
    const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 2, 0}};
    const auto proj = projectPoints(cam, pts, W, H);
    glm::dvec2 lo(1e9), hi(-1e9);
    for (int i : {0, 1}) lo = glm::min(lo, *proj[size_t(i)]), hi = glm::max(hi, *proj[size_t(i)]);
    // Drag direction does not matter.
    const auto boxed = pointsInBox(cam, pts, hi + glm::dvec2(1), lo - glm::dvec2(1), W, H);
    for (uint32_t i : {0u, 1u}) EXPECT_NE(std::find(boxed.begin(), boxed.end(), i), boxed.end());
    EXPECT_EQ(std::find(boxed.begin(), boxed.end(), 3u), boxed.end());
}

TEST(EditorPicking, UsedPointMask) {
    Document doc = makePatchGrid(1, 1);
    doc.points.push_back({9, 9, 9});
    const auto used = usedPointMask(doc);
    EXPECT_EQ(std::count(used.begin(), used.end(), true), 16);
    EXPECT_FALSE(used.back());
}

TEST(EditorPicking, TriangleIntersection) {
    Ray r{{0.2, 0.2, 5.0}, {0, 0, -1}};
    const auto t = intersectTriangle(r, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 5.0, 1e-12);
    r.origin = {0.8, 0.8, 5.0};
    EXPECT_FALSE(intersectTriangle(r, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    r.dir = {0, 0, 1};  // pointing away
    r.origin = {0.2, 0.2, 5.0};
    EXPECT_FALSE(intersectTriangle(r, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
}

TEST(EditorPicking, SurfacePickFindsThePatchUnderTheRay) {
    const Document doc = makePatchGrid(2, 3);  // patches over [0,3] x [0,2], row-major
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 3; ++col) {
            Ray r{{col + 0.5, row + 0.5, 10.0}, {0, 0, -1}};
            const auto hit = pickSurface(doc, r);
            ASSERT_TRUE(hit);
            const Net16 net = gatherNet(doc, doc.patches[size_t(hit->patch)].idx);
            // The hit patch's parameter domain contains the ray's (x, y).
            const Vec3 c = evaluateNet(net, Basis::Bezier, 0.5, hit->u, hit->v).p;
            EXPECT_NEAR(c.x, col + 0.5, 0.1);
            EXPECT_NEAR(c.y, row + 0.5, 0.1);
        }
    Ray miss{{10, 10, 10}, {0, 0, -1}};
    EXPECT_FALSE(pickSurface(doc, miss));
}

TEST(EditorPicking, DragHelpers) {
    const Ray r{{0, 0, 5}, glm::normalize(glm::dvec3(0.1, 0, -1))};
    const auto hit = intersectPlane(r, {0, 0, 1}, {0, 0, 1});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->z, 1.0, 1e-12);
    EXPECT_NEAR(hit->x, 0.4, 1e-12);
    EXPECT_FALSE(intersectPlane(r, {0, 0, 10}, {0, 0, 1}));  // behind the origin

    // Axis: the ray x = 2 going down the -z axis; the closest point on the x axis through (0,0,0) is (2,0,0).
    const Ray down{{2, 0, 5}, {0, 0, -1}};
    const glm::dvec3 onAxis = closestPointOnAxis(down, {0, 0, 0}, {1, 0, 0});
    EXPECT_NEAR(onAxis.x, 2.0, 1e-12);
    EXPECT_NEAR(onAxis.y, 0.0, 1e-12);
    EXPECT_NEAR(onAxis.z, 0.0, 1e-12);
    // Parallel axis: no motion.
    const glm::dvec3 par = closestPointOnAxis(down, {1, 1, 1}, {0, 0, 1});
    EXPECT_EQ(par, glm::dvec3(1, 1, 1));

    EXPECT_EQ(snapToGrid({0.26, -0.74, 1.0}, 0.5), glm::dvec3(0.5, -0.5, 1.0));
    EXPECT_EQ(snapToGrid({0.26, -0.74, 1.0}, 0.0), glm::dvec3(0.26, -0.74, 1.0));
    EXPECT_DOUBLE_EQ(niceGridStep(10.0), 1.0);
    EXPECT_DOUBLE_EQ(niceGridStep(7.0), 0.5);
    EXPECT_NEAR(niceGridStep(0.03), 0.002, 1e-15);
}

// `render --eye/--target` (issue 41): the orbit camera built from an eye and a target puts its eye
// there and projects the target to the image centre, for z-up and y-up documents alike.
TEST(CameraLookFrom, EyeAndTargetAreWhereTheyWereAsked) {
    for (bool zUp : {true, false})
        for (const glm::dvec3 eye : {glm::dvec3(0, -110, 45), glm::dvec3(3, 4, -5), glm::dvec3(-7, 0.5, 2), glm::dvec3(0.001, 0, 9)}) {
            Camera base = testCamera(false);
            base.zUp = zUp;
            const glm::dvec3 target(1, 2, 0.5);
            const auto cam = lookFrom(base, eye, target);
            ASSERT_TRUE(cam.has_value());
            const glm::dvec3 got = cameraEye(*cam);
            EXPECT_NEAR(glm::length(got - eye), 0.0, 1e-9 * glm::length(eye - target))
                << zUp << " " << eye.x << "," << eye.y << "," << eye.z;
            const auto px = projectToPixel(viewMatrices(*cam, 16.0 / 9.0), target, 1600, 900);
            ASSERT_TRUE(px.has_value());
            EXPECT_NEAR(px->x, 800.0, 1e-3);  // float matrices
            EXPECT_NEAR(px->y, 450.0, 1e-3);
            EXPECT_EQ(cam->fovYDeg, base.fovYDeg);
        }
    EXPECT_FALSE(lookFrom(testCamera(false), glm::dvec3(1, 1, 1), glm::dvec3(1, 1, 1)).has_value());
}

// `render --theme light` frames the surface tightly: every point inside the image, and the points
// span nearly all of its width or height (perspective and orthographic, any direction).
TEST(CameraFrameTightly, PointsFillTheFrame) {
    std::vector<glm::dvec3> pts;
    for (int i = 0; i < 200; ++i) {
        const double t = i * 0.37;
        pts.emplace_back(3.0 * std::cos(t) + 1.0, 1.2 * std::sin(1.7 * t) - 2.0, 0.8 * std::sin(t) + 0.5 * std::cos(3.1 * t) + 4.0);
    }
    for (bool ortho : {false, true})
        for (double yaw : {0.0, 40.0, 200.0}) {
            Camera cam = testCamera(ortho);
            cam.yawDeg = yaw;
            const Camera tight = frameTightly(cam, pts, 16.0 / 9.0, 1.0);
            const ViewMatrices vm = viewMatrices(tight, 16.0 / 9.0);
            double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
            for (const auto& p : pts) {
                const auto px = projectToPixel(vm, p, 1600, 900);
                ASSERT_TRUE(px.has_value());
                x0 = std::min(x0, px->x), x1 = std::max(x1, px->x), y0 = std::min(y0, px->y), y1 = std::max(y1, px->y);
            }
            EXPECT_GE(x0, -1.0) << ortho << " " << yaw;
            EXPECT_LE(x1, 1601.0) << ortho << " " << yaw;
            EXPECT_GE(y0, -1.0) << ortho << " " << yaw;
            EXPECT_LE(y1, 901.0) << ortho << " " << yaw;
            EXPECT_GT(std::max((x1 - x0) / 1600.0, (y1 - y0) / 900.0), 0.97) << ortho << " " << yaw;
        }
}

// Helpers for the renderer tests: one Vulkan device per test process with the validation layer on
// (every test fails on any validation message), offscreen rendering to RGBA8 pixels, and small
// hand-made documents.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/model/camera_math.hpp"
#include "render/scene/renderer.hpp"
#include "render/targets/offscreen_target.hpp"
#include "render/vk/device.hpp"

namespace pw::test {

struct Image {
    uint32_t w = 0, h = 0;
    std::vector<uint8_t> rgba;
    const uint8_t* at(int x, int y) const { return &rgba[(size_t(y) * w + size_t(x)) * 4]; }
};

// A device shared by the tests of one process (created on first use, validation on).
inline render::Device& sharedDevice() {
    static std::unique_ptr<render::Device> dev = [] {
        render::DeviceOptions o;
        o.validation = true;
        return std::make_unique<render::Device>(o);
    }();
    return *dev;
}

// Fails the current test when the validation layer said anything since the fixture started.
class RenderTest : public ::testing::Test {
protected:
    void SetUp() override {
        render::Device::resetValidationMessageCount();
        ASSERT_TRUE(sharedDevice().validationEnabled());
    }
    void TearDown() override { EXPECT_EQ(render::Device::validationMessageCount(), 0u) << "Vulkan validation messages (see stderr)"; }
};

// Renders `doc` once (the first frame also warms the pipeline) and returns the pixels and stats.
struct Rendered {
    Image image;
    render::FrameStats stats;
};

class Offscreen {
public:
    Offscreen(uint32_t w, uint32_t h, bool msaa = true) : target_(sharedDevice(), w, h, msaa), renderer_(sharedDevice(), target_) {}
    void setDocument(const Document& doc, std::shared_ptr<const HeightMap> map = {}) { renderer_.setDocument(doc, std::move(map)); }
    void setPlainMesh(const TriangleMesh& m) { renderer_.setPlainMesh(m); }
    void updateLevels(const Document& doc) { renderer_.updateLevels(doc); }
    Rendered render(const render::RenderOptions& o) {
        Rendered r;
        r.stats = renderer_.render(o);
        r.image.w = target_.extent().width;
        r.image.h = target_.extent().height;
        r.image.rgba = target_.pixels();
        return r;
    }
    // The surface render(o) draws, read back through transform feedback and welded.
    render::CapturedSurface capture(const render::RenderOptions& o) { return renderer_.captureSurface(o); }
    uint32_t width() const { return target_.extent().width; }
    uint32_t height() const { return target_.extent().height; }

private:
    render::OffscreenTarget target_;
    render::Renderer renderer_;
};

// Options with every overlay off, uniform level `level`, equal spacing, no culling.
inline render::RenderOptions plainOptions(const Document& doc, float level, double aspect, const char* view = nullptr) {
    render::RenderOptions o = render::optionsFromDocument(doc);
    o.display.showGrid = o.display.showWireframe = o.display.showNormals = o.display.showBoundaries = false;
    o.display.shading = ShadingMode::Lit;
    o.tess.outer = {level, level, level, level};
    o.tess.inner = {level, level};
    o.tess.spacing = Spacing::Equal;
    o.tess.adaptive = AdaptiveMode::None;
    o.tess.cullBackfaces = false;
    o.tess.cullOffscreen = true;
    Camera cam = doc.camera;
    if (view) cam = *applyNamedView(cam, view);
    o.camera = frameBounds(cam, computeBounds(doc.points), aspect);
    return o;
}

// One flat Bézier patch over [0,3]x[0,3] in z = 0 with normal +z.
inline Document flatPatch() {
    Document doc;
    doc.name = "flat";
    Patch p;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            doc.points.push_back(Vec3(j, i, 0.0));
            p.idx[size_t(i * 4 + j)] = uint32_t(i * 4 + j);
        }
    doc.patches.push_back(p);
    return doc;
}

inline bool sameColor(const uint8_t* a, const std::array<float, 3>& c, int tol = 2) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(int(a[k]) - int(std::lround(c[size_t(k)] * 255.0f))) > tol) return false;
    return true;
}

// Pixels whose colour differs by more than `tol` in any channel.
inline size_t countDifferent(const Image& a, const Image& b, int tol = 0) {
    size_t n = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4)
        for (int k = 0; k < 3; ++k)
            if (std::abs(int(a.rgba[i + size_t(k)]) - int(b.rgba[i + size_t(k)])) > tol) {
                ++n;
                break;
            }
    return n;
}

// True when a pixel within `radius` of px has a curvature comb's colour (the teeth (242, 128, 217)
// or the envelope (255, 204, 242)).
inline bool combColoured(const Image& img, const glm::dvec2& px, int radius = 2) {
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int x = int(std::lround(px.x)) + dx, y = int(std::lround(px.y)) + dy;
            if (x < 0 || y < 0 || x >= int(img.w) || y >= int(img.h)) continue;
            const uint8_t* c = img.at(x, y);
            if (c[0] > 170 && c[2] > 140) return true;
        }
    return false;
}

}  // namespace pw::test

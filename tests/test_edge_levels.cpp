// The shared-edge rule (core/tess/edge_levels.hpp with sharedEdgeLevel of core/gpu/patch_math.h): whatever
// the per-patch and per-triangle overrides, both sides of every shared boundary curve end up with
// the same outer level for any level the settings give.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "core/construct/model_builders.hpp"
#include "core/eval/bezier_triangle.hpp"
#include "core/gpu/patch_math.h"
#include "core/tess/edge_levels.hpp"
#include "core/tess/tess_levels.hpp"

using namespace pw;

namespace {

using Pool = std::array<uint32_t, 4>;

Pool canonical(Pool p) { return edgeReversed(p) ? reversedEdgePool(p) : p; }

// Every (item, edge) on each canonical boundary curve: Bézier windows, then triangles.
std::map<Pool, std::vector<std::pair<size_t, int>>> sides(const Document& doc, const std::vector<PatchInstance>& inst) {
    std::map<Pool, std::vector<std::pair<size_t, int>>> out;
    for (size_t w = 0; w < inst.size(); ++w)
        for (int e = 0; e < 4; ++e) {
            Pool p;
            for (int k = 0; k < 4; ++k) p[size_t(k)] = inst[w].idx[size_t(edgeSlot(Edge(e), k))];
            out[canonical(p)].push_back({w, e});
        }
    for (size_t t = 0; t < doc.triangles.size(); ++t)
        for (int e = 0; e < 3; ++e) out[canonical(triEdgePool(doc.triangles[t].idx, e))].push_back({inst.size() + t, e});
    return out;
}

float finalLevel(const WindowLevels& l, int e, float computed) {
    return gpu::sharedEdgeLevel(computed, l.outer[size_t(e)], (l.fixedMask >> e) & 1u);
}

// Checks both sides of every shared curve agree for a range of settings' levels; returns how many
// curves are shared.
size_t expectSharedEdgesAgree(const Document& doc) {
    const std::vector<PatchInstance> inst = expandPatches(doc);
    const std::vector<WindowLevels> levels = resolveEdgeLevels(doc, inst);
    EXPECT_EQ(levels.size(), inst.size() + doc.triangles.size());
    size_t shared = 0;
    for (const auto& [pool, on] : sides(doc, inst)) {
        if (on.size() < 2) continue;
        ++shared;
        for (float computed : {1.0f, 2.0f, 3.7f, 16.0f, 64.0f})
            for (const auto& [item, e] : on)
                EXPECT_EQ(finalLevel(levels[item], e, computed), finalLevel(levels[on[0].first], on[0].second, computed))
                    << "item " << item << " edge " << e << " computed " << computed;
    }
    return shared;
}

}  // namespace

TEST(EdgeLevels, BothSidesOverriddenTakeTheLargerLevel) {
    Document doc = makePatchGrid(1, 2);
    doc.patches[0].tessOverride = std::array<float, 6>{2, 2, 2, 2, 3, 4};
    doc.patches[1].tessOverride = std::array<float, 6>{16, 16, 16, 16, 16, 16};
    const std::vector<WindowLevels> l = resolveEdgeLevels(doc, expandPatches(doc));
    ASSERT_EQ(l.size(), 2u);
    // Patch 0's u1 edge is patch 1's u0 edge.
    EXPECT_EQ(l[0].outer[2], 16.0f);
    EXPECT_EQ(l[1].outer[0], 16.0f);
    EXPECT_EQ(l[0].fixedMask, 0xFu);  // every window on every edge has its own levels
    EXPECT_EQ(l[1].fixedMask, 0xFu);
    EXPECT_EQ(l[0].outer[0], 2.0f);  // its own, unshared edges keep their levels
    EXPECT_EQ(l[0].outer[1], 2.0f);
    ASSERT_TRUE(l[0].inner.has_value());
    EXPECT_EQ(*l[0].inner, (std::array<float, 2>{3, 4}));  // inner levels are the window's own
    EXPECT_EQ(expectSharedEdgesAgree(doc), 1u);
}

TEST(EdgeLevels, OneSideOverriddenRaisesTheSettingsLevel) {
    Document doc = makePatchGrid(1, 2);
    doc.patches[0].tessOverride = std::array<float, 6>{16, 16, 16, 16, 16, 16};
    const std::vector<WindowLevels> l = resolveEdgeLevels(doc, expandPatches(doc));
    EXPECT_EQ(l[0].fixedMask, 0b1011u);  // u0, v0, v1 its own; u1 is shared with a window without
    EXPECT_EQ(l[0].outer[2], 16.0f);
    EXPECT_EQ(l[1].fixedMask, 0u);
    EXPECT_EQ(l[1].outer[0], 16.0f);
    EXPECT_EQ(l[1].outer[2], 0.0f);  // its other edges: the settings' level as is
    EXPECT_FALSE(l[1].inner.has_value());
    // On the shared edge: the settings' level when larger, else the override.
    EXPECT_EQ(finalLevel(l[0], 2, 32.0f), 32.0f);
    EXPECT_EQ(finalLevel(l[1], 0, 4.0f), 16.0f);
    expectSharedEdgesAgree(doc);
    // No overrides anywhere: nothing stored, nothing fixed.
    const Document plain = makePatchGrid(2, 2);
    for (const WindowLevels& w : resolveEdgeLevels(plain, expandPatches(plain))) EXPECT_EQ(w, WindowLevels{});
}

TEST(EdgeLevels, RandomOverridesOnGridsAndTrianglesAlwaysAgree) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> level(1.0f, 64.0f);
    for (int round = 0; round < 20; ++round) {
        Document doc = round % 2 ? makePatchGrid(4, 5) : makeTriangleDome();
        for (Patch& p : doc.patches)
            if (rng() % 2) p.tessOverride = std::array<float, 6>{level(rng), level(rng), level(rng), level(rng), level(rng), level(rng)};
        for (TrianglePatch& t : doc.triangles)
            if (rng() % 2) t.tessOverride = std::array<float, 4>{level(rng), level(rng), level(rng), level(rng)};
        EXPECT_GT(expectSharedEdgesAgree(doc), 0u);
    }
}

// What a frame asks of the tessellator (the editor's heavy-document rule): single patches, net
// windows and triangles at the largest level any can get; past 2 M evaluation vertices a CPU
// renderer is not interactive.
TEST(FrameLoad, CountsEveryPatchAtItsLargestLevel) {
    Document doc = makePatchGrid(4, 4);
    TessSettings t;
    t.outer = {9, 9, 9, 9};
    t.inner = {9, 9};
    FrameLoad l = frameLoad(doc, t);
    EXPECT_EQ(l.patches, 16u);
    EXPECT_EQ(l.segments, 9);
    EXPECT_EQ(l.evaluations, 16u * 100u);
    doc.patches[3].tessOverride = std::array<float, 6>{2, 2, 2, 2, 30, 2};
    EXPECT_EQ(frameLoad(doc, t).segments, 30);
    Surface net;
    net.rows = net.cols = 99;  // B-spline: 96 x 96 windows
    net.basis = Basis::BSpline;
    net.idx.assign(size_t(99) * 99, 0u);
    doc.surfaces.push_back(net);
    l = frameLoad(doc, t);
    EXPECT_EQ(l.patches, 16u + 96u * 96u);
    EXPECT_TRUE(heavyForCpu(l));  // 9 232 patches at 30 (the override): 8.9 M vertices
    doc.patches[3].tessOverride.reset();
    EXPECT_FALSE(heavyForCpu(frameLoad(doc, t)));  // at 9: 0.92 M vertices
    t.outer = {16, 16, 16, 16};
    t.inner = {16, 16};
    EXPECT_TRUE(heavyForCpu(frameLoad(doc, t)));  // at 16: 2.7 M
    EXPECT_FALSE(heavyForCpu(frameLoad(makePatchGrid(4, 4), t)));
    t.adaptive = AdaptiveMode::ScreenSpace;
    t.maxLevel = 64;
    EXPECT_EQ(frameLoad(makePatchGrid(4, 4), t).segments, 64);  // adaptive: bounded by the max level
}

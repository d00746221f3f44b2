// The surface renderer: owns the pipelines, the document's GPU buffers, the frame uniforms, the
// queries and a command buffer; renders one frame into a RenderTarget (submit and wait) and
// returns its statistics.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "core/mesh/mesh_tessellate.hpp"
#include "core/model/document.hpp"
#include "core/model/height_map.hpp"
#include "render/scene/pipelines.hpp"
#include "render/targets/render_target.hpp"
#include "render/vk/device.hpp"
#include "render/vk/stats.hpp"

namespace pw::render {
inline namespace scene {

// Whether windows of a net at one level are drawn several to a patch (render/scene/merged_blocks.hpp):
// by default on CPU renderers, where every patch costs the same whatever its level.
enum class MergeWindows { Auto, Never, Always };

struct RenderOptions {
    TessSettings tess;
    DisplaySettings display;  // shading, overlays (showGrid, showWireframe, showNormals, showBoundaries)
    Camera camera;
    int hoveredPoint = -1;
    int selectedPoint = -1;
    bool plainMesh = false;  // draw the uploaded CPU mesh instead of tessellating
    // Comparison panes: draw into this rectangle of the target (x, y, width, height in pixels; a
    // zero width or height means the whole target). The camera takes the rectangle's aspect, and
    // screen-space levels its pixels.
    std::array<int, 4> pane{0, 0, 0, 0};
    // Keep what the target holds (earlier panes of this frame) and clear only the pane's rectangle;
    // otherwise the whole target is cleared to the background first.
    bool keepTarget = false;
    // The editor's ground grid (translucent lines in the ground plane, hidden behind the surface):
    // drawn when > 0, with lines this far apart (render/scene/overlays.hpp).
    double groundGridStep = 0.0;
    // The document's displacement scale and bias (live while a slider is dragged; the map, the
    // mapping and the windows' own values come with setDocument).
    float displacementScale = 0.0f, displacementBias = 0.0f;
    // With display.showCombs: the join whose curvature graph is drawn (combs on the isocurves that
    // cross it, both sides), -1 none.
    int combJoin = -1;
    // The wireframe overlay's colour: near-black on the dark theme; `--theme light` (slides) uses
    // a mid grey, so a dense wire shades the surface instead of blacking it out.
    std::array<float, 4> wireColor{0.08f, 0.09f, 0.12f, 1.0f};
    // A debug camera: when set, adaptive levels and culling are decided from this camera while the
    // picture is drawn from `camera`; the patches it culls are drawn greyed in place and its view
    // frustum is drawn (out to `lodFrustumDepth`, or the far distance, or past the model).
    std::optional<Camera> lodCamera;
    double lodFrustumDepth = 0.0;
    MergeWindows mergeWindows = MergeWindows::Auto;
    // The benchmark's floor: the windows at the uniform levels through trivial shaders (a bilinear
    // position of the corners, lit flat), no Bézier triangles, no merging.
    bool rawTessellator = false;
};

// The pane rectangle `opt` draws into, clamped to a target of `extent` (the whole target when
// the options give none, or one that lies outside it).
VkRect2D paneRect(const RenderOptions& opt, VkExtent2D extent);

RenderOptions optionsFromDocument(const Document& doc);

// What the GPU's tessellator made for the surface (Bézier windows, net windows, Bézier triangles),
// read back through transform feedback and welded (core/mesh/mesh_weld.hpp): Renderer::captureSurface.
struct CapturedSurface {
    TriangleMesh mesh;
    uint64_t gpuTriangles = 0;   // triangles the tessellator emitted
    size_t degenerate = 0;       // of them, collapsed at poles and left out of the mesh
    uint32_t patchesCulled = 0;  // patches the control shader culled (culling on: facing away, off screen)
    bool culledCounted = false;  // the device counted them (stores and atomics in the control shader)
    int64_t culledPatches() const { return culledCounted ? int64_t(patchesCulled) : -1; }  // ExportOptions::culledPatches
};

class Renderer {
public:
    Renderer(Device& dev, RenderTarget& target);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // `map`: the document's height map (DESIGN §11), or none; the surface is displaced when the
    // document's displacement is active and a map is given.
    void setDocument(const Document& doc, std::shared_ptr<const HeightMap> map = {});
    void setPlainMesh(const TriangleMesh& mesh);
    // Editor drags: rewrites only the pool entries `changed` of the uploaded document in place (the
    // pool buffer is host-visible and the previous frame has completed). The topology must be the
    // one given to setDocument; boundary overlays refresh at the next setDocument.
    void updatePoints(const std::vector<Vec3>& points, const std::vector<uint32_t>& changed);
    // Per-patch level edits: rewrites only the per-window levels (the patch-data buffer, in place where
    // the host sees it, as on lavapipe) for `doc`, which must have the uploaded document's items and
    // points; anything else is a setDocument.
    void updateLevels(const Document& doc);
    FrameStats render(const RenderOptions& opt);
    // The surface `render(opt)` would draw, triangle for triangle, as a welded mesh in document
    // coordinates (render/scene/surface_capture.cpp). InputError (exit 2) when the device has no
    // transform feedback (VK_EXT_transform_feedback).
    CapturedSurface captureSurface(const RenderOptions& opt);
    // Draws a one-patch scene with every pipeline variant so the first real frame does not pay for
    // shader JIT. That scene is the renderer's document afterwards: set the real one after this.
    void warmUp();

    const PipelineSet& pipelines() const { return pipes_; }
    double modelSize() const { return modelSize_; }

private:
    friend class FramePasses;  // render/scene/frame_passes: what a frame records, pass by pass
    struct Impl;
    struct FramePlan;
    // Writes the frame uniforms for `opt` drawn into `area` and plans the draws.
    FramePlan prepareFrame(const RenderOptions& opt, VkRect2D area);
    bool mergingWanted(const RenderOptions& opt) const;  // the frame may merge windows (render/scene/merged_blocks.hpp)
    // One piece of captureSurface's transform feedback (render/scene/surface_capture.cpp).
    void recordCapturePiece(VkCommandBuffer cmd, uint32_t k, uint32_t pieces, const std::vector<uint8_t>* skip, VkBuffer out,
                            VkDeviceSize capacity, VkBuffer counter, VkQueryPool query, VkPipeline windowsPipe, VkPipeline trianglesPipe,
                            const FramePlan& plan, const VkRect2D& area);
    Device& dev_;
    RenderTarget& target_;
    PipelineSet pipes_;
    std::unique_ptr<Impl> impl_;
    double modelSize_ = 1.0;
};

}  // namespace scene
}  // namespace pw::render

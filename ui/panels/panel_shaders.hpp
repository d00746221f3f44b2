// The Shaders window: the GLSL of the tessellation pipelines the current settings draw with
// (surface, triangles, wireframe, normal vectors, domain panes), stage by stage, read-only, with
// the glslc defines of each variant and the lines those defines switch off dimmed
// (render/shader_listing), Copy; or the short teaching listing of the marked parts.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "render/domain/domain_view.hpp"
#include "render/scene/shader_listing.hpp"
#include "ui/panels/panel_context.hpp"

namespace pw::ui {
inline namespace panels {

class ShaderPanel {
public:
    // `geometryShader`: the device has them (the normal vectors' pipeline differs without).
    void draw(PanelContext& ctx, bool geometryShader, const TessSettings& shownTess,
              const std::vector<render::DomainViewOptions>& domainPanes);

    bool open = false;
    std::string shown;  // the variant on screen this frame ("" = closed)
    std::vector<std::string> variantsInUse;
    bool teaching = false;  // the short listing a slide shows (render::teachingListing) where the variant has one
    size_t shownLines = 0;  // lines listed this frame (the test trace)

private:
    bool hideInactive_ = false;
    std::string pipeline_;                                                // the pipeline picked (by name: the list changes)
    std::map<std::string, render::ShaderListing, std::less<>> listings_;  // cache by variant
};

}  // namespace panels
}  // namespace pw::ui

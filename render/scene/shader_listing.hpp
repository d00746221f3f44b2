// The GLSL behind what is on screen, for the shader panel and `patchwork shaders`: which pipelines
// the current settings use, the compiled variant of each of their stages, and that variant's source
// as glslc saw it (includes inlined, lines in #ifdef branches the variant's defines switch off
// marked inactive). Names come from the same variant choice the renderer binds by
// (shader_variants.hpp), and the text from the files the build compiled (shaders/CMakeLists.txt).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/document.hpp"
#include "core/tess/tess_domain.hpp"

namespace pw::render {
inline namespace scene {

struct StageUse {
    std::string stage;    // "vertex", "tessellation control", "tessellation evaluation", "geometry", "fragment"
    std::string variant;  // compiled variant name (shaders/CMakeLists.txt), e.g. "surface_tese_odd"
};

struct PipelineUse {
    std::string name;  // "Surface (Bézier quads)", "Wireframe", "Domain view: quad, fractional_odd", ...
    std::string why;   // one line: which settings chose these variants
    std::vector<StageUse> stages;
};

struct ShaderContext {
    TessSettings tess;
    DisplaySettings display;
    bool windows = true;         // the document has quad windows (Bézier, B-spline, Catmull-Rom)
    bool triangles = false;      // the document has Bézier triangles
    bool curves = false;         // the document has Bézier curves
    bool geometryShader = true;  // the device draws the normal-vector overlay
    // Domain-view panes (kind and partitioning each), empty when the domain view is closed.
    std::vector<std::pair<DomainKind, Spacing>> domainPanes;
};

// The tessellation pipelines drawn with these settings, in drawing order.
std::vector<PipelineUse> pipelinesInUse(const ShaderContext& c);

struct ListingLine {
    std::string text;
    std::string file;    // the file this line comes from (an include's name inside it)
    int line = 0;        // 1-based line number in that file
    int depth = 0;       // include depth (0: the stage's own file)
    bool active = true;  // false inside an #ifdef/#ifndef/#else branch the defines switch off
};

struct ShaderListing {
    std::string variant, source;
    std::vector<std::string> defines;  // as given to glslc: "-DSPACING=fractional_odd_spacing", ...
    std::vector<ListingLine> lines;
};

// The listing of one compiled variant; nullopt for a name the build does not have.
std::optional<ShaderListing> shaderListing(std::string_view variant);

// The short listing a slide shows (~20 lines): only the parts of the variant's source marked for
// teaching, its active lines, each part headed by a comment naming it and where it is, the
// variant's object-like defines substituted (SPACING -> fractional_odd_spacing). Marks in the
// shader files: `// @teach{ title` ... `// @teach}` around lines, or `code  // @teach= [title]` on
// one (a title starts a new part). Empty for a variant without marks.
std::vector<ListingLine> teachingListing(const ShaderListing& l);

// Every compiled variant's name (for checks and the command line).
std::vector<std::string> shaderVariantNames();

}  // namespace scene
}  // namespace pw::render

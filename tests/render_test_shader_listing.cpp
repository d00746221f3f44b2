// The shader panel's listing (render/shader_listing) and `patchwork shaders`: every variant the
// settings can select exists in the build and lists the very text glslc compiled, includes inlined,
// with the lines its defines switch off marked; the stages follow spacing, adaptivity, shading,
// overlays, triangles and domain panes. No device needed.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "render/scene/shader_listing.hpp"
#include "support.hpp"

namespace pw::test {
namespace {

using render::ListingLine;
using render::PipelineUse;
using render::ShaderContext;

std::string readText(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const ListingLine* findLine(const render::ShaderListing& l, const std::string& text) {
    for (const auto& line : l.lines)
        if (line.text == text) return &line;
    return nullptr;
}

std::string variantOf(const std::vector<PipelineUse>& pipes, const std::string& pipeline, const std::string& stage) {
    for (const auto& p : pipes)
        if (p.name.starts_with(pipeline))
            for (const auto& s : p.stages)
                if (s.stage == stage) return s.variant;
    return "";
}

TEST(ShaderListing, EveryVariantListsTheFileGlslcCompiled) {
    const auto names = render::shaderVariantNames();
    ASSERT_GE(names.size(), 40u);
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        const auto l = render::shaderListing(name);
        ASSERT_TRUE(l);
        // The stage's own lines (depth 0) are the file on disk, byte for byte.
        std::string own;
        for (const auto& line : l->lines)
            if (line.depth == 0) own += line.text + "\n";
        EXPECT_EQ(own, readText(testsDir() / ".." / "shaders" / l->source));
        // Every #include "file" is followed by the included file's first line, one level deeper
        // (the shared headers' C++ branch includes <system> headers, shown but not expanded).
        for (size_t i = 0; i < l->lines.size(); ++i)
            if (l->lines[i].text.starts_with("#include \"")) {
                ASSERT_LT(i + 1, l->lines.size());
                EXPECT_EQ(l->lines[i + 1].depth, l->lines[i].depth + 1);
                EXPECT_EQ(l->lines[i + 1].line, 1);
            }
    }
    EXPECT_FALSE(render::shaderListing("no_such_variant"));
}

TEST(ShaderListing, DefinesSwitchBranchesOnAndOff) {
    const auto surface = render::shaderListing("surface_tese_odd");
    const auto points = render::shaderListing("points_tese_odd");
    ASSERT_TRUE(surface && points);
    EXPECT_EQ(surface->defines, std::vector<std::string>{"-DSPACING=fractional_odd_spacing"});
    // A family's own defines come first, then its axes' (shaders/CMakeLists.txt).
    EXPECT_EQ(points->defines, (std::vector<std::string>{"-DPOINT_MODE", "-DSPACING=fractional_odd_spacing"}));
    const std::string tri = "layout(quads, SPACING, ccw) in;", pts = "layout(quads, SPACING, ccw, point_mode) in;";
    ASSERT_TRUE(findLine(*surface, tri) && findLine(*surface, pts));
    EXPECT_TRUE(findLine(*surface, tri)->active);
    EXPECT_FALSE(findLine(*surface, pts)->active);
    EXPECT_FALSE(findLine(*points, tri)->active);
    EXPECT_TRUE(findLine(*points, pts)->active);

    // Inside an include: tess_levels.glsl's adaptive block is off in the fixed control shader and on
    // in the full one; the #ifdef lines themselves belong to the enclosing (active) region.
    const auto fixed = render::shaderListing("surface_tesc_fixed"), full = render::shaderListing("surface_tesc_full");
    ASSERT_TRUE(fixed && full);
    size_t fixedOff = 0, fullOff = 0, fixedIncludedOff = 0;
    for (const auto& line : fixed->lines) {
        fixedOff += !line.active;
        fixedIncludedOff += !line.active && line.file == "tess_levels.glsl";
        // (A shared header included a second time is all off behind its guard, its #ifdef lines too.)
        if ((line.text.starts_with("#ifdef") || line.text.starts_with("#endif")) && line.file.find('/') == std::string::npos) {
            EXPECT_TRUE(line.active) << line.file << ": " << line.text;
        }
    }
    // Every line of the shaders' own files is on in the full variant; the shared headers
    // (core/gpu/patch_math.h, ...) have a C++ branch that is off.
    size_t sharedOff = 0;
    for (const auto& line : full->lines) {
        const bool shared = line.file.find('/') != std::string::npos;
        fullOff += !line.active && !shared;
        sharedOff += !line.active && shared;
    }
    EXPECT_GT(sharedOff, 10u);
    EXPECT_GE(fixedIncludedOff, 4u);  // the adaptive-level wrapper
    EXPECT_GT(fixedOff, fixedIncludedOff);
    EXPECT_EQ(fullOff, 0u);
}

TEST(ShaderListing, StagesFollowTheSettings) {
    ShaderContext c;
    c.tess.cullOffscreen = false;
    auto pipes = render::pipelinesInUse(c);
    ASSERT_EQ(pipes.size(), 1u);
    EXPECT_EQ(variantOf(pipes, "Surface", "tessellation control"), "surface_tesc_fixed");
    EXPECT_EQ(variantOf(pipes, "Surface", "tessellation evaluation"), "surface_tese_equal");
    EXPECT_EQ(variantOf(pipes, "Surface", "fragment"), "surface_frag");

    c.tess.spacing = Spacing::Pow2;  // pow2 is equal spacing with levels rounded in the control shader
    c.tess.adaptive = AdaptiveMode::ScreenSpace;
    c.display.shading = ShadingMode::MeanCurvature;
    pipes = render::pipelinesInUse(c);
    EXPECT_EQ(variantOf(pipes, "Surface", "tessellation control"), "surface_tesc_full");
    EXPECT_EQ(variantOf(pipes, "Surface", "tessellation evaluation"), "surface_tese_equal_full");
    EXPECT_EQ(variantOf(pipes, "Surface", "fragment"), "surface_frag_full");
    EXPECT_NE(pipes[0].why.find("pow2"), std::string::npos);
    EXPECT_NE(pipes[0].why.find("adaptive screen"), std::string::npos);

    c.tess.spacing = Spacing::FractionalEven;
    c.display.showWireframe = c.display.showNormals = true;
    c.triangles = true;
    pipes = render::pipelinesInUse(c);
    EXPECT_EQ(variantOf(pipes, "Surface (Bézier triangles", "tessellation evaluation"), "tri_surface_tese_even_full");
    EXPECT_EQ(variantOf(pipes, "Wireframe (quad", "tessellation evaluation"), "surface_tese_even");  // lean
    EXPECT_EQ(variantOf(pipes, "Wireframe (Bézier", "tessellation evaluation"), "tri_surface_tese_even");
    EXPECT_EQ(variantOf(pipes, "Normal vectors", "tessellation evaluation"), "points_tese_even");
    EXPECT_EQ(variantOf(pipes, "Normal vectors", "geometry"), "normals_geom");
    c.geometryShader = false;
    EXPECT_EQ(variantOf(render::pipelinesInUse(c), "Normal vectors", "geometry"), "");

    c.curves = c.display.showIsocurves = true;
    pipes = render::pipelinesInUse(c);
    EXPECT_EQ(variantOf(pipes, "Isocurves", "tessellation control"), "isocurve_tesc");
    EXPECT_EQ(variantOf(pipes, "Isocurves", "tessellation evaluation"), "isocurve_tese_even");
    EXPECT_EQ(variantOf(pipes, "Bézier curves", "tessellation evaluation"), "curve_tese_even");

    c.domainPanes = {{DomainKind::Triangle, Spacing::FractionalOdd}, {DomainKind::Isoline, Spacing::Pow2}};
    pipes = render::pipelinesInUse(c);
    EXPECT_EQ(variantOf(pipes, "Domain view: tri, fractional_odd", "tessellation evaluation"), "domain_tese_tri_odd");
    EXPECT_EQ(variantOf(pipes, "Domain view: isoline, pow2", "tessellation evaluation"), "domain_tese_iso_equal");
}

TEST(ShaderListing, EverySelectableVariantIsBuilt) {
    const auto names = render::shaderVariantNames();
    const std::set<std::string> built(names.begin(), names.end());
    size_t checked = 0;
    for (Spacing sp : {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2})
        for (AdaptiveMode ad : {AdaptiveMode::None, AdaptiveMode::Distance, AdaptiveMode::ScreenSpace, AdaptiveMode::Orientation})
            for (int sh = 0; sh <= int(ShadingMode::MeanCurvature); ++sh)
                for (int flags = 0; flags < 8; ++flags)
                    for (DomainKind dk : {DomainKind::Quad, DomainKind::Triangle, DomainKind::Isoline}) {
                        ShaderContext c;
                        c.tess.spacing = sp;
                        c.tess.adaptive = ad;
                        c.tess.cullOffscreen = flags & 1;
                        c.display.shading = ShadingMode(sh);
                        c.display.showWireframe = c.display.showNormals = c.display.showIsocurves = flags & 2;
                        c.triangles = c.curves = flags & 4;
                        c.domainPanes = {{dk, sp}};
                        for (const auto& p : render::pipelinesInUse(c))
                            for (const auto& s : p.stages) {
                                EXPECT_TRUE(built.contains(s.variant)) << s.variant << " in " << p.name;
                                ++checked;
                            }
                    }
    EXPECT_GT(checked, 10000u);
}

TEST(ShaderListing, CommandPrintsTheStagesInUse) {
    const std::string bin = patchworkBinary().string();
    RunResult r = runCommand(bin + " shaders --stage tese --spacing fractional_even --active-only");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("surface_tese_even: surface.tese, glslc --target-env=vulkan1.3 -O -DSPACING=fractional_even_spacing"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("layout(quads, SPACING, ccw) in;"), std::string::npos);
    EXPECT_EQ(r.output.find("point_mode"), std::string::npos);  // switched off, left out
    EXPECT_EQ(r.output.find("-- vertex"), std::string::npos);

    r = runCommand(bin + " shaders --list --domain isoline --outer 3,5 --spacing fractional_odd");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Domain view: isoline, fractional_odd"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("-- tessellation evaluation: domain_tese_iso_odd\n"), std::string::npos);
    EXPECT_EQ(r.output.find("Surface"), std::string::npos);

    r = runCommand(bin + " shaders --variant nope");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("--variant"), std::string::npos) << r.output;
    r = runCommand(bin + " shaders --stage tessellate");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("--stage"), std::string::npos) << r.output;
}

}  // namespace

// The teaching listing (`shaders --teaching`, the panel's "Teaching listing"): only the marked parts
// of the real source, a slide's length, each part headed by where it comes from, the defines and
// the GLSL side of core/gpu/glsl_cpp.h substituted, no preprocessor lines and no marks left.
TEST(ShaderListing, TeachingListingIsTheMarkedPartsOfTheVariant) {
    const auto l = render::shaderListing("surface_tese_odd");
    ASSERT_TRUE(l.has_value());
    const auto t = render::teachingListing(*l);
    ASSERT_GE(t.size(), 15u);
    EXPECT_LE(t.size(), 40u);
    std::set<std::string> texts;
    size_t headers = 0;
    for (const auto& line : t) {
        texts.insert(line.text);
        EXPECT_EQ(line.text.find("@teach"), std::string::npos) << line.text;
        EXPECT_FALSE(line.text.starts_with("#")) << line.text;
        if (line.line == 0 && !line.text.empty()) {
            ++headers;
            EXPECT_TRUE(line.text.starts_with("// ")) << line.text;
            EXPECT_NE(line.text.find(line.file + ":"), std::string::npos) << line.text;
        } else if (line.line > 0) {  // a real line of that file, inside the listing
            EXPECT_TRUE(std::any_of(l->lines.begin(), l->lines.end(),
                                    [&](const ListingLine& f) { return f.file == line.file && f.line == line.line && f.active; }))
                << line.file << ":" << line.line;
        }
    }
    EXPECT_GE(headers, 4u);
    EXPECT_TRUE(texts.count("layout(quads, fractional_odd_spacing, ccw) in;"));
    EXPECT_TRUE(texts.count("vec4 bernstein3(float t, float s) {"));
    EXPECT_TRUE(texts.count("    float u = gl_TessCoord.x, v = gl_TessCoord.y;"));
    // A variant without marked parts has no teaching listing (the panel shows it whole).
    const auto vert = render::shaderListing("surface_vert");
    ASSERT_TRUE(vert.has_value());
    EXPECT_TRUE(render::teachingListing(*vert).empty());
}

}  // namespace pw::test

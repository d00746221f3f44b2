#include "render/scene/shader_listing.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>

#include "render/scene/shader_variants.hpp"
#include "shaders/glsl_sources.hpp"
#include "shaders/spirv.hpp"

namespace pw::render {
inline namespace scene {
namespace {

// Which settings chose the spacing and control-shader variants.
std::string describe(const TessSettings& t) {
    std::string why = "partitioning " + std::string(spacingName(t.spacing));
    if (t.spacing == Spacing::Pow2) why += " (equal spacing, levels rounded up to powers of two in the control shader)";
    if (levelsVariant(t) == LevelsVariant::Full) {
        why += "; control shader with adaptive levels and culling (";
        std::vector<std::string> on;
        if (t.adaptive != AdaptiveMode::None) on.push_back("adaptive " + std::string(adaptiveName(t.adaptive)));
        if (t.cullBackfaces) on.push_back("back-face culling");
        if (t.cullOffscreen) on.push_back("off-screen culling");
        if (t.cullFar && t.adaptive == AdaptiveMode::Distance) on.push_back("culling beyond the far distance");
        for (size_t i = 0; i < on.size(); ++i) why += (i ? ", " : "") + on[i];
        why += ")";
        if (on.size() == 1 && t.cullOffscreen)  // render/scene/renderer.cpp prepareFrame
            why +=
                "; frames whose whole model is in view use the fixed-level control shader instead (nothing to cull), and "
                "otherwise windows wholly in view do, windows wholly out of it are culled on the CPU";
    } else {
        why += "; control shader with fixed levels (uniform levels and per-patch overrides)";
    }
    return why;
}

struct Preprocessor {
    std::set<std::string, std::less<>> defined;
    std::vector<ListingLine>& out;

    static std::string_view trimLeft(std::string_view s) {
        while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
        return s;
    }
    static std::string_view word(std::string_view s) {  // first identifier of s
        s = trimLeft(s);
        size_t n = 0;
        while (n < s.size() && (std::isalnum(static_cast<unsigned char>(s[n])) || s[n] == '_')) ++n;
        return s.substr(0, n);
    }
    static const glsl::File* find(std::string_view name) {
        for (const auto& f : glsl::files())
            if (f.name == name) return &f;
        return nullptr;
    }

    // Appends `file`'s lines; includes are expanded in place, one level deeper.
    void expand(const glsl::File& file, int depth, bool outerActive) {
        struct Branch {
            bool parentActive, taken;
        };
        std::vector<Branch> stack;
        std::string_view text = file.text;
        int lineNo = 0;
        while (!text.empty()) {
            const size_t nl = text.find('\n');
            std::string_view line = text.substr(0, nl);
            text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
            ++lineNo;
            const bool active = stack.empty() ? outerActive : stack.back().parentActive && stack.back().taken;
            const std::string_view t = trimLeft(line);
            bool lineActive = active;
            if (t.starts_with("#ifdef") || t.starts_with("#ifndef")) {
                const bool isDef = t.starts_with("#ifdef");
                const bool has = defined.contains(word(t.substr(isDef ? 6 : 7)));
                stack.push_back({active, isDef ? has : !has});
            } else if (t.starts_with("#else") && !stack.empty()) {
                stack.back().taken = !stack.back().taken;
                lineActive = stack.back().parentActive;
            } else if (t.starts_with("#endif") && !stack.empty()) {
                lineActive = stack.back().parentActive;
                stack.pop_back();
            } else if (t.starts_with("#define") && active) {
                defined.emplace(word(t.substr(7)));
            }
            out.push_back({std::string(line), std::string(file.name), lineNo, depth, lineActive});
            if (t.starts_with("#include") && depth < 8) {
                const size_t q0 = t.find('"'), q1 = q0 == std::string_view::npos ? q0 : t.find('"', q0 + 1);
                if (q1 != std::string_view::npos)
                    if (const glsl::File* inc = find(t.substr(q0 + 1, q1 - q0 - 1))) expand(*inc, depth + 1, active);
            }
        }
    }
};

}  // namespace

std::vector<PipelineUse> pipelinesInUse(const ShaderContext& c) {
    // Stage names from the generated variant index (shaders/CMakeLists.txt), as the renderer picks them.
    const size_t sp = size_t(spacingVariant(c.tess.spacing)), lv = size_t(levelsVariant(c.tess));
    const size_t varyings = size_t(varyingsVariant(c.display.shading));
    auto stage = [](const spirv::Blob& b) { return std::string(b.name); };
    const std::string why = describe(c.tess);
    const std::string shading = std::string(shadingName(c.display.shading)) + " shading";
    std::vector<PipelineUse> out;
    const bool tri = true, quad = false;
    auto surface = [&](const std::string& title, bool triangles, size_t v) {
        const std::string vary = v == size_t(VaryingsVariant::Lean)
                                     ? "; lean varyings (position and normal: " + (title.starts_with("Wire") ? "wireframe" : shading) + ")"
                                     : "; full varyings (UV, patch id, curvatures: " + shading + ")";
        out.push_back({title,
                       why + vary,
                       {{"vertex", stage(spirv::surface_vert())},
                        {"tessellation control", stage(triangles ? spirv::tri_surface_tesc(lv) : spirv::surface_tesc(lv))},
                        {"tessellation evaluation", stage(triangles ? spirv::tri_surface_tese(sp, v, 0) : spirv::surface_tese(sp, v, 0))},
                        {"fragment", stage(spirv::surface_frag(v))}}});
    };
    const size_t lean = size_t(VaryingsVariant::Lean);
    if (c.windows) surface("Surface (quad windows, 16 points)", quad, varyings);
    if (c.triangles) surface("Surface (Bézier triangles, 10 points)", tri, varyings);
    if (c.display.showWireframe) {
        if (c.windows) surface("Wireframe (quad windows)", quad, lean);
        if (c.triangles) surface("Wireframe (Bézier triangles)", tri, lean);
    }
    auto normals = [&](const std::string& title, bool triangles) {
        out.push_back({title,
                       why,
                       {{"vertex", stage(spirv::surface_vert())},
                        {"tessellation control", stage(triangles ? spirv::tri_surface_tesc(lv) : spirv::surface_tesc(lv))},
                        {"tessellation evaluation", stage(triangles ? spirv::tri_points_tese(sp, 0) : spirv::points_tese(sp, 0))},
                        {"geometry", stage(spirv::normals_geom())},
                        {"fragment", stage(spirv::line_frag())}}});
    };
    if (c.display.showNormals && c.windows && c.geometryShader) normals("Normal vectors (point mode)", quad);
    if (c.display.showNormals && c.triangles && c.geometryShader) normals("Normal vectors (Bézier triangles, point mode)", tri);
    char levels[96];
    std::snprintf(levels, sizeof levels, "isoline domain: outer level 0 = lines (%g), outer level 1 = segments (%g)",
                  double(c.tess.isolineLevels[0]), double(c.tess.isolineLevels[1]));
    const std::string isoWhy = levels + std::string(" under partitioning ") + std::string(spacingName(c.tess.spacing));
    if (c.display.showIsocurves && c.windows)
        out.push_back({"Isocurves (isoline domain, 16 points)",
                       isoWhy,
                       {{"vertex", stage(spirv::surface_vert())},
                        {"tessellation control", stage(spirv::isocurve_tesc())},
                        {"tessellation evaluation", stage(spirv::isocurve_tese(sp))},
                        {"fragment", stage(spirv::line_frag())}}});
    if (c.curves)
        out.push_back({"Bézier curves (isoline domain, 4 points)",
                       isoWhy + "; one line per curve",
                       {{"vertex", stage(spirv::surface_vert())},
                        {"tessellation control", stage(spirv::curve_tesc())},
                        {"tessellation evaluation", stage(spirv::curve_tese(sp))},
                        {"fragment", stage(spirv::line_frag())}}});
    for (size_t i = 0; i < c.domainPanes.size(); ++i) {
        const auto [kind, spacing] = c.domainPanes[i];
        const size_t dk = size_t(kind), ds = size_t(spacingVariant(spacing));
        std::string name = "Domain view: " + std::string(domainName(kind)) + ", " + std::string(spacingName(spacing));
        if (c.domainPanes.size() > 1) name += " (pane " + std::to_string(i + 1) + ")";
        out.push_back({name,
                       "the evaluation shader outputs gl_TessCoord; partitioning " + std::string(spacingName(spacing)) +
                           (spacing == Spacing::Pow2 ? " (equal spacing, levels rounded up to powers of two)" : ""),
                       {{"vertex", stage(spirv::domain_vert())},
                        {"tessellation control", stage(spirv::domain_tesc())},
                        {"tessellation evaluation", stage(spirv::domain_tese(dk, ds, 0))},
                        {"tessellation evaluation (vertex dots)", stage(spirv::domain_tese(dk, ds, spirv::domain_tese_output_points))},
                        {"fragment", stage(spirv::line_frag())}}});
    }
    return out;
}

std::optional<ShaderListing> shaderListing(std::string_view variant) {
    for (const auto& v : glsl::variants()) {
        if (v.name != variant) continue;
        const glsl::File* file = Preprocessor::find(v.source);
        if (!file) return std::nullopt;
        ShaderListing l;
        l.variant = std::string(v.name);
        l.source = std::string(v.source);
        Preprocessor pp{{}, l.lines};
        std::string_view defs = v.defines;
        while (!defs.empty()) {
            const size_t sp = defs.find(' ');
            const std::string_view d = defs.substr(0, sp);
            defs = sp == std::string_view::npos ? std::string_view{} : defs.substr(sp + 1);
            if (d.empty()) continue;
            l.defines.emplace_back(d);
            if (d.starts_with("-D")) pp.defined.emplace(Preprocessor::word(d.substr(2)));
        }
        pp.expand(*file, 0, true);
        return l;
    }
    return std::nullopt;
}

std::vector<std::string> shaderVariantNames() {
    std::vector<std::string> names;
    for (const auto& v : glsl::variants()) names.emplace_back(v.name);
    return names;
}

std::vector<ListingLine> teachingListing(const ShaderListing& l) {
    // The defines' values, for the words they name (SPACING=fractional_odd_spacing).
    // And the object-like #defines of the active lines (core/gpu/glsl_cpp.h's GLSL side: PW_REAL float).
    std::vector<std::pair<std::string, std::string>> macros;
    for (const std::string& d : l.defines) {
        const size_t eq = d.find('=');
        if (d.starts_with("-D") && eq != std::string::npos) macros.emplace_back(d.substr(2, eq - 2), d.substr(eq + 1));
    }
    for (const ListingLine& line : l.lines) {
        const size_t at = line.text.find("#define ");
        if (!line.active || at == std::string::npos || line.text.find_first_not_of(' ') != at) continue;
        std::string rest = line.text.substr(at + 8);
        if (const size_t c = rest.find("//"); c != std::string::npos) rest.erase(c);
        const size_t end = rest.find_first_of(" (");
        if (end != std::string::npos && rest[end] == '(') continue;  // function-like
        std::string value = end == std::string::npos ? "" : rest.substr(end + 1);
        while (!value.empty() && (value.back() == ' ' || value.back() == '\\')) value.pop_back();
        while (!value.empty() && value.front() == ' ') value.erase(value.begin());
        macros.emplace_back(rest.substr(0, end), value);
    }
    const auto substitute = [&](const std::string& original) {
        std::string text = original;
        const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
        for (const auto& [name, value] : macros)
            for (size_t at = 0; (at = text.find(name, at)) != std::string::npos;) {
                const bool alone = (at == 0 || !word(text[at - 1])) && (at + name.size() == text.size() || !word(text[at + name.size()]));
                if (alone) text.replace(at, name.size(), value);
                at += alone ? value.size() : name.size();
            }
        // A macro that stood first on its line and vanished (PW_REAL_FN) leaves no indent behind.
        if (!text.empty() && text.front() == ' ' && original.front() != ' ') text.erase(0, text.find_first_not_of(' '));
        return text;
    };
    std::vector<ListingLine> out;
    const auto header = [&](const ListingLine& at, std::string title) {
        while (!title.empty() && title.front() == ' ') title.erase(title.begin());
        ListingLine h = at;
        h.text = "// " + title + "  (" + at.file + ":" + std::to_string(at.line) + ")";
        h.line = 0;
        if (!out.empty()) out.push_back({"", at.file, 0, at.depth, true});  // a blank line between parts
        out.push_back(std::move(h));
    };
    bool inside = false;
    for (const ListingLine& line : l.lines) {
        const size_t open = line.text.find("// @teach{"), close = line.text.find("// @teach}"), one = line.text.find("// @teach=");
        if (open != std::string::npos) {
            inside = true;
            header(line, line.text.substr(open + 10));
            continue;
        }
        if (close != std::string::npos) {
            inside = false;
            continue;
        }
        const size_t first = line.text.find_first_not_of(' ');
        if (!line.active || (first != std::string::npos && line.text[first] == '#')) continue;  // no preprocessor lines
        if (one != std::string::npos) {
            const std::string title = line.text.substr(one + 10);
            if (title.find_first_not_of(' ') != std::string::npos) header(line, title);
            ListingLine shown = line;
            shown.text = substitute(line.text.substr(0, one));
            while (!shown.text.empty() && shown.text.back() == ' ') shown.text.pop_back();
            out.push_back(std::move(shown));
        } else if (inside) {
            ListingLine shown = line;
            shown.text = substitute(line.text);
            out.push_back(std::move(shown));
        }
    }
    return out;
}

}  // namespace scene
}  // namespace pw::render

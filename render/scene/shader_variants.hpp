// Which compiled shader variant (shaders/CMakeLists.txt) a setting selects: the one place the
// renderer (which pipeline to bind) and the shader panel (which GLSL to show) both ask.
#pragma once

#include "core/model/document.hpp"
#include "render/scene/pipelines.hpp"

namespace pw::render {
inline namespace scene {

// Evaluation-shader spacing: pow2 uses equal spacing (its levels are rounded in the control shader).
inline int spacingVariant(Spacing s) {
    switch (s) {
        case Spacing::FractionalOdd:
            return int(SpacingVariant::FractionalOdd);
        case Spacing::FractionalEven:
            return int(SpacingVariant::FractionalEven);
        default:
            return int(SpacingVariant::Equal);
    }
}

// Adaptive levels or culling need the full control shader; uniform levels and overrides do not.
inline LevelsVariant levelsVariant(const TessSettings& ts) {
    const bool adaptive = ts.adaptive != AdaptiveMode::None;
    return adaptive || ts.cullBackfaces || ts.cullOffscreen ? LevelsVariant::Full : LevelsVariant::Fixed;
}

// Patch-id, UV and curvature shading need the full varying set; the others position and normal only.
// A scene with trimmed windows always takes the full set: the fragment shader tests (u, v) against
// the trims (shaders/trim.glsl).
inline VaryingsVariant varyingsVariant(ShadingMode m, bool trimmed = false) {
    if (trimmed) return VaryingsVariant::Full;
    switch (m) {
        case ShadingMode::PatchId:
        case ShadingMode::UvChecker:
        case ShadingMode::GaussCurvature:
        case ShadingMode::MeanCurvature:
        case ShadingMode::Level:
            return VaryingsVariant::Full;
        default:
            return VaryingsVariant::Lean;
    }
}

}  // namespace scene
}  // namespace pw::render

// Documented limits of what Patchwork reads (docs/LIMITS.md). Inputs beyond them are refused with
// an InputError rather than exhausting memory.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pw {
inline namespace base {
namespace limits {

inline constexpr std::size_t kMaxFileBytes = 256u * 1024u * 1024u;  // any file read
inline constexpr std::size_t kMaxPoints = 4'000'000;                // pool entries
inline constexpr std::size_t kMaxPatches = 1'000'000;               // patches + surface windows
inline constexpr std::size_t kMaxJoins = 4'000'000;
inline constexpr uint32_t kMaxNetSide = 4096;  // rows or columns of one net
inline constexpr double kMaxCoordinate = 1e9;  // |x|, |y|, |z|
// STEP/IGES import through OpenCASCADE runs in a child process with these budgets (wall time; address
// space beyond the parent's), so that no file can hang or exhaust the program (issue 44).
// PATCHWORK_CAD_SECONDS overrides the time (tests).
inline constexpr double kMaxCadImportSeconds = 8.0;
inline constexpr std::size_t kMaxCadImportBytes = std::size_t{1} << 30;
// STEP/IGES values checked before OpenCASCADE sees them: |number| (knots and coordinates alike),
// digits in one number, and values in one entity (a B-spline's poles, knots and weights).
inline constexpr double kMaxCadNumber = 1e12;
inline constexpr std::size_t kMaxCadNumberDigits = 40;
inline constexpr std::size_t kMaxCadEntityValues = 200'000;
inline constexpr float kMinTessLevel = 1.0f;
inline constexpr float kMaxTessLevel = 64.0f;  // Vulkan's guaranteed maxTessellationGenerationLevel
inline constexpr int kMaxExportLevel = 256;    // CPU tessellation for export
// Presentation mode's text, times the interface's size (the `presentation-text` command, the
// Teaching panel's slider).
inline constexpr float kMinPresentationText = 1.0f;
inline constexpr float kMaxPresentationText = 4.0f;
// Distance mode's pow2 curve: the exponents of 2 at the near and far distances (tess.distanceExponents).
inline constexpr double kMinDistanceExponent = -8.0, kMaxDistanceExponent = 32.0;
// A perspective camera's vertical field of view, degrees, in (0, kMaxFovYDeg]: at 180 the
// projection is singular (it rendered blank).
inline constexpr double kMaxFovYDeg = 170.0;

}  // namespace limits
}  // namespace base
}  // namespace pw

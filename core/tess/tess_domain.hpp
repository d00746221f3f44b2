// The fixed-function tessellator's rules on the CPU (Vulkan spec, "Tessellation"; DESIGN §3): how
// a requested level becomes a segment count under each partitioning, and how many vertices and
// primitives the quad, triangle and isoline domains produce for a set of levels. The domain view
// shows what the GPU made; these rules are what the tests hold the GPU's counts against.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/model/document.hpp"

namespace pw {
inline namespace tess {

enum class DomainKind : uint8_t { Quad, Triangle, Isoline };
std::string_view domainName(DomainKind k);                     // "quad", "tri", "isoline"
std::optional<DomainKind> parseDomain(std::string_view name);  // also "triangle", "isolines"

// Levels as a tessellation control shader writes them. Quad: outer[0..3] = edges u=0, v=0, u=1,
// v=1; inner[0] along u, inner[1] along v. Triangle: outer[0..2] = edges u=0, v=0, w=0; inner[0].
// Isoline: outer[0] = number of lines, outer[1] = segments per line; inner unused.
struct DomainLevels {
    std::array<float, 4> outer{4, 4, 4, 4};
    std::array<float, 2> inner{4, 4};
    bool operator==(const DomainLevels&) const = default;
};

// How many outer and inner levels a domain uses (quad 4 and 2, triangle 3 and 1, isoline 2 and 0).
int outerLevelCount(DomainKind k);
int innerLevelCount(DomainKind k);

// Levels as the notes write them, each in the fewest decimals that read back to the same float,
// joined by `sep`: "4.9,4.5,4.1".
std::string joinLevels(const float* levels, int count, std::string_view sep);
// "quad {1,2,3,4 | 4,4}": a domain's used levels; describeSet adds the partitioning
// ("tri {4.9,4.5,4.1 | 4.4} fractional_odd"), for messages and captures.
std::string describeLevels(DomainKind kind, const DomainLevels& levels);
std::string describeSet(DomainKind kind, Spacing spacing, const DomainLevels& levels);

// `used` with every level its domain uses (the non-zero ones) set to `level`; unused stay 0.
DomainLevels withUniformLevel(const DomainLevels& used, float level);

// The level the control shader hands the tessellator: pow2 is emulated there (next power of two
// of the integer level, then equal spacing); the other modes pass the level through.
float controlShaderLevel(float level, Spacing s);

// The spacing the tessellator runs with (pow2 runs as equal).
Spacing tessellatorSpacing(Spacing s);

// Segment count of one edge for a level the tessellator receives, under its spacing (equal,
// fractional_odd, fractional_even): the level clamped to [1, max] (odd: [1, max-1]; even:
// [2, max]) and rounded up to an integer (odd: the next odd, even: the next even). 0 when the
// level culls the patch (<= 0 or NaN; outer levels only). `maxLevel` is the device's
// maxTessellationGenerationLevel.
int segmentCount(float level, Spacing tessellatorSpacing, float maxLevel = 64.0f);

// How far the two short segments of a fractional partitioning have grown, in percent of a full
// segment, for an edge of `level` (the control shader's) cut into `seg` segments: the notes'
// (f - 3) / (5 - 3) * 100 for a level f between 3 and 5 under fractional_odd, (f - 4) / (6 - 4) * 100
// between 4 and 6 under fractional_even. Negative where nothing slides: equal and pow2 spacing,
// fewer than two segments, or a level the partitioning meets exactly (all segments full, 0 or 100).
float slidePercent(float level, Spacing spacing, int seg);

// The notes' rounding table: what each partitioning (equal, fractional_odd, fractional_even, pow2)
// makes of each requested level: the segments of one edge and, for the fractional ones, the slide.
struct RoundingCell {
    float level = 0.0f;
    int segments = 0;
    float slide = -1.0f;  // slidePercent, negative: none
};
struct RoundingRow {
    Spacing spacing = Spacing::Equal;
    std::vector<RoundingCell> cells;
};
std::vector<RoundingRow> roundingTable(const std::vector<float>& levels, float maxLevel = 64.0f);
// The levels the notes' table lists: 3.0, 3.25, 3.75, 4.25, 4.75 and 5.
std::vector<float> notesRoundingLevels();

struct DomainCounts {
    bool culled = false;      // an outer level <= 0 or NaN: the patch is discarded
    uint64_t vertices = 0;    // distinct domain points = evaluation shader invocations
    uint64_t primitives = 0;  // triangles (quad, triangle) or line segments (isoline)
    // Segment counts the tessellator used: outer edges, then inner (quad: 2, triangle: 1).
    std::array<int, 4> outerSegments{};
    std::array<int, 2> innerSegments{};
};

// What the tessellator produces for one patch with these levels and partitioning (pow2 included:
// it is applied as the control shader does).
DomainCounts expectedDomainCounts(DomainKind kind, const DomainLevels& levels, Spacing spacing, float maxLevel = 64.0f);

}  // namespace tess
}  // namespace pw

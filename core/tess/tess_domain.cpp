#include "core/tess/tess_domain.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/base/enum_names.hpp"
#include "core/gpu/patch_math.h"

namespace pw {
inline namespace tess {

namespace {
constexpr std::array<std::string_view, 3> kDomainNames{"quad", "tri", "isoline"};
constexpr std::array<std::string_view, 3> kDomainPlurals{"quads", "triangles", "isolines"};
}  // namespace

std::string_view domainName(DomainKind k) { return enumName(k, kDomainNames); }

int outerLevelCount(DomainKind k) { return k == DomainKind::Quad ? 4 : k == DomainKind::Triangle ? 3 : 2; }
int innerLevelCount(DomainKind k) { return k == DomainKind::Quad ? 2 : k == DomainKind::Triangle ? 1 : 0; }

std::string joinLevels(const float* levels, int count, std::string_view sep) {
    std::string s;
    for (int i = 0; i < count; ++i) {
        char buf[32];
        const auto r = std::to_chars(buf, buf + sizeof buf, levels[i]);
        s += (i ? std::string(sep) : std::string()) + std::string(buf, r.ptr);
    }
    return s;
}

std::string describeLevels(DomainKind kind, const DomainLevels& l) {
    return std::string(domainName(kind)) + " {" + joinLevels(l.outer.data(), outerLevelCount(kind), ",") + " | " +
           joinLevels(l.inner.data(), innerLevelCount(kind), ",") + "}";
}

std::string describeSet(DomainKind kind, Spacing spacing, const DomainLevels& l) {
    return describeLevels(kind, l) + " " + std::string(spacingName(spacing));
}

std::optional<DomainKind> parseDomain(std::string_view name) {
    if (name == "triangle") return DomainKind::Triangle;
    if (auto k = parseEnum<DomainKind>(name, kDomainNames)) return k;
    return parseEnum<DomainKind>(name, kDomainPlurals);
}

float controlShaderLevel(float level, Spacing s) { return s == Spacing::Pow2 ? gpu::roundLevel(level, gpu::kSpacingPow2) : level; }

Spacing tessellatorSpacing(Spacing s) { return s == Spacing::Pow2 ? Spacing::Equal : s; }

namespace {

// The level clamped as the tessellator clamps it for a spacing.
float clampLevel(float level, Spacing s, float maxLevel) {
    switch (s) {
        case Spacing::FractionalOdd:
            return std::clamp(level, 1.0f, maxLevel - 1.0f);
        case Spacing::FractionalEven:
            return std::clamp(level, 2.0f, maxLevel);
        default:
            return std::clamp(level, 1.0f, maxLevel);
    }
}

// Segments for an already clamped level; `plusEpsilon` treats a level of exactly 1 as 1 + ε.
int roundClamped(float clamped, Spacing s, bool plusEpsilon) {
    double f = clamped;
    if (plusEpsilon && clamped == 1.0f) f = 1.0 + 1e-6;
    const int c = int(std::ceil(f - 1e-9));
    switch (s) {
        case Spacing::FractionalOdd:
            return c % 2 == 1 ? c : c + 1;
        case Spacing::FractionalEven:
            return c % 2 == 0 ? c : c + 1;
        default:
            return std::max(1, c);
    }
}

bool culls(float outer) { return !(outer > 0.0f); }  // <= 0 or NaN

// Interior vertices of a triangle domain whose inner level gives n segments per side: concentric
// triangles with n-2, n-4, ... segments per side (3m vertices each), then a centre point (n even)
// or a last small triangle (n odd, included as m = 1).
uint64_t triangleInteriorVertices(int n) {
    uint64_t v = 0;
    int m = n - 2;
    for (; m > 0; m -= 2) v += 3u * uint64_t(m);
    if (m == 0) v += 1;
    return v;
}

}  // namespace

float slidePercent(float level, Spacing spacing, int seg) {
    const Spacing ts = tessellatorSpacing(spacing);
    if (spacing == Spacing::Pow2 || ts == Spacing::Equal || seg < 2) return -1.0f;
    const float f = std::max(level, ts == Spacing::FractionalEven ? 2.0f : 1.0f);
    const float pct = std::clamp((f - float(seg - 2)) * 50.0f, 0.0f, 100.0f);
    return pct >= 100.0f || pct <= 0.0f ? -1.0f : pct;
}

std::vector<RoundingRow> roundingTable(const std::vector<float>& levels, float maxLevel) {
    std::vector<RoundingRow> rows;
    for (Spacing s : {Spacing::Equal, Spacing::FractionalOdd, Spacing::FractionalEven, Spacing::Pow2}) {
        RoundingRow row{s, {}};
        for (float l : levels) {
            const float cs = controlShaderLevel(l, s);
            const int seg = segmentCount(cs, tessellatorSpacing(s), maxLevel);
            row.cells.push_back({l, seg, slidePercent(cs, s, seg)});
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::vector<float> notesRoundingLevels() { return {3.0f, 3.25f, 3.75f, 4.25f, 4.75f, 5.0f}; }

int segmentCount(float level, Spacing s, float maxLevel) {
    if (culls(level)) return 0;
    return roundClamped(clampLevel(level, s, maxLevel), s, false);
}

DomainCounts expectedDomainCounts(DomainKind kind, const DomainLevels& levels, Spacing spacing, float maxLevel) {
    DomainCounts out;
    const Spacing ts = tessellatorSpacing(spacing);
    const int nOuter = outerLevelCount(kind), nInner = innerLevelCount(kind);
    std::array<float, 4> outer{};
    std::array<float, 2> inner{};
    for (int e = 0; e < nOuter; ++e) {
        outer[size_t(e)] = controlShaderLevel(levels.outer[size_t(e)], spacing);
        if (culls(outer[size_t(e)])) {
            out.culled = true;
            return out;
        }
    }
    for (int i = 0; i < nInner; ++i) {
        float l = controlShaderLevel(levels.inner[size_t(i)], spacing);
        inner[size_t(i)] = l == l ? l : 1.0f;
    }

    if (kind == DomainKind::Isoline) {
        // The line count always uses integer spacing; the segments per line use the partitioning.
        const uint64_t lines = uint64_t(segmentCount(outer[0], Spacing::Equal, maxLevel));
        const uint64_t segs = uint64_t(segmentCount(outer[1], ts, maxLevel));
        out.outerSegments = {int(lines), int(segs), 0, 0};
        out.vertices = lines * (segs + 1);
        out.primitives = lines * segs;
        return out;
    }

    // The special case: every clamped level exactly one gives the undivided domain.
    bool allOne = true;
    for (int e = 0; e < nOuter; ++e) allOne = allOne && clampLevel(outer[size_t(e)], ts, maxLevel) == 1.0f;
    for (int i = 0; i < nInner; ++i) allOne = allOne && clampLevel(inner[size_t(i)], ts, maxLevel) == 1.0f;
    uint64_t boundary = 0;
    for (int e = 0; e < nOuter; ++e) {
        out.outerSegments[size_t(e)] = segmentCount(outer[size_t(e)], ts, maxLevel);
        boundary += uint64_t(out.outerSegments[size_t(e)]);
    }
    if (allOne) {
        out.innerSegments = {1, kind == DomainKind::Quad ? 1 : 0};
        out.vertices = uint64_t(nOuter);
        out.primitives = kind == DomainKind::Quad ? 2 : 1;
        return out;
    }
    // Otherwise an inner level of exactly one counts as 1 + ε (two or three segments).
    for (int i = 0; i < nInner; ++i) out.innerSegments[size_t(i)] = roundClamped(clampLevel(inner[size_t(i)], ts, maxLevel), ts, true);
    const uint64_t interior = kind == DomainKind::Quad ? uint64_t(out.innerSegments[0] - 1) * uint64_t(out.innerSegments[1] - 1)
                                                       : triangleInteriorVertices(out.innerSegments[0]);
    out.vertices = boundary + interior;
    // A triangulated disc with B boundary and I interior vertices has B + 2I - 2 triangles (Euler).
    out.primitives = boundary + 2 * interior - 2;
    return out;
}

DomainLevels withUniformLevel(const DomainLevels& used, float level) {
    DomainLevels out = used;
    for (float& l : out.outer) l = l > 0.0f ? level : 0.0f;
    for (float& l : out.inner) l = l > 0.0f ? level : 0.0f;
    return out;
}

}  // namespace tess
}  // namespace pw

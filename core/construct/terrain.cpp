#include "core/construct/terrain.hpp"

#include <cmath>

namespace pw {
inline namespace construct {

Document makeTerrainDocument(const TerrainSpec& spec) {
    Document doc;
    doc.name = "terrain";
    // A B-spline net of (n + 3) points per side: n windows, the outer ring one spacing outside the
    // square so the surface covers it exactly (uniform cubic B-spline of collinear, evenly spaced points).
    const int n = spec.windows, pts = n + 3;
    const double step = spec.size / n, x0 = -spec.size / 2 - step;
    Surface s;
    s.rows = s.cols = uint32_t(pts);
    s.basis = Basis::BSpline;
    s.name = "terrain";
    for (int r = 0; r < pts; ++r)
        for (int c = 0; c < pts; ++c) {
            s.idx.push_back(uint32_t(doc.points.size()));
            doc.points.emplace_back(x0 + c * step, x0 + r * step, 0.0);
        }
    doc.surfaces.push_back(std::move(s));
    doc.displacement.map = spec.map;
    doc.displacement.scale = spec.height;
    doc.displacement.mapping = DisplacementMapping::Planar;
    doc.displacement.rect = std::array<double, 4>{-spec.size / 2, -spec.size / 2, spec.size, spec.size};
    doc.tess.adaptive = AdaptiveMode::Distance;
    doc.tess.distanceNear = float(spec.size / 16);
    doc.tess.distanceFar = float(spec.size * 1.5);
    doc.tess.maxLevel = 16.0f;  // lavapipe draws the near view in about 0.2 s; 64 looks the same at 12x the triangles
    doc.tess.cullOffscreen = true;
    doc.tess.linked = false;
    doc.display.showGrid = false;
    doc.display.background = {0.55f, 0.68f, 0.82f};
    doc.camera.target = {0.0, -spec.size * 0.2, spec.height * 0.4};
    doc.camera.distance = spec.size * 0.22;
    doc.camera.yawDeg = 20.0;
    doc.camera.pitchDeg = 14.0;
    doc.camera.fovYDeg = 55.0;
    return doc;
}

namespace {

double hash01(uint32_t x, uint32_t y, uint32_t seed) {
    uint32_t h = x * 374761393u + y * 668265263u + seed * 2246822519u;
    h = (h ^ (h >> 13)) * 1274126177u;
    h ^= h >> 16;
    return (h & 0xffffffu) / double(0xffffff);
}

// Smoothly interpolated lattice noise with period `period` (tiles the map), 0..1.
double valueNoise(double x, double y, uint32_t period, uint32_t seed) {
    const double fx = std::floor(x), fy = std::floor(y);
    const double tx = x - fx, ty = y - fy;
    const double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
    const auto ix = uint32_t(int64_t(fx) % period), iy = uint32_t(int64_t(fy) % period);
    const uint32_t jx = (ix + 1) % period, jy = (iy + 1) % period;
    const double a = hash01(ix, iy, seed), b = hash01(jx, iy, seed), c = hash01(ix, jy, seed), d = hash01(jx, jy, seed);
    return (a * (1 - sx) + b * sx) * (1 - sy) + (c * (1 - sx) + d * sx) * sy;
}

}  // namespace

HeightMap makeTerrainHeightMap(uint32_t size, uint32_t seed) {
    std::vector<double> v(size_t(size) * size);
    double lo = 1e9, hi = -1e9;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            double sum = 0, amp = 1, norm = 0;
            for (uint32_t o = 0; o < 8; ++o) {
                const uint32_t period = 4u << o;
                const double f = double(period) / size;
                double n = valueNoise(x * f, y * f, period, seed + o);
                if (o < 2) n = 1.0 - std::abs(2.0 * n - 1.0);  // ridges in the broad shapes
                sum += amp * n;
                norm += amp;
                amp *= 0.5;
            }
            const double h = sum / norm;
            v[size_t(y) * size + x] = h;
            lo = std::min(lo, h);
            hi = std::max(hi, h);
        }
    for (double& h : v) h = (h - lo) / (hi - lo);  // the full 0..1 range
    return heightMapFromValues(size, size, v, "terrain.png");
}

}  // namespace construct
}  // namespace pw

#include "core/trim/surface_domain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/base/errors.hpp"
#include "core/trim/gauss_legendre.hpp"

namespace pw {
inline namespace trim {

std::string surfaceRefName(const SurfaceRef& s) { return (s.net ? "n" : "") + std::to_string(s.index); }

bool surfaceExists(const Document& doc, const SurfaceRef& s) {
    return s.net ? s.index < doc.surfaces.size() : s.index < doc.patches.size();
}

SurfaceRef parseSurfaceRef(const Document& doc, std::string_view word) {
    SurfaceRef s;
    std::string_view digits = word;
    if (!digits.empty() && (digits[0] == 'n' || digits[0] == 'N')) {
        s.net = true;
        digits.remove_prefix(1);
    }
    const bool ok =
        !digits.empty() && digits.size() <= 9 && std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!ok) throw EditError("'" + printable(word) + "' is not a surface: give a patch number (3) or a net as nN (n0)");
    s.index = uint32_t(std::stoul(std::string(digits)));
    if (!surfaceExists(doc, s))
        throw EditError(std::string(s.net ? "net " : "patch ") + std::to_string(s.index) + " does not exist (the document has " +
                        std::to_string(s.net ? doc.surfaces.size() : doc.patches.size()) + (s.net ? " nets)" : " patches)"));
    return s;
}

std::vector<TrimLoop>& trimsOf(Document& doc, const SurfaceRef& s) {
    return s.net ? doc.surfaces[s.index].trims : doc.patches[s.index].trims;
}
const std::vector<TrimLoop>& trimsOf(const Document& doc, const SurfaceRef& s) {
    return s.net ? doc.surfaces[s.index].trims : doc.patches[s.index].trims;
}

DomainSurface::DomainSurface(const Document& doc, const SurfaceRef& ref) {
    if (!surfaceExists(doc, ref)) throw EditError("surface " + surfaceRefName(ref) + " does not exist");
    if (!ref.net) {
        const Patch& p = doc.patches[ref.index];
        windows_.push_back({gatherWindow(doc, p.idx), p.basis, p.tension});
    } else {
        const Surface& s = doc.surfaces[ref.index];
        const uint32_t step = netStep(s.basis);
        wu_ = uint32_t(netWindowCount(s.cols, s.closedU, step));
        wv_ = uint32_t(netWindowCount(s.rows, s.closedV, step));
        if (wu_ == 0 || wv_ == 0) throw EditError("net " + std::to_string(ref.index) + " has no windows");
        closedU_ = s.closedU;
        closedV_ = s.closedV;
        for (uint32_t r = 0; r < wv_; ++r)
            for (uint32_t c = 0; c < wu_; ++c) {
                std::array<uint32_t, 16> idx{};
                for (uint32_t i = 0; i < 4; ++i)
                    for (uint32_t j = 0; j < 4; ++j) idx[i * 4 + j] = s.idx[((r * step + i) % s.rows) * s.cols + (c * step + j) % s.cols];
                windows_.push_back({gatherWindow(doc, idx), s.basis, s.tension});
            }
    }
    // A sample grid for closest-point starts: 8 x 8 per window (at most 64 x 64 in all).
    const uint32_t nu = std::min<uint32_t>(64, 8 * wu_), nv = std::min<uint32_t>(64, 8 * wv_);
    Bounds b;
    for (uint32_t i = 0; i <= nv; ++i)
        for (uint32_t j = 0; j <= nu; ++j) {
            const UV uv{double(j) / nu, double(i) / nv};
            const Vec3 p = evaluate(uv).p;
            samples_.push_back({uv, p});
            b.add(p);
        }
    size_ = std::max(b.diagonal(), 1e-12);
}

SurfacePoint DomainSurface::evaluate(UV uv) const {
    const double U = std::clamp(uv[0], 0.0, 1.0) * wu_, V = std::clamp(uv[1], 0.0, 1.0) * wv_;
    const uint32_t c = std::min<uint32_t>(uint32_t(U), wu_ - 1), r = std::min<uint32_t>(uint32_t(V), wv_ - 1);
    const Window& w = windows_[size_t(r) * wu_ + c];
    SurfacePoint sp = evaluateWindow(w.net, w.basis, w.tension, U - c, V - r);
    sp.du *= double(wu_);
    sp.dv *= double(wv_);
    return sp;
}

UV DomainSurface::closest(const Vec3& p, std::optional<UV> guess) const {
    UV best{0.5, 0.5};
    double bestD = std::numeric_limits<double>::infinity();
    if (guess) {
        best = *guess;
        bestD = glm::length(evaluate(best).p - p);
    }
    // The sample grid too, unless the guess is already close (a curve followed point by point).
    if (!guess || bestD > 0.02 * size_) {
        for (const auto& [uv, q] : samples_) {
            const double d = glm::length(q - p);
            if (d < bestD) {
                bestD = d;
                best = uv;
            }
        }
    }
    // Newton on the distance's gradient (Gauss-Newton with the second-derivative term dropped), clamped.
    UV uv = best;
    for (int it = 0; it < 30; ++it) {
        const SurfacePoint s = evaluate(uv);
        const Vec3 r = s.p - p;
        const double a = glm::dot(s.du, s.du), b = glm::dot(s.du, s.dv), c = glm::dot(s.dv, s.dv);
        const double gu = glm::dot(r, s.du), gv = glm::dot(r, s.dv);
        const double det = a * c - b * b;
        if (!(det > 1e-300)) break;
        double du = -(c * gu - b * gv) / det, dv = -(a * gv - b * gu) / det;
        // Keep steps modest: a quarter of a window at most.
        const double lim = 0.25 / double(std::max(wu_, wv_));
        const double m = std::max(std::abs(du), std::abs(dv));
        if (m > lim) {
            du *= lim / m;
            dv *= lim / m;
        }
        UV next{uv[0] + du, uv[1] + dv};
        if (closedU_)
            next[0] -= std::floor(next[0]);
        else
            next[0] = std::clamp(next[0], 0.0, 1.0);
        if (closedV_)
            next[1] -= std::floor(next[1]);
        else
            next[1] = std::clamp(next[1], 0.0, 1.0);
        const bool small = std::abs(next[0] - uv[0]) < 1e-14 && std::abs(next[1] - uv[1]) < 1e-14;
        uv = next;
        if (small) break;
    }
    return uv;
}

std::optional<UV> DomainSurface::alongDirection(const Vec3& p, const Vec3& dirIn, std::optional<UV> guess) const {
    const Vec3 dir = glm::normalize(dirIn);
    // Start from the sample nearest the line, then Newton on S(u, v) - p - t dir = 0 (3 unknowns).
    UV uv = guess.value_or(UV{0.5, 0.5});
    if (!guess) {
        double best = std::numeric_limits<double>::infinity();
        for (const auto& [s, q] : samples_) {
            const Vec3 d = q - p;
            const double off = glm::length(d - glm::dot(d, dir) * dir);
            if (off < best) {
                best = off;
                uv = s;
            }
        }
    }
    double t = glm::dot(evaluate(uv).p - p, dir);
    for (int it = 0; it < 40; ++it) {
        const SurfacePoint s = evaluate(uv);
        const Vec3 f = s.p - p - t * dir;
        if (glm::length(f) < 1e-13 * size_) break;
        // Solve [du dv -dir] x = -f.
        const Vec3 c0 = s.du, c1 = s.dv, c2 = -dir;
        const double det = glm::dot(c0, glm::cross(c1, c2));
        if (std::abs(det) < 1e-300) return std::nullopt;
        const Vec3 x = Vec3(glm::dot(-f, glm::cross(c1, c2)), glm::dot(c0, glm::cross(-f, c2)), glm::dot(c0, glm::cross(c1, -f))) / det;
        UV next{uv[0] + x.x, uv[1] + x.y};
        if (closedU_) next[0] -= std::floor(next[0]);
        if (closedV_) next[1] -= std::floor(next[1]);
        next[0] = std::clamp(next[0], 0.0, 1.0);
        next[1] = std::clamp(next[1], 0.0, 1.0);
        uv = next;
        t += x.z;
    }
    const Vec3 f = evaluate(uv).p - p - t * dir;
    if (glm::length(f) > 1e-7 * size_) return std::nullopt;
    return uv;
}

namespace {

double jacobian(const DomainSurface& s, UV uv) {
    const SurfacePoint p = s.evaluate(uv);
    return glm::length(glm::cross(p.du, p.dv));
}
}  // namespace

double DomainSurface::area() const {
    double a = 0.0;
    const int sub = 4;  // 4 x 4 cells of 8 x 8 Gauss points per window
    const double hu = 1.0 / (wu_ * sub), hv = 1.0 / (wv_ * sub);
    for (uint32_t i = 0; i < wv_ * sub; ++i)
        for (uint32_t j = 0; j < wu_ * sub; ++j)
            for (int a1 = 0; a1 < 8; ++a1)
                for (int b1 = 0; b1 < 8; ++b1)
                    a += kGaussW[a1] * kGaussW[b1] * jacobian(*this, {(j + kGaussX[b1]) * hu, (i + kGaussX[a1]) * hv});
    return a * hu * hv;
}

namespace {

// ∫ J(s, v) ds from u0 to u1 in pieces that end at quarter-window boundaries (J is smooth inside a
// window), each of 8 Gauss points.
double stripPart(const DomainSurface& s, double u0, double u1, double v) {
    double sum = 0.0;
    const double step = 1.0 / (s.windowsU() * 4.0);
    while (u0 < u1) {
        const double next = std::min(u1, (std::floor(u0 / step + 1e-9) + 1.0) * step);
        for (int k = 0; k < 8; ++k) sum += kGaussW[k] * (next - u0) * jacobian(s, {u0 + kGaussX[k] * (next - u0), v});
        u0 = next;
    }
    return sum;
}

// Chebyshev points of the first kind on [-1, 1] and their barycentric weights, computed once.
constexpr int kStripNodes = 16;
struct ChebyshevNodes {
    std::array<double, kStripNodes> x{}, w{};
    ChebyshevNodes() {
        for (int n = 0; n < kStripNodes; ++n) {
            const double angle = (2.0 * n + 1.0) * std::numbers::pi / (2.0 * kStripNodes);
            x[size_t(n)] = std::cos(angle);
            w[size_t(n)] = ((n % 2) ? -1.0 : 1.0) * std::sin(angle);
        }
    }
};
const ChebyshevNodes kChebyshev;

}  // namespace

double AreaStrips::at(UV uv) {
    const uint32_t wu = s_.windowsU(), wv = s_.windowsV();
    const double u = std::clamp(uv[0], 0.0, 1.0), v = std::clamp(uv[1], 0.0, 1.0);
    const uint32_t row = std::min(uint32_t(v * wv), wv - 1), whole = std::min(uint32_t(u * wu), wu - 1);
    const double v0 = double(row) / wv, v1 = double(row + 1) / wv;
    std::vector<double>& table = rows_[row];
    if (table.empty()) {
        table.assign(size_t(wu + 1) * kStripNodes, 0.0);
        for (int n = 0; n < kStripNodes; ++n) {
            const double vn = v0 + (v1 - v0) * 0.5 * (1.0 + kChebyshev.x[size_t(n)]);
            for (uint32_t k = 0; k < wu; ++k)
                table[size_t(k + 1) * kStripNodes + size_t(n)] =
                    table[size_t(k) * kStripNodes + size_t(n)] + stripPart(s_, double(k) / wu, double(k + 1) / wu, vn);
        }
    }
    // Barycentric interpolation at the Chebyshev points (exact on a node).
    const double x = 2.0 * (v - v0) / (v1 - v0) - 1.0;
    const double* prefix = &table[size_t(whole) * kStripNodes];
    double num = 0.0, den = 0.0;
    for (size_t n = 0; n < size_t(kStripNodes); ++n) {
        const double d = x - kChebyshev.x[n];
        if (d == 0.0) return prefix[n] + stripPart(s_, double(whole) / wu, u, v);
        num += kChebyshev.w[n] / d * prefix[n];
        den += kChebyshev.w[n] / d;
    }
    return num / den + stripPart(s_, double(whole) / wu, u, v);
}

}  // namespace trim
}  // namespace pw

#include "render/figures/math_figure.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/model/camera_math.hpp"

namespace pw::render {
inline namespace figures {

namespace {

// A segment of width `w` with round caps, anti-aliased by distance (a disc where a == b).
void strokeSegment(PixelImage& img, glm::dvec2 a, glm::dvec2 b, float w, const std::array<unsigned char, 4>& c) {
    const double r = 0.5 * double(w);
    const int x0 = int(std::floor(std::min(a.x, b.x) - r - 1)), x1 = int(std::ceil(std::max(a.x, b.x) + r + 1));
    const int y0 = int(std::floor(std::min(a.y, b.y) - r - 1)), y1 = int(std::ceil(std::max(a.y, b.y) + r + 1));
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    for (int y = std::max(y0, 0); y <= std::min(y1, int(img.height) - 1); ++y)
        for (int x = std::max(x0, 0); x <= std::min(x1, int(img.width) - 1); ++x) {
            const glm::dvec2 p(x + 0.5, y + 0.5);
            const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
            const double d = glm::length(p - (a + t * ab));
            blendPixel(img, x, y, c, float(std::clamp(r + 0.5 - d, 0.0, 1.0)));
        }
}

}  // namespace

void drawMathDiagram(PixelImage image, const MathDiagram& d, const Camera& cam, const std::array<float, 4>& rect, float textPixels,
                     const LabelRaster& labels) {
    const int W = std::max(int(rect[2]), 1), H = std::max(int(rect[3]), 1);
    const ViewMatrices vm = viewMatrices(cam, double(W) / H);
    const auto proj = [&](const Vec3& q) -> std::optional<glm::dvec2> {
        const auto s = projectToPixel(vm, q, W, H);
        if (!s) return std::nullopt;
        return *s + glm::dvec2(rect[0], rect[1]);
    };
    const float dot = mathDotRadius(textPixels);
    for (const MathDiagram::Stroke& s : d.strokes) {
        const auto a = proj(s.a), b = proj(s.b);
        if (a && b) strokeSegment(image, *a, *b, mathStrokeWidth(s.role, textPixels), mathColor(s.role));
    }
    for (const MathDiagram::Dot& o : d.dots)
        if (const auto c = proj(o.p)) strokeSegment(image, *c, *c, 2.0f * dot * float(o.radius), mathColor(o.role));
    for (const MathDiagram::Dot& o : d.dots) {
        const auto c = proj(o.p);
        if (!c || o.label.empty()) continue;
        TextStyle st;
        st.pixels = textPixels;
        st.color = mathColor(o.role);
        st.box = true;
        st.boxColor = {0, 0, 0, 170};
        labels.draw(image, float(c->x) + dot * float(o.radius) + 2.0f, float(c->y) - 1.0f, o.label, st, 0.0f, 1.0f);
    }
    // The numbers, bottom left, each line in the colour of what it describes.
    const float line = textPixels * 1.3f;
    float y = rect[1] + rect[3] - textPixels * 0.8f - line * float(d.legend.size() - 1);
    for (size_t i = 0; i < d.legend.size(); ++i, y += line) {
        TextStyle st;
        st.pixels = textPixels;
        st.color = mathColor(i < d.legendRoles.size() ? d.legendRoles[i] : MathDiagram::Role::Point);
        st.box = true;
        st.boxColor = {0, 0, 0, 190};
        labels.draw(image, rect[0] + textPixels * 0.8f, y, d.legend[i], st, 0.0f, 1.0f);
    }
}

}  // namespace figures
}  // namespace pw::render

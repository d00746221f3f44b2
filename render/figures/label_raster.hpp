// Text drawn onto RGBA8 images on the CPU with stb_truetype (Debian's libstb) and the embedded
// DejaVu Sans: the labels of headless figures (domain view, sweep frames). UTF-8 text; one line.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace pw::render {
inline namespace figures {

struct TextStyle {
    float pixels = 18.0f;                           // line height in pixels
    std::array<uint8_t, 4> color{20, 24, 34, 255};  // RGBA
    bool box = false;                               // a filled box behind the text
    std::array<uint8_t, 4> boxColor{255, 255, 255, 215};
};

// An RGBA8 image the labels are drawn into (row-major, top row first).
struct PixelImage {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t>& rgba;
};

class LabelRaster {
public:
    LabelRaster();  // parses the embedded font; throws std::runtime_error if it cannot
    ~LabelRaster();
    LabelRaster(const LabelRaster&) = delete;
    LabelRaster& operator=(const LabelRaster&) = delete;

    // Width and height in pixels of `text` at `pixels` line height.
    std::array<float, 2> measure(std::string_view text, float pixels) const;
    // Draws `text` with its anchor point at (x, y): ax, ay pick the anchor within the text's box
    // (0, 0 top left; 0.5, 0.5 centre; 1, 1 bottom right). Clipped to the image.
    void draw(PixelImage image, float x, float y, std::string_view text, const TextStyle& style, float ax = 0.0f, float ay = 0.0f) const;

private:
    struct Font;
    std::unique_ptr<Font> font_;
};

// Pixels of an RGBA8 image: `c` blended over the pixel with `coverage` (0..1) times its alpha
// (outside the image: nothing), and a rectangle [x0, x1) x [y0, y1) filled so.
void blendPixel(PixelImage& img, int x, int y, const std::array<uint8_t, 4>& c, float coverage);
void fillRect(PixelImage& img, float x0, float y0, float x1, float y1, const std::array<uint8_t, 4>& c);

// The code points of UTF-8 text (invalid bytes become U+FFFD).
std::vector<uint32_t> decodeUtf8(std::string_view text);

}  // namespace figures
}  // namespace pw::render

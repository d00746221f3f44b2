#include "core/model/height_map.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"

namespace pw {
inline namespace model {

namespace {
constexpr uint32_t kMaxSide = 8192;
}

double HeightMap::texel(int64_t x, int64_t y) const {
    x = std::clamp<int64_t>(x, 0, int64_t(width) - 1);
    y = std::clamp<int64_t>(y, 0, int64_t(height) - 1);
    return texels[size_t(y) * width + size_t(x)] / 65535.0;
}

double HeightMap::sample(double u, double v) const {
    if (empty()) return 0.0;
    const double x = u * width - 0.5, y = v * height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double fx = x - x0, fy = y - y0;
    const auto ix = int64_t(x0), iy = int64_t(y0);
    const double a = texel(ix, iy) * (1 - fx) + texel(ix + 1, iy) * fx;
    const double b = texel(ix, iy + 1) * (1 - fx) + texel(ix + 1, iy + 1) * fx;
    return a * (1 - fy) + b * fy;
}

HeightMap loadHeightMap(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::string bytes = readFileLimited(path);  // InputError naming the file when unreadable
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int len = int(std::min<size_t>(bytes.size(), size_t(INT32_MAX)));
    int w = 0, h = 0, comp = 0;
    if (bytes.size() < 8 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
        throw InputError(name, "not a PNG file (a height map is an 8- or 16-bit PNG)");
    if (!stbi_info_from_memory(data, len, &w, &h, &comp)) throw InputError(name, std::string("unreadable PNG: ") + stbi_failure_reason());
    if (w < 1 || h < 1 || uint32_t(w) > kMaxSide || uint32_t(h) > kMaxSide)
        throw InputError(name, "height map is " + std::to_string(w) + " x " + std::to_string(h) + "; the limit is 8192 x 8192");
    HeightMap m;
    m.width = uint32_t(w);
    m.height = uint32_t(h);
    m.source = name;
    m.bits = stbi_is_16_bit_from_memory(data, len) ? 16 : 8;
    m.texels.resize(size_t(w) * size_t(h));
    if (m.bits == 16) {
        stbi_us* px = stbi_load_16_from_memory(data, len, &w, &h, &comp, 1);
        if (!px) throw InputError(name, std::string("unreadable PNG: ") + stbi_failure_reason());
        std::copy(px, px + m.texels.size(), m.texels.begin());
        stbi_image_free(px);
    } else {
        stbi_uc* px = stbi_load_from_memory(data, len, &w, &h, &comp, 1);
        if (!px) throw InputError(name, std::string("unreadable PNG: ") + stbi_failure_reason());
        for (size_t i = 0; i < m.texels.size(); ++i) m.texels[i] = uint16_t(px[i] * 257u);
        stbi_image_free(px);
    }
    return m;
}

HeightMap heightMapFromValues(uint32_t width, uint32_t height, const std::vector<double>& values, std::string source) {
    HeightMap m;
    m.width = width;
    m.height = height;
    m.bits = 16;
    m.source = std::move(source);
    m.texels.resize(size_t(width) * height);
    for (size_t i = 0; i < m.texels.size() && i < values.size(); ++i)
        m.texels[i] = uint16_t(std::lround(std::clamp(values[i], 0.0, 1.0) * 65535.0));
    return m;
}

std::vector<HeightMap> heightMipChain(const HeightMap& map, int levels) {
    std::vector<HeightMap> out;
    out.reserve(size_t(std::max(levels, 0)));  // `prev` points into it
    const HeightMap* prev = &map;
    for (int l = 1; l <= levels && !prev->empty() && (prev->width > 1 || prev->height > 1); ++l) {
        HeightMap m;
        m.width = std::max(1u, prev->width / 2);
        m.height = std::max(1u, prev->height / 2);
        m.bits = 16;
        m.source = map.source;
        m.texels.resize(size_t(m.width) * m.height);
        for (uint32_t y = 0; y < m.height; ++y)
            for (uint32_t x = 0; x < m.width; ++x) {
                // The 2 x 2 texels above (one of them where that side is 1 texel): a box filter.
                const uint32_t x0 = std::min(2 * x, prev->width - 1), x1 = std::min(2 * x + 1, prev->width - 1);
                const uint32_t y0 = std::min(2 * y, prev->height - 1), y1 = std::min(2 * y + 1, prev->height - 1);
                const auto at = [&](uint32_t tx, uint32_t ty) { return uint32_t(prev->texels[size_t(ty) * prev->width + tx]); };
                m.texels[size_t(y) * m.width + x] = uint16_t((at(x0, y0) + at(x1, y0) + at(x0, y1) + at(x1, y1) + 2) / 4);
            }
        out.push_back(std::move(m));
        prev = &out.back();
    }
    return out;
}

}  // namespace model
}  // namespace pw

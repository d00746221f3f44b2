#include "png_writer.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO_UNUSED
#include <stb/stb_image_write.h>

#include "errors.hpp"

namespace pw::render {

void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba) {
    if (rgba.size() < size_t(width) * height * 4) throw OutputError(path.string(), "image buffer too small");
    std::vector<uint8_t> opaque(rgba.begin(), rgba.begin() + size_t(width) * height * 4);
    for (size_t i = 3; i < opaque.size(); i += 4) opaque[i] = 255;
    if (!stbi_write_png(path.string().c_str(), int(width), int(height), 4, opaque.data(), int(width * 4)))
        throw OutputError(path.string(), "cannot write PNG (missing directory or no permission?)");
}

}  // namespace pw::render

#include "render/targets/png_writer.hpp"

#include <stb/stb_image_write.h>  // Debian's libstb (linked through pkg-config `stb`)

#include <string>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"

namespace pw::render {
inline namespace targets {

std::string encodePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba) {
    if (rgba.size() < size_t(width) * height * 4) throw OutputError(path.string(), "image buffer too small");
    std::vector<uint8_t> opaque(rgba.begin(), rgba.begin() + size_t(width) * height * 4);
    for (size_t i = 3; i < opaque.size(); i += 4) opaque[i] = 255;
    std::string png;
    const auto append = [](void* out, void* data, int size) {
        static_cast<std::string*>(out)->append(static_cast<char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &png, int(width), int(height), 4, opaque.data(), int(width * 4)))
        throw OutputError(path.string(), "PNG encoding failed");
    return png;
}

void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba) {
    writeFileAtomic(path, encodePng(path, width, height, rgba));
}

}  // namespace targets
}  // namespace pw::render

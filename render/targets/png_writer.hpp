// PNG output of RGBA8 pixels (stb_image_write). Throws pw::OutputError naming the path on failure.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pw::render {
inline namespace targets {

// The PNG file's bytes (alpha forced opaque); throws OutputError naming `path` when it cannot.
std::string encodePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba);
// encodePng, then writeFileAtomic.
void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba);

}  // namespace targets
}  // namespace pw::render

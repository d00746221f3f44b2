// PNG output of RGBA8 pixels (stb_image_write). Throws pw::OutputError naming the path on failure.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace pw::render {

void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba);

}  // namespace pw::render

// A 16-bit greyscale PNG writer for height-map tests and for regenerating data/terrain.png:
// stored deflate blocks, so no compression library (stb_image_write has no 16-bit PNGs).
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace pw::test {

namespace png16_detail {

inline uint32_t crc32(const std::string& bytes) {
    uint32_t c = 0xffffffffu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

inline void putBigEndian(std::string& out, uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(char((v >> s) & 0xff));
}

}  // namespace png16_detail

// w x h values, row-major (row 0 at the top).
inline void writeGreyPng16(const std::filesystem::path& file, uint32_t w, uint32_t h, const std::vector<uint16_t>& values) {
    using namespace png16_detail;
    std::string raw;  // filter byte 0, then big-endian samples, per row
    for (uint32_t y = 0; y < h; ++y) {
        raw.push_back(0);
        for (uint32_t x = 0; x < w; ++x) {
            const uint16_t v = values[size_t(y) * w + x];
            raw.push_back(char(v >> 8));
            raw.push_back(char(v & 0xff));
        }
    }
    std::string z = "\x78\x01";  // a zlib stream of stored blocks
    uint32_t a = 1, b = 0;
    for (unsigned char c : raw) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    for (size_t at = 0; at < raw.size(); at += 65535) {
        const size_t n = std::min<size_t>(65535, raw.size() - at);
        z.push_back(at + n >= raw.size() ? 1 : 0);
        z.push_back(char(n & 0xff));
        z.push_back(char(n >> 8));
        z.push_back(char(~n & 0xff));
        z.push_back(char((~n >> 8) & 0xff));
        z.append(raw, at, n);
    }
    putBigEndian(z, (b << 16) | a);
    auto chunk = [](std::string& out, const char* type, const std::string& data) {
        putBigEndian(out, uint32_t(data.size()));
        const std::string body = std::string(type, 4) + data;
        out += body;
        putBigEndian(out, crc32(body));
    };
    std::string ihdr;
    putBigEndian(ihdr, w);
    putBigEndian(ihdr, h);
    ihdr += std::string("\x10\x00\x00\x00\x00", 5);  // 16-bit greyscale, deflate, adaptive filters, no interlace
    std::string png = "\x89PNG\r\n\x1a\n";
    chunk(png, "IHDR", ihdr);
    chunk(png, "IDAT", z);
    chunk(png, "IEND", "");
    std::ofstream(file, std::ios::binary).write(png.data(), std::streamsize(png.size()));
}

}  // namespace pw::test

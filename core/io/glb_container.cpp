#include "core/io/glb_container.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "core/base/errors.hpp"

namespace pw {
inline namespace io {

namespace {
constexpr uint32_t kJsonChunk = 0x4E4F534Au;  // "JSON"
constexpr uint32_t kBinChunk = 0x004E4942u;   // "BIN\0"

uint32_t u32At(std::string_view data, size_t at) {
    uint32_t v = 0;
    std::memcpy(&v, data.data() + at, 4);
    return v;
}
}  // namespace

GlbParts splitGlb(std::string_view data, const std::string& name) {
    auto u32 = [&](size_t at) { return u32At(data, at); };
    if (data.size() < 20)
        throw InputError(name, "not a valid glTF binary (.glb) file: " + std::to_string(data.size()) + " bytes, shorter than its header");
    if (u32(4) != 2) throw InputError(name, "glTF binary version " + std::to_string(u32(4)) + "; Patchwork reads version 2");
    if (u32(8) > data.size())
        throw InputError(name, "not a valid glTF binary (.glb) file: its header says " + std::to_string(u32(8)) + " bytes, the file has " +
                                   std::to_string(data.size()));
    const uint32_t jsonLength = u32(12);
    if (u32(16) != kJsonChunk) throw InputError(name, "not a valid glTF binary (.glb) file: the first chunk is not JSON");
    if (jsonLength > data.size() - 20)
        throw InputError(name, "not a valid glTF binary (.glb) file: the JSON chunk says " + std::to_string(jsonLength) + " bytes, " +
                                   std::to_string(data.size() - 20) + " follow");
    return {data.substr(20, jsonLength), data.substr(20 + size_t(jsonLength))};
}

size_t binChunkBytes(std::string_view rest, const std::string& name) {
    if (rest.size() < 8 || u32At(rest, 4) != kBinChunk) return 0;
    const uint32_t length = u32At(rest, 0);
    if (length > rest.size() - 8)
        throw InputError(name, "not a valid glTF binary (.glb) file: the BIN chunk says " + std::to_string(length) + " bytes, " +
                                   std::to_string(rest.size() - 8) + " follow");
    return length;
}

std::string joinGlb(std::string json, std::string_view rest) { return joinGlb(std::move(json), std::vector<std::string_view>{rest}); }

std::string glbHead(std::string json, size_t restBytes) {
    while (!json.empty() && json.back() == ' ') json.pop_back();  // padding it came with
    while (json.size() % 4) json += ' ';
    if (20.0 + double(json.size()) + double(restBytes) > double(UINT32_MAX))
        throw std::length_error("the file would pass the 4 GiB a .glb can hold");
    std::string out;
    out.reserve(20 + json.size());
    auto put = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    out += "glTF";
    put(2);
    put(uint32_t(20 + json.size() + restBytes));
    put(uint32_t(json.size()));
    put(kJsonChunk);
    out += json;
    return out;
}

std::string joinGlb(std::string json, const std::vector<std::string_view>& rest) {
    size_t restBytes = 0;
    for (std::string_view r : rest) restBytes += r.size();
    std::string out = glbHead(std::move(json), restBytes);
    out.reserve(out.size() + restBytes);
    for (std::string_view r : rest) out.append(r);
    return out;
}

}  // namespace io
}  // namespace pw

// libFuzzer target: the Patchwork glTF importer (.gltf JSON and .glb). Any input either imports or
// throws InputError.
#include <cstdint>
#include <string_view>

#include "core/base/errors.hpp"
#include "core/io/gltf_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        (void)pw::parsePatchworkGltf(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.gltf");
    } catch (const pw::InputError&) {
    }
    return 0;
}

// libFuzzer target: the .patchwork JSON loader. Any input either loads or throws InputError; a
// loaded document saves and loads back identical.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/errors.hpp"
#include "core/patchwork_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    pw::Document doc;
    try {
        doc = pw::parseDocument(text, "fuzz.patchwork");
    } catch (const pw::InputError&) {
        return 0;
    }
    if (!(pw::parseDocument(pw::serializeDocument(doc), "fuzz-roundtrip.patchwork") == doc)) std::abort();
    return 0;
}

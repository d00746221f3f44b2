// libFuzzer target: the .patchwork JSON loader. Any input either loads or throws InputError; a
// loaded document saves and loads back identical.
#include "core/io/patchwork_format.hpp"
#include "fuzz/fuzz_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return pw::fuzz::loadAndRoundTrip(
        data, size, [](std::string_view text, const char* name) { return pw::parseDocument(text, name); },
        [](const pw::Document& d) { return pw::serializeDocument(d); },
        [](const pw::Document& a, const pw::Document& b) { return a == b; });
}

// libFuzzer target: the .bpt importer. Any input either parses or throws InputError; a parsed
// document survives formatBpt -> parseBpt with the same patch count.
#include "core/io/bpt_format.hpp"
#include "fuzz/fuzz_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return pw::fuzz::loadAndRoundTrip(
        data, size, [](std::string_view text, const char* name) { return pw::parseBpt(text, name); },
        [](const pw::Document& d) { return pw::formatBpt(d); },
        [](const pw::Document& a, const pw::Document& b) { return a.patches.size() == b.patches.size(); });
}

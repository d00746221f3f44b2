// libFuzzer target: the .bpt importer. Any input either parses or throws InputError; a parsed
// document survives formatBpt -> parseBpt with the same patch count.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/bpt_format.hpp"
#include "core/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    pw::Document doc;
    try {
        doc = pw::parseBpt(text, "fuzz.bpt");
    } catch (const pw::InputError&) {
        return 0;
    }
    const pw::Document again = pw::parseBpt(pw::formatBpt(doc), "fuzz-roundtrip.bpt");
    if (again.patches.size() != doc.patches.size()) std::abort();
    return 0;
}

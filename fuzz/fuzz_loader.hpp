// What every loader's fuzz target checks: the input either loads or throws InputError (anything
// else, or a crash, is a finding), and a loaded document written back and loaded again keeps what
// `same` compares.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/base/errors.hpp"
#include "core/model/document.hpp"

namespace pw::fuzz {

template <class Parse, class Format, class Same>
int loadAndRoundTrip(const uint8_t* data, size_t size, Parse parse, Format format, Same same) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Document doc;
    try {
        doc = parse(text, "fuzz-input");
    } catch (const InputError&) {
        return 0;
    }
    if (!same(parse(format(doc), "fuzz-roundtrip"), doc)) std::abort();
    return 0;
}

}  // namespace pw::fuzz

// libFuzzer target: the STEP and IGES value check that runs before OpenCASCADE (core/io/cad_values).
// The first byte picks the format (even: STEP, odd: IGES); any input either passes or throws
// InputError with a line inside the file, and never crashes or hangs (the check is one pass).
#include <cstdint>
#include <string_view>

#include "core/base/errors.hpp"
#include "core/io/cad_values.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const bool step = data[0] % 2 == 0;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        pw::checkCadValues("fuzz.step", text, step);
    } catch (const pw::InputError& e) {
        size_t lines = 1;
        for (char c : text) lines += c == '\n';
        if (e.line() < 0 || size_t(e.line()) > lines) __builtin_trap();  // a line that is not in the file
    }
    return 0;
}

// Names of the small enums in files and on the command line: one table per enum, indexed by the
// enum's value, read both ways (enumName, parseEnum). The tables live next to their enums.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace pw {
inline namespace base {

template <typename E, size_t N>
std::string_view enumName(E value, const std::array<std::string_view, N>& names) {
    const auto i = static_cast<size_t>(value);
    return i < N ? names[i] : names[0];
}

template <typename E, size_t N>
std::optional<E> parseEnum(std::string_view name, const std::array<std::string_view, N>& names) {
    for (size_t i = 0; i < N; ++i)
        if (names[i] == name) return static_cast<E>(i);
    return std::nullopt;
}

}  // namespace base
}  // namespace pw

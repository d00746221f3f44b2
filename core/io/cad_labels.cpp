// Face names of CAD files (cad_labels.hpp).
#include "core/io/cad_labels.hpp"

#include <charconv>

namespace pw {
inline namespace io {

std::string cadFaceName(std::string_view kind, size_t index, const std::string& name) {
    return name.empty() ? std::string(kind) + " " + std::to_string(index) : name;
}

std::optional<size_t> cadFaceLabelIndex(std::string_view name, std::string_view kind) {
    if (name.size() <= kind.size() + 1 || name.substr(0, kind.size()) != kind || name[kind.size()] != ' ') return std::nullopt;
    const std::string_view digits = name.substr(kind.size() + 1);
    if (digits.size() > 1 && digits[0] == '0') return std::nullopt;  // "patch 012" is a name
    size_t n = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
    return n;
}

std::string cadSafeName(std::string_view name, size_t maxBytes, bool asciiOnly) {
    std::string out;
    for (size_t i = 0; i < name.size();) {
        const auto c = static_cast<unsigned char>(name[i]);
        // The length of this UTF-8 character (a stray byte counts as one).
        size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 1;
        if (i + len > name.size()) len = 1;
        std::string_view ch = name.substr(i, len);
        std::string piece = c < 0x20 || c == 0x7f ? std::string(" ") : asciiOnly && c >= 0x80 ? std::string("_") : std::string(ch);
        if (out.size() + piece.size() > maxBytes) break;
        out += piece;
        i += len;
    }
    return out;
}

std::string cadPartName(const std::vector<std::string>& itemNames) {
    std::optional<std::string> common;
    for (const std::string& name : itemNames) {
        if (name.empty()) continue;
        if (!common) {
            common = name;
            continue;
        }
        size_t n = 0;
        while (n < common->size() && n < name.size() && (*common)[n] == name[n]) ++n;
        common->resize(n);
    }
    if (!common) return {};
    // Trailing digits go when they are a numbering ("lid 0") or the start of numbers that differ
    // ("patch10", "patch11" → "patch1" in common); digits that belong to the name stay ("M8").
    const auto separator = [](char c) { return std::string_view(" _-.,:#").find(c) != std::string_view::npos; };
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    std::string& s = *common;
    size_t d = s.size();
    while (d > 0 && digit(s[d - 1])) --d;
    bool cutInside = false;
    for (const std::string& name : itemNames) cutInside = cutInside || (name.size() > s.size() && digit(name[s.size()]));
    if (d < s.size() && (cutInside || d == 0 || separator(s[d - 1]))) s.resize(d);
    while (!s.empty() && separator(s.back())) s.pop_back();
    return s;
}

}  // namespace io
}  // namespace pw

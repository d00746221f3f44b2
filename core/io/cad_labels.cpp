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
    while (!common->empty() && std::string_view(" _-.,:#0123456789").find(common->back()) != std::string_view::npos) common->pop_back();
    return *common;
}

}  // namespace io
}  // namespace pw

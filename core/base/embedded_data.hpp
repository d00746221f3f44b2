// Files compiled into the binary (see data/CMakeLists.txt).
#pragma once

#include <string_view>

namespace pw {
inline namespace base {
namespace embedded {
extern const std::string_view teapotBpt;  // data/teapot.bpt, the default document
extern const std::string_view uiFontTtf;  // DejaVu Sans (fonts-dejavu-core): figure labels, presentation fonts
}  // namespace embedded
}  // namespace base
}  // namespace pw

// The font bytes placed by embedded_font.S (see CMakeLists.txt), as a string_view.
#include <string_view>

extern "C" const char pw_embedded_font_begin[];
extern "C" const char pw_embedded_font_end[];

namespace pw {
inline namespace base {
namespace embedded {  // core/base/embedded_data.hpp
extern const std::string_view uiFontTtf{pw_embedded_font_begin, size_t(pw_embedded_font_end - pw_embedded_font_begin)};
}  // namespace embedded
}  // namespace base
}  // namespace pw

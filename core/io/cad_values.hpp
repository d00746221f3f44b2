// STEP (ISO 10303-21) and IGES values checked before OpenCASCADE sees them (issue 44): a number
// that is not finite (inf, nan, 1e309), larger in magnitude than limits::kMaxCadNumber, longer than
// limits::kMaxCadNumberDigits characters, a bare word where a value belongs (STEP), or an entity of
// more than limits::kMaxCadEntityValues values (a million-pole surface) is refused with an
// InputError naming the entity (#123 in STEP, the directory entry in IGES) and the line. OpenCASCADE
// loops or exhausts memory on such input; everything it would accept otherwise passes unchanged.
#pragma once

#include <string>
#include <string_view>

namespace pw {
inline namespace io {

void checkCadValues(const std::string& file, std::string_view text, bool step);

}  // namespace io
}  // namespace pw

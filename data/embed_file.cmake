# Writes INPUT as a C++ source defining `std::string_view NAME` (the file's bytes), at build time.
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" len)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${INPUT} by data/embed_file.cmake; do not edit.\n"
  "#include <string_view>\nnamespace pw {\ninline namespace base {\nnamespace embedded {  // core/base/embedded_data.hpp\n"
  "static const char k${NAME}[] = {${bytes} 0};\n"
  "extern const std::string_view ${NAME}{k${NAME}, sizeof(k${NAME}) - 1};\n}\n}\n}\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)

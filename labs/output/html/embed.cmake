# Writes a C++ header holding a file's bytes, so the program carries its page scripts and styles:
#   cmake -DINPUT=stepper.js -DOUTPUT=stepper_js.hpp -DNAME=stepper_js -P embed.cmake
# gives numlab::cli::html::stepper_js, a std::string_view of stepper.js's bytes.
file(READ "${INPUT}" hex HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
get_filename_component(source "${INPUT}" NAME)
file(WRITE "${OUTPUT}.tmp" "#pragma once\n// Generated from labs/output/html/${source} by embed.cmake at build time: edit that file.\n"
     "#include <string_view>\nnamespace numlab::cli::html {\n"
     "inline constexpr char ${NAME}_bytes[] = {${bytes}'\\0'};\n"
     "inline constexpr std::string_view ${NAME}{${NAME}_bytes, sizeof ${NAME}_bytes - 1};\n}\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")

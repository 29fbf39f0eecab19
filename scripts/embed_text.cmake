# Writes OUTPUT, a C++ file defining `const std::string_view arbc::embedded::SYMBOL` with the
# bytes of INPUT: a program kept in its own file (a Lua stand-in, where `luac -p`, editors and
# the gates read it) and compiled into a library. Run by arbc_embed_text (CMakeLists.txt) at
# build time: cmake -DINPUT=FILE -DOUTPUT=FILE.cc -DSYMBOL=NAME -P scripts/embed_text.cmake
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" digits)
math(EXPR size "${digits} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
string(REGEX REPLACE "(([^,]*,){16})" "\\1\n    " bytes "${bytes}")
file(RELATIVE_PATH shown "${CMAKE_SOURCE_DIR}" "${INPUT}")
file(WRITE "${OUTPUT}.tmp"
"// Generated from ${INPUT} by scripts/embed_text.cmake: edit that file, not this one.
#include <string_view>

namespace arbc::embedded {

namespace {
const char ${SYMBOL}Bytes[${size} + 1] = {
    ${bytes}'\\0'};
}  // namespace

extern const std::string_view ${SYMBOL};
const std::string_view ${SYMBOL}(${SYMBOL}Bytes, ${size});

}  // namespace arbc::embedded
")
# Only a changed file is rewritten, so that its dependants are not rebuilt for nothing.
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUTPUT}.tmp" "${OUTPUT}")
file(REMOVE "${OUTPUT}.tmp")

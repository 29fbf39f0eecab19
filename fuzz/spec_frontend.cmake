# The spec front end: parse and check (compiler/frontend/frontend.h). The grammar compiles with
# clang through a patched copy of the ANTLR headers (grammar/CMakeLists.txt says why).
arbc_fuzzer(spec_frontend_fuzz spec_frontend_fuzz.cc)
target_link_libraries(spec_frontend_fuzz PRIVATE arbc_frontend)

# Lua-to-value conversion (runtime/lua_value.h).
arbc_fuzzer(lua_value_fuzz lua_value_fuzz.cc)
target_link_libraries(lua_value_fuzz PRIVATE arbc_runtime)

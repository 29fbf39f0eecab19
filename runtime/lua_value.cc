#include "runtime/lua_value.h"

#include <lua.hpp>
#include <string_view>
#include <vector>

namespace arbc {

namespace {

void push_vec3(lua_State* L, const Eigen::Vector3d& p) {
  lua_createtable(L, 0, 3);
  lua_pushnumber(L, p.x());
  lua_setfield(L, -2, "x");
  lua_pushnumber(L, p.y());
  lua_setfield(L, -2, "y");
  lua_pushnumber(L, p.z());
  lua_setfield(L, -2, "z");
}

std::string lua_kind(lua_State* L, int index) {
  if (lua_isinteger(L, index)) return "integer";
  return lua_typename(L, lua_type(L, index));
}

std::optional<double> read_number(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TNUMBER) return std::nullopt;
  return lua_tonumber(L, index);
}

std::optional<Value> too_deep(std::string* why) {
  *why = "the value is nested too deeply";
  return std::nullopt;
}

// The string key of the table entry lua_next just pushed (key at -2), or empty.
std::string_view entry_key(lua_State* L) {
  if (lua_type(L, -2) != LUA_TSTRING) return {};  // lua_tolstring would convert a number key
  size_t len = 0;
  const char* s = lua_tolstring(L, -2, &len);
  return {s, len};
}

// Everything below reads tables raw (lua_next, lua_rawgeti): a metamethod would run Lua code
// that may raise, and Lua's longjmp would skip the destructors of the C++ values being built.
// Nothing here raises, so read_value may be called while C++ objects are alive.
char vec3_keys_key;  // registry slot of {"x", "y", "z"} (prepare_lua_values)

// xyz[k] = the number at key kNames[k] of the table at `index`, read raw; *named when any of
// the three keys is there. With the key strings kept in the registry: three raw lookups, no
// allocation. Without (a state prepare_lua_values never saw): a walk over every entry.
void read_named_components(lua_State* L, int index, std::optional<double> xyz[3], bool* named) {
  static const char* kNames[3] = {"x", "y", "z"};
  if (lua_rawgetp(L, LUA_REGISTRYINDEX, &vec3_keys_key) == LUA_TTABLE) {
    int keys = lua_gettop(L);
    for (int k = 0; k < 3; ++k) {
      lua_rawgeti(L, keys, k + 1);
      if (lua_rawget(L, index) != LUA_TNIL) *named = true;  // a present key has a value
      xyz[k] = read_number(L, -1);
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return;
  }
  lua_pop(L, 1);
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    std::string_view key = entry_key(L);
    for (int k = 0; k < 3; ++k) {
      if (key != kNames[k]) continue;
      *named = true;
      xyz[k] = read_number(L, -1);
    }
    lua_pop(L, 1);
  }
}

std::optional<Value> read_vec3(lua_State* L, int index, std::string* why) {
  if (!lua_checkstack(L, 4)) return too_deep(why);
  static const char* kNames[3] = {"x", "y", "z"};
  std::optional<double> xyz[3];
  bool named = false;
  read_named_components(L, index, xyz, &named);
  for (int k = 0; k < 3 && !named; ++k) {
    lua_rawgeti(L, index, k + 1);
    xyz[k] = read_number(L, -1);
    lua_pop(L, 1);
  }
  for (int k = 0; k < 3; ++k) {
    if (xyz[k]) continue;
    *why = std::string("expected vec3 ({x=, y=, z=} or {x, y, z}), component ") + kNames[k] +
           " is not a number";
    return std::nullopt;
  }
  return Value(Eigen::Vector3d(*xyz[0], *xyz[1], *xyz[2]));
}

std::optional<Value> read_record(lua_State* L, int index, const Type& t, std::string* why) {
  if (!lua_checkstack(L, 4)) return too_deep(why);
  std::vector<std::optional<Value>> values(t.fields.size());
  std::vector<std::string> errors(t.fields.size());
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    std::string_view key = entry_key(L);
    for (size_t i = 0; i < t.fields.size(); ++i) {
      if (key == t.fields[i].name) values[i] = read_value(L, -1, *t.fields[i].type, &errors[i]);
    }
    lua_pop(L, 1);
  }
  // The first bad field in the type's order, whatever order the table keeps its keys in.
  ValueRecord fields;
  for (size_t i = 0; i < t.fields.size(); ++i) {
    if (!values[i]) {
      *why = errors[i].empty() ? "missing field " + t.fields[i].name
                               : "field " + t.fields[i].name + ": " + errors[i];
      return std::nullopt;
    }
    fields.emplace(t.fields[i].name, std::move(*values[i]));
  }
  return Value(std::move(fields));
}

}  // namespace

void prepare_lua_values(lua_State* L) {
  lua_createtable(L, 3, 0);
  const char* names[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    lua_pushstring(L, names[k]);
    lua_rawseti(L, -2, k + 1);
  }
  lua_rawsetp(L, LUA_REGISTRYINDEX, &vec3_keys_key);
}

void push_value(lua_State* L, const Value& v) {
  luaL_checkstack(L, 4, "message too deeply nested");
  switch (v.kind()) {
    case Value::Kind::None:
      lua_pushnil(L);
      break;
    case Value::Kind::Bool:
      lua_pushboolean(L, v.as_bool());
      break;
    case Value::Kind::Int:
      lua_pushinteger(L, v.as_int());
      break;
    case Value::Kind::Float:
      lua_pushnumber(L, v.as_float());
      break;
    case Value::Kind::String: {
      const std::string& s = v.as_string();
      lua_pushlstring(L, s.data(), s.size());
      break;
    }
    case Value::Kind::Vec3:
      push_vec3(L, v.as_vec3());
      break;
    case Value::Kind::List: {
      const ValueList& items = v.as_list();
      lua_createtable(L, static_cast<int>(items.size()), 0);
      for (size_t i = 0; i < items.size(); ++i) {
        push_value(L, items[i]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
      }
      break;
    }
    case Value::Kind::Record: {
      const ValueRecord& fields = v.as_record();
      lua_createtable(L, 0, static_cast<int>(fields.size()));
      for (const auto& [name, field] : fields) {
        push_value(L, field);
        lua_setfield(L, -2, name.c_str());
      }
      break;
    }
  }
}

std::optional<Value> read_value(lua_State* L, int index, const Type& t, std::string* why) {
  index = lua_absindex(L, index);
  auto mismatch = [&]() -> std::optional<Value> {
    *why = "expected " + t.to_string() + ", got " + lua_kind(L, index);
    return std::nullopt;
  };
  switch (t.kind) {
    case Type::Kind::Bool:
      if (!lua_isboolean(L, index)) return mismatch();
      return Value(static_cast<bool>(lua_toboolean(L, index)));
    case Type::Kind::Int: {
      if (lua_type(L, index) != LUA_TNUMBER) return mismatch();
      lua_Integer i;
      if (lua_isinteger(L, index)) return Value(static_cast<int64_t>(lua_tointeger(L, index)));
      if (!lua_numbertointeger(lua_tonumber(L, index), &i) ||
          static_cast<double>(i) != lua_tonumber(L, index)) {
        return mismatch();
      }
      return Value(static_cast<int64_t>(i));
    }
    case Type::Kind::Float: {
      auto d = read_number(L, index);
      if (!d) return mismatch();
      return Value(*d);
    }
    case Type::Kind::String: {
      if (lua_type(L, index) != LUA_TSTRING) return mismatch();
      size_t len = 0;
      const char* s = lua_tolstring(L, index, &len);
      if (t.size > 0 && len > static_cast<size_t>(t.size)) {
        *why = "a string of " + std::to_string(len) + " bytes where " + t.to_string() +
               " holds at most " + std::to_string(t.size);
        return std::nullopt;
      }
      return Value(std::string(s, len));
    }
    case Type::Kind::Vec3:
      if (!lua_istable(L, index)) return mismatch();
      return read_vec3(L, index, why);
    case Type::Kind::List: {
      if (!lua_istable(L, index)) return mismatch();
      if (!lua_checkstack(L, 4)) return too_deep(why);
      lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, index));
      if (t.size > 0 && (t.fixed ? n != t.size : n > t.size)) {
        *why = "a list of " + std::to_string(n) + " elements where " + t.to_string() +
               (t.fixed ? " has exactly " : " holds at most ") + std::to_string(t.size);
        return std::nullopt;
      }
      ValueList items;
      items.reserve(static_cast<size_t>(n));
      for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, index, i);
        std::string inner;
        auto item = read_value(L, -1, *t.element, &inner);
        lua_pop(L, 1);
        if (!item) {
          *why = "element " + std::to_string(i) + ": " + inner;
          return std::nullopt;
        }
        items.push_back(std::move(*item));
      }
      return Value(std::move(items));
    }
    case Type::Kind::Record:
      if (!lua_istable(L, index)) return mismatch();
      return read_record(L, index, t, why);
  }
  return mismatch();
}

}  // namespace arbc

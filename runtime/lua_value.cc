#include "runtime/lua_value.h"

#include <lua.hpp>

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

}  // namespace

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
      return Value(std::string(s, len));
    }
    case Type::Kind::Vec3: {
      if (!lua_istable(L, index)) return mismatch();
      luaL_checkstack(L, 4, "message too deeply nested");
      double xyz[3];
      static const char* kNames[3] = {"x", "y", "z"};
      bool named = lua_getfield(L, index, "x") != LUA_TNIL;
      lua_pop(L, 1);
      for (int k = 0; k < 3; ++k) {
        if (named) {
          lua_getfield(L, index, kNames[k]);
        } else {
          lua_rawgeti(L, index, k + 1);
        }
        auto d = read_number(L, -1);
        lua_pop(L, 1);
        if (!d) {
          *why = std::string("expected vec3 ({x=, y=, z=} or {x, y, z}), component ") + kNames[k] +
                 " is not a number";
          return std::nullopt;
        }
        xyz[k] = *d;
      }
      return Value(Eigen::Vector3d(xyz[0], xyz[1], xyz[2]));
    }
    case Type::Kind::List: {
      if (!lua_istable(L, index)) return mismatch();
      luaL_checkstack(L, 4, "message too deeply nested");
      lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, index));
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
    case Type::Kind::Record: {
      if (!lua_istable(L, index)) return mismatch();
      luaL_checkstack(L, 4, "message too deeply nested");
      ValueRecord fields;
      for (const Field& f : t.fields) {
        lua_getfield(L, index, f.name.c_str());
        if (lua_isnil(L, -1)) {
          lua_pop(L, 1);
          *why = "missing field " + f.name;
          return std::nullopt;
        }
        std::string inner;
        auto field = read_value(L, -1, *f.type, &inner);
        lua_pop(L, 1);
        if (!field) {
          *why = "field " + f.name + ": " + inner;
          return std::nullopt;
        }
        fields.emplace(f.name, std::move(*field));
      }
      return Value(std::move(fields));
    }
  }
  return mismatch();
}

}  // namespace arbc

#include "runtime/data_claims.h"

#include <lua.hpp>

#include "runtime/lua_value.h"

namespace arbc {

namespace {

// The script's view of its host: PortMonitor.novalue() only (the prelude's "no value").
int install_claims_api(lua_State* L) {
  lua_newtable(L);
  lua_pushcfunction(L, LuaSandbox::raise_novalue);
  lua_setfield(L, -2, "novalue");
  lua_setglobal(L, "PortMonitor");
  prepare_lua_values(L);
  return 0;
}

struct Count {
  lua_Integer n = -1;
};

int count_claims(lua_State* L) {
  auto* out = static_cast<Count*>(lua_touserdata(L, 1));
  if (lua_getglobal(L, "Claims") == LUA_TTABLE) out->n = luaL_len(L, -1);
  return 0;
}

struct Evaluation {
  lua_Integer index = 0;  // from 1
  const Value* value = nullptr;
  bool holds = false;
};

int evaluate_claim(lua_State* L) {
  auto* e = static_cast<Evaluation*>(lua_touserdata(L, 1));
  lua_getglobal(L, "Claims");
  lua_rawgeti(L, -1, e->index);
  push_value(L, *e->value);
  lua_call(L, 1, 1);
  e->holds = lua_toboolean(L, -1);
  return 0;
}

}  // namespace

std::unique_ptr<DataClaims> DataClaims::load(const model::App& app, const std::string& text,
                                             const std::string& file, std::string* err) {
  std::unique_ptr<DataClaims> d(new DataClaims());
  d->claims_ = model::data_claims(app);
  d->sandbox_ = LuaSandbox::create(SandboxLimits{});
  if (!d->sandbox_) {
    *err = file + ": cannot create a Lua state within the memory cap";
    return nullptr;
  }
  LuaCall installed = d->sandbox_->protected_call(install_claims_api, nullptr);
  LuaCall ran = installed.ok() ? d->sandbox_->run_chunk(text, file) : installed;
  Count count;
  if (ran.ok()) ran = d->sandbox_->protected_call(count_claims, &count);
  if (!ran.ok()) {
    *err = file + ": does not load: " + ran.error + " (rebuild the app with `arbc build`)";
    return nullptr;
  }
  if (count.n != static_cast<lua_Integer>(d->claims_.size())) {
    *err = file + ": defines " + std::to_string(count.n) + " claims, app.json states " +
           std::to_string(d->claims_.size()) + " (rebuild the app with `arbc build`)";
    return nullptr;
  }
  return d;
}

DataClaims::Outcome DataClaims::evaluate(size_t i, const Value& emitted, std::string* why) {
  Evaluation e{static_cast<lua_Integer>(i) + 1, &emitted};
  LuaCall call = sandbox_->protected_call(evaluate_claim, &e);
  if (call.status == LuaCall::Status::NoValue) {
    *why = "it reads a value that does not exist";
    return Outcome::NoValue;
  }
  if (!call.ok()) {
    *why = call.error;
    return Outcome::Error;
  }
  return e.holds ? Outcome::Holds : Outcome::Fails;
}

}  // namespace arbc

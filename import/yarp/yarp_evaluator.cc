#include "import/yarp/yarp_evaluator.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <lua.hpp>

#include "import/yarp/minimal_dnf.h"

namespace arbc::yarp {
namespace {

bool is_keyword(const std::string& t) {
  return t == "true" || t == "false" || t == "and" || t == "or" || t == "not";
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  // MonitorLua::searchReplace: scanning resumes after the replacement.
  size_t pos = 0;
  while ((pos = s.find(from, pos)) != std::string::npos) {
    s.replace(pos, from.size(), to);
    pos += to.size();
  }
}

// MonitorLua::trimString: spaces only, not tabs or newlines.
std::string trim_spaces(std::string_view s) {
  size_t b = s.find_first_not_of(' ');
  if (b == std::string_view::npos) return "";
  size_t e = s.find_last_not_of(' ');
  return std::string(s.substr(b, e - b + 1));
}

struct EvalArgs {
  const std::string* code;
  YarpVerdict* verdict;
};

int run_return(lua_State* L) {
  auto* a = static_cast<EvalArgs*>(lua_touserdata(L, 1));
  if (luaL_loadbufferx(L, a->code->data(), a->code->size(), "=constraint", "t") != LUA_OK ||
      lua_pcall(L, 0, 1, 0) != LUA_OK) {
    a->verdict->result = YarpVerdict::Result::LuaError;
    a->verdict->error = lua_isstring(L, -1) ? lua_tostring(L, -1) : "error";
    return 0;
  }
  if (!lua_isboolean(L, -1)) {
    a->verdict->result = YarpVerdict::Result::NotBoolean;
    a->verdict->error = std::string("the value is ") + luaL_typename(L, -1);
  } else {
    a->verdict->result =
        lua_toboolean(L, -1) ? YarpVerdict::Result::True : YarpVerdict::Result::False;
  }
  return 0;
}

}  // namespace

std::vector<std::string> yarp_lookups(std::string_view constraint) {
  std::string dummy = trim_spaces(constraint);
  std::replace(dummy.begin(), dummy.end(), '(', ' ');
  std::replace(dummy.begin(), dummy.end(), ')', ' ');
  dummy = " " + dummy + " ";
  std::vector<std::string> out;
  size_t pos;
  while ((pos = dummy.find(' ')) != std::string::npos) {
    std::string token = dummy.substr(0, pos);
    if (!token.empty() && !is_keyword(token)) out.push_back(token);
    dummy.erase(0, pos + 1);
  }
  return out;
}

std::string yarp_substitute(std::string_view constraint, const std::set<std::string>& present) {
  std::string text = trim_spaces(constraint);
  for (const std::string& token : yarp_lookups(constraint)) {
    replace_all(text, token, present.count(token) ? "true" : "false");
  }
  return text;
}

std::unique_ptr<YarpEvaluator> YarpEvaluator::create() {
  SandboxLimits limits;
  limits.memory_bytes = 4u << 20;
  limits.instructions = 100000;
  std::unique_ptr<LuaSandbox> box = LuaSandbox::create(limits);
  if (!box) return nullptr;
  return std::unique_ptr<YarpEvaluator>(new YarpEvaluator(std::move(box)));
}

YarpVerdict YarpEvaluator::evaluate(std::string_view constraint,
                                    const std::set<std::string>& present) {
  YarpVerdict v;
  if (trim_spaces(constraint).empty()) {  // no constraint: always accepted
    v.result = YarpVerdict::Result::True;
    return v;
  }
  v.text = yarp_substitute(constraint, present);
  std::string code = "return " + v.text;
  EvalArgs args{&code, &v};
  LuaCall call = box_->protected_call(run_return, &args);
  if (!call.ok()) {
    v.result = YarpVerdict::Result::LuaError;
    v.error = call.error;
  }
  return v;
}

namespace {

// The state of `events` encoded by the bits of `mask`.
std::set<std::string> state_of(const std::vector<std::string>& events, unsigned mask) {
  std::set<std::string> present;
  for (size_t i = 0; i < events.size(); ++i) {
    if (mask & (1u << i)) present.insert(events[i]);
  }
  return present;
}

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

ConstraintMeaning constraint_meaning(YarpEvaluator& evaluator, std::string_view text) {
  ConstraintMeaning m;
  m.text = trim_spaces(text);
  ConstraintParse parse = parse_constraint(m.text.empty() ? "true" : m.text);
  m.parsed = parse.ok;
  if (parse.ok) {
    m.written = parse.constraint;
  } else {
    m.parse_error = parse.error + " (at byte " + std::to_string(parse.offset) + ")";
  }
  std::vector<std::string> lookups = yarp_lookups(m.text);
  std::set<std::string> distinct(lookups.begin(), lookups.end());
  m.events.assign(distinct.begin(), distinct.end());
  m.yarp = m.parsed ? m.written : Constraint::constant(false);
  if (m.events.size() > kMaxSimulatedEvents) return m;
  m.simulated = true;
  // States by number of events present, so the first difference found is a smallest one.
  std::vector<unsigned> masks(1u << m.events.size());
  for (unsigned i = 0; i < masks.size(); ++i) masks[i] = i;
  std::stable_sort(masks.begin(), masks.end(),
                   [](unsigned a, unsigned b) { return std::popcount(a) < std::popcount(b); });
  std::vector<unsigned> accepted;
  for (unsigned mask : masks) {
    std::set<std::string> present = state_of(m.events, mask);
    YarpVerdict v = evaluator.evaluate(m.text, present);
    if (v.accepts()) accepted.push_back(mask);
    bool written = m.parsed && evaluate(m.written, present);
    if (!m.differs && (!m.parsed || v.accepts() != written)) {
      m.differs = true;
      m.witness.assign(present.begin(), present.end());
      m.witness_verdict = v;
      m.written_at_witness = written;
    }
  }
  if (m.differs) m.yarp = minimal_dnf(m.events, accepted);
  return m;
}

}  // namespace arbc::yarp

namespace arbc::yarp {

Corruption first_corruption(std::string_view constraint, const std::set<std::string>& present) {
  std::string text = trim_spaces(constraint);
  for (const std::string& token : yarp_lookups(constraint)) {
    const std::string value = present.count(token) ? "true" : "false";
    size_t pos = 0;
    while ((pos = text.find(token, pos)) != std::string::npos) {
      bool starts = pos == 0 || !word_char(text[pos - 1]);
      bool ends = pos + token.size() >= text.size() || !word_char(text[pos + token.size()]);
      if (!starts || !ends) {
        size_t b = pos, e = pos + token.size();
        while (b > 0 && word_char(text[b - 1])) --b;
        while (e < text.size() && word_char(text[e])) ++e;
        return {token, text.substr(b, e - b), true};
      }
      text.replace(pos, token.size(), value);
      pos += value.size();
    }
  }
  return {};
}

}  // namespace arbc::yarp

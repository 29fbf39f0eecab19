#include "import/yarp/monitor_analysis.h"

#include "import/yarp/app_xml.h"
#include "import/yarp/lua_lexer.h"
#include "import/yarp/lua_parser.h"

namespace arbc::yarp {
namespace {

// String and number literals of the script, to build sample bottles from.
void literals(const std::string& text, std::set<std::string>& strings, std::set<double>& numbers) {
  std::optional<std::vector<LuaToken>> tokens = lua_tokens(text, nullptr);
  if (!tokens) return;
  for (const LuaToken& t : *tokens) {
    if (t.kind == LuaToken::Kind::String && t.text.size() <= 64) strings.insert(t.text);
    if (t.kind == LuaToken::Kind::Number) numbers.insert(t.number);
  }
}

}  // namespace

MonitorAnalysis analyse_monitor(const std::string& path, const std::string& text,
                                const MonitorContext& context, const Carrier& carrier,
                                const model::SourceLocation& carrier_loc) {
  MonitorAnalysis m;
  m.path = path;
  m.text = text;
  std::string err;
  std::shared_ptr<LuaFunction> chunk = parse_lua(text, &err);
  if (chunk) {
    m.parsed = true;
    m.facts = analyse_script(*chunk);
  } else {
    m.parse_error = err;
    m.facts.opaque = true;
    m.facts.opaque_reason = "arbc's Lua reader stopped at line " + err;
  }
  std::set<std::string> strings;
  std::set<double> numbers;
  literals(text, strings, numbers);
  m.run = run_script(text, path, context, sample_bottles(strings, numbers));
  for (const SampleRun& s : m.run.samples) {
    for (const RecordedCall& c : s.calls) {
      if (c.function == "setEvent") m.observed_sets.insert(c.text);
      if (c.function == "unsetEvent") m.observed_unsets.insert(c.text);
    }
  }
  if (m.run.constraint) {
    m.constraint = *m.run.constraint;
    m.has_constraint = true;
    m.constraint_loc = locate(path, text, m.run.constraint_line, "setConstraint");
  } else if (carrier.constraint) {
    m.constraint = *carrier.constraint;
    m.has_constraint = true;
    m.constraint_loc = carrier_loc;
  }
  return m;
}

}  // namespace arbc::yarp

#include "verify/data_pair.h"

#include "core/join.h"

namespace arbc::verify {

std::string core_lines_text(const std::vector<int>& lines, const std::string& rule) {
  if (lines.empty()) return "the values '" + rule + "' reads";
  std::vector<std::string> n;
  for (int l : lines) n.push_back(std::to_string(l));
  return std::string(lines.size() == 1 ? "the accept on line " : "the accepts on lines ") +
         join(n) + " of '" + rule + "'";
}

bool replay_accepts(const model::App& app, const MonitorRunner* runner,
                    const std::vector<const model::Connection*>& rules,
                    const std::vector<Value>& messages, const std::vector<int>& message_of,
                    MessageExample& example, std::string* why) {
  for (size_t i = 0; i < rules.size(); ++i) {
    const model::Connection& c = *rules[i];
    const Value& msg = messages[static_cast<size_t>(message_of[i])];
    const Type* msg_type = port_type_of(app, c.source);
    MonitorRun run;
    std::string err;
    if (!runner->run(c, msg, &run, &err)) {
      *why = "the monitor of '" + c.name + "' could not be run on " +
             spec_value_text(msg, msg_type) + ": " + err;
      return false;
    }
    if (!run.accepted) {
      *why = "Z3 says '" + c.name + "' accepts " + c.source + " = " +
             spec_value_text(msg, msg_type) + ", but its Lua monitor drops it (" +
             (run.reason.empty() ? "rejected" : run.reason) + ")";
      return false;
    }
    example.replay.push_back("'" + c.name + "' accepts it and delivers " +
                             spec_value_text(run.delivered, port_type_of(app, c.destination)));
  }
  return true;
}

Finding internal_data_error(const std::string& port, const model::SourceLocation& loc,
                            const std::string& what) {
  Finding f;
  f.check = kCheckInternal;
  f.severity = Severity::Error;
  f.port = port;
  f.loc = loc;
  f.message = "internal error: Z3 and the runtime's Lua monitors disagree: " + what +
              "; please report this bug";
  return f;
}

DataPair same_message_pair(DataQuery& data, const MonitorRunner* runner, const model::Connection& a,
                           const model::Connection& b) {
  DataPair d;
  if (a.source != b.source) return d;
  for (const model::Connection* c : {&a, &b}) {
    std::string why = data.opaque_reason(*c);
    if (!why.empty())
      d.notes.push_back(
          {"data not considered: '" + c->name + "' is opaque for data (" + why + ")", {}});
  }
  if (!d.notes.empty()) return d;
  DataWitness w;
  DataCore core;
  d.queries = 1;
  Answer ans = data.ask({{&a, nullptr}, {&b, nullptr}}, &w, &core);
  if (ans == Answer::Unknown) {
    d.kind = DataPair::Kind::Unknown;
    d.text = "whether '" + a.name + "' and '" + b.name + "' can accept the same message";
    return d;
  }
  if (ans == Answer::Unsat) {
    d.kind = DataPair::Kind::Exclusive;
    d.text = "'" + a.name + "' and '" + b.name + "': no " + a.source + " message passes both " +
             core_lines_text(core.accept_lines[0], a.name) + " and " +
             core_lines_text(core.accept_lines[1], b.name);
    return d;
  }
  MessageExample ex;
  ex.source = a.source;
  ex.value = spec_value_text(w.messages[0], port_type_of(data.app(), a.source));
  std::vector<std::string> assumed = w.assumed_state[0];
  assumed.insert(assumed.end(), w.assumed_state[1].begin(), w.assumed_state[1].end());
  d.kind = DataPair::Kind::Overlap;
  d.notes.push_back({"a message both accept: " + ex.source + " = " + ex.value, {}});
  if (!assumed.empty()) {
    // Monitor state is abstracted: the message needs that state, which a fresh monitor lacks.
    d.notes.push_back({"with monitor state " + join(assumed) +
                           " (abstracted: any value earlier messages could leave), so not "
                           "replayed",
                       {}});
  } else if (!runner) {
    d.notes.push_back({"not replayed (no monitor runner)", {}});
  } else {
    std::string why;
    if (!replay_accepts(data.app(), runner, {&a, &b}, w.messages, {0, 0}, ex, &why)) {
      d.kind = DataPair::Kind::Internal;
      d.text = why;
      return d;
    }
    d.notes.push_back({"replayed through the Lua monitors: " + join(ex.replay, "; "), {}});
  }
  if (assumed.empty()) d.message = w.messages[0];
  d.example = std::move(ex);
  return d;
}

}  // namespace arbc::verify

#include "compiler/frontend/foreign_words.h"

#include <initializer_list>

namespace arbc::frontend {

namespace {

struct Meaning {
  std::initializer_list<std::string_view> words;
  const char* how;
};

std::optional<std::string> look_up(std::initializer_list<Meaning> table, std::string_view word) {
  for (const Meaning& m : table)
    for (std::string_view w : m.words)
      if (w == word) return std::string(m.how);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> declaration_for_word(std::string_view word) {
  return look_up(
      {
          {{"feed", "feeds"},
           "an event fed from a stream is declared `event NAME = Module.port : PREDICATE [for "
           "D];`, events named in a stream of strings `events from Module.port { NAME, ... } "
           "lifetime D;`"},
          {{"monitor", "monitors"},
           "a monitor is the body of a rule, `arbitrate Module.port { NAME: from Module.port { "
           "BODY } }`, or of a connection, `connect Module.port -> Module.port { BODY }`"},
          {{"arbitrator", "arbiter", "arbitration", "mux", "selector"},
           "an arbitrated port is declared `arbitrate Module.port { RULES }`"},
          {{"rule", "rules"},
           "rules are written inside their port's block: `arbitrate Module.port { NAME: from "
           "Module.port [when CONSTRAINT]; }`"},
          {{"constraint", "constraints"},
           "a rule's constraint follows its `when`; one that holds in every state is `invariant "
           "CONSTRAINT;`"},
          {{"priority", "priorities"},
           "`arbitrate Module.port by priority { RULES }` ranks its rules, highest first"},
          {{"struct", "message", "msg", "record", "typedef"},
           "a message type is declared `type NAME = { FIELD: TYPE, ... };`"},
          {{"node", "component", "process"},
           "a module is declared `module NAME { in PORT: TYPE; out PORT: TYPE; }`"},
          {{"port", "topic", "in", "out", "input", "output"},
           "ports are declared inside their module: `module NAME { out PORT: TYPE; }`"},
          {{"let", "var", "define"}, "a named value outside a body is `const NAME = EXPR;`"},
      },
      word);
}

std::optional<std::string> statement_for_word(std::string_view word) {
  return look_up(
      {
          {{"setEvent"}, "an event is set with `set NAME [for D];`"},
          {{"unsetEvent"}, "an event is unset with `unset NAME;`"},
          {{"return"},
           "a body has no `return`: `accept CONDITION;` drops the messages that fail CONDITION, "
           "`emit EXPR;` gives the value delivered"},
          {{"drop", "reject", "filter", "discard", "require"},
           "`accept CONDITION;` drops the messages that fail CONDITION"},
          {{"publish", "send", "write", "deliver", "output", "forward"},
           "`emit EXPR;` gives the value delivered"},
          {{"rate", "limit", "period"}, "`throttle D;` delivers at most one message per D"},
          {{"const"}, "a name for the rest of the body is `let NAME = EXPR;`"},
          {{"while", "for", "foreach", "loop", "do"},
           "a body has no loops: it runs once per message, and `min_by`, `max_by` and `len` "
           "read a whole list"},
          {{"else"}, "`else` follows the `}` of an `if`: `if C { ... } else { ... }`"},
      },
      word);
}

}  // namespace arbc::frontend

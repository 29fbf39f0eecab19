#include "compiler/frontend/syntax_words.h"

#include <ArbcParser.h>

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "core/duration_literal.h"

namespace arbc::frontend {

using arbc_grammar::ArbcParser;

namespace {

const std::set<std::string> kOperators = {".",  "[", "-",  "*",  "/",  "%",   "+", "<",
                                          "<=", ">", ">=", "==", "!=", "and", "or"};

}  // namespace

// What the user was writing when the parser stopped, by grammar rule; rules not listed
// (expressions, port references...) defer to the enclosing rule.
const char* describe_rule(size_t rule) {
  switch (rule) {
    case ArbcParser::RuleAppDecl:
      return "the app declaration";
    case ArbcParser::RuleTypeDecl:
      return "the type declaration";
    case ArbcParser::RuleConstDecl:
      return "the constant declaration";
    case ArbcParser::RuleModuleDecl:
      return "the module declaration";
    case ArbcParser::RulePortDecl:
      return "the port declaration";
    case ArbcParser::RuleEventDecl:
      return "the event declaration";
    case ArbcParser::RuleDerivedEventDecl:
      return "the derived event declaration";
    case ArbcParser::RuleStatusEventsDecl:
      return "the `events from` declaration";
    case ArbcParser::RuleExclusiveDecl:
      return "the `exclusive` declaration";
    case ArbcParser::RuleInvariantDecl:
      return "the invariant";
    case ArbcParser::RuleArbitrateDecl:
      return "the `arbitrate` block";
    case ArbcParser::RuleRuleDecl:
      return "the rule";
    case ArbcParser::RuleConnectDecl:
      return "the `connect` declaration";
    case ArbcParser::RuleAssertDecl:
      return "the assertion";
    case ArbcParser::RuleNeverDecl:
      return "the `never` property";
    case ArbcParser::RuleOnlyAfterDecl:
      return "the `only ... after` property";
    case ArbcParser::RuleAssumeDecl:
      return "the `assume` declaration";
    case ArbcParser::RuleResourceDecl:
      return "the `resource` declaration";
    case ArbcParser::RuleResponseDecl:
      return "the `after ... within` property";
    case ArbcParser::RuleStableDecl:
      return "the `stable` property";
    case ArbcParser::RuleGivenDecl:
      return "the rate (`given`)";
    case ArbcParser::RuleStmt:
      return "the statement";
    case ArbcParser::RuleTestDecl:
      return "the test";
    case ArbcParser::RuleTestsForDecl:
      return "the `tests for` declaration";
    case ArbcParser::RuleTestStep:
      return "the test step";
    case ArbcParser::RuleFieldType:
      return "the record field";
    case ArbcParser::RuleFieldInit:
      return "the record field";
    default:
      return nullptr;
  }
}

std::string describe_context(antlr4::ParserRuleContext* ctx) {
  for (; ctx; ctx = dynamic_cast<antlr4::ParserRuleContext*>(ctx->parent)) {
    if (const char* d = describe_rule(ctx->getRuleIndex())) return d;
  }
  return "the spec";
}

antlr4::ParserRuleContext* enclosing(antlr4::ParserRuleContext* ctx, size_t rule) {
  for (; ctx; ctx = dynamic_cast<antlr4::ParserRuleContext*>(ctx->parent))
    if (ctx->getRuleIndex() == rule) return ctx;
  return nullptr;
}

extern const std::set<std::string> kDeclKeywords = {
    "app",       "use",       "type",      "const",   "module", "event", "events",
    "exclusive", "invariant", "arbitrate", "connect", "assert", "test",  "tests",
    "resource",  "never",     "only",      "assume",  "given",  "stable"};

// A token type as the user would name it.
std::string token_name(const antlr4::dfa::Vocabulary& vocabulary, size_t type) {
  switch (type) {
    case antlr4::Token::EOF:
      return "the end of the file";
    case ArbcParser::ID:
      return "a name";
    case ArbcParser::NUMBER:
      return "a number";
    case ArbcParser::DURATION:
      return "a duration such as 500ms";
    case ArbcParser::STRING:
      return "a string in double quotes";
    default:
      return vocabulary.getLiteralName(type);  // already quoted: 'when'
  }
}

std::string found_text(const antlr4::Token* token) {
  if (token->getType() == antlr4::Token::EOF) return "the end of the file";
  std::string text = token->getText();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return "'" + text + "'";
}

bool is_keyword(const antlr4::dfa::Vocabulary& vocabulary, const antlr4::Token* token) {
  std::string literal = vocabulary.getLiteralName(token->getType());
  return literal.size() > 2 && std::isalpha(static_cast<unsigned char>(literal[1]));
}

extern const std::vector<std::string> kStatementKeywords = {
    "let", "var", "accept", "set", "unset", "if", "emit", "throttle", "every", "script"};

Expected expected_tokens(antlr4::Parser* parser) {
  const antlr4::dfa::Vocabulary& vocabulary = parser->getVocabulary();
  Expected x;
  for (size_t type : parser->getExpectedTokens().toList()) {
    x.kinds.insert(type);
    std::string literal = vocabulary.getLiteralName(type);
    if (literal.size() >= 2) x.literals.insert(literal.substr(1, literal.size() - 2));
  }
  for (size_t type : x.kinds) {
    std::string literal = vocabulary.getLiteralName(type);
    if (literal.size() >= 2 && kOperators.count(literal.substr(1, literal.size() - 2))) continue;
    x.wanted.push_back(token_name(vocabulary, type));
  }
  return x;
}

// A test step that starts well ('at' or 'expect') but fits none of its forms. ANTLR reports
// this where its prediction failed, with the tokens that may start a step as the expected ones
// ("expected 'at' or 'expect', found '-'" under the `at` the user wrote): say instead which
// forms the step may take after the word it starts with.
void describe_test_step(const antlr4::Token* start, const antlr4::Token* offending,
                        const std::string& found, Diagnostic& d) {
  Diagnostic note;
  note.severity = Severity::Note;
  if (start->getText() == "at") {
    bool at_time = offending->getTokenIndex() == start->getTokenIndex() + 1;
    if (at_time) {
      d.message = "expected a time such as 100ms after 'at' in the test step, found " + found;
      if (offending->getText() == "-")
        d.message += " (times count from the start of the test: they cannot be negative)";
    } else {
      d.message =
          "expected 'Module.port <- VALUE;', 'set EVENT;' or 'unset EVENT;' after the time in "
          "the test step, found " +
          found;
    }
    note.message =
        "a timed step reads `at TIME Module.port <- VALUE;`, `at TIME set EVENT;` or `at TIME "
        "unset EVENT;`";
  } else {
    d.message = "this `expect` fits none of its forms, at " + found;
    note.message =
        "an expectation reads `expect Module.port receives VALUE [WINDOW];` (or `receives "
        "nothing`), `expect RULE drops [\"reason\"] [WINDOW];`, `expect RULE delivers [nothing] "
        "[WINDOW];`, `expect PROPERTY;` (a property over time), `expect exclusive Module.port;`, "
        "`expect assert Module.port: RULE -> CONDITION;` or `expect CONDITION WINDOW;`, where "
        "WINDOW is `at TIME` or `within T1..T2`";
  }
  d.notes.push_back(std::move(note));
}

// ": 1ms" for "1e-3" and "s": the duration the number and unit mean, as a literal; "" when
// none can be written (below the microsecond, which durations are not).
std::string exponent_free_duration(const std::string& number, const std::string& unit) {
  double scale = unit == "ms" ? 1e-3 : unit == "min" ? 60 : 1;
  double seconds = std::strtod(number.c_str(), nullptr) * scale;
  if (!(seconds >= 1e-6) || !std::isfinite(seconds)) return " (in ms, s or min)";
  return ": " + duration_literal(seconds);
}

}  // namespace arbc::frontend

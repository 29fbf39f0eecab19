#include "compiler/frontend/syntax_errors.h"

#include <ArbcParser.h>
#include <antlr4-runtime.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

#include "compiler/frontend/foreign_words.h"
#include "compiler/frontend/syntax_words.h"
#include "compiler/frontend/token_checks.h"
#include "compiler/frontend/unclosed_block.h"
#include "compiler/frontend/unit_words.h"
#include "core/check_ids.h"
#include "core/duration_literal.h"
#include "core/join.h"
#include "core/suggest.h"

namespace arbc::frontend {

using arbc_grammar::ArbcParser;

class SyntaxErrorCollector : public antlr4::BaseErrorListener {
 public:
  explicit SyntaxErrorCollector(std::string file) : file_(std::move(file)) {}

  void syntaxError(antlr4::Recognizer* recognizer, antlr4::Token* offending, size_t, size_t,
                   const std::string&, std::exception_ptr) override {
    if (first_) return;
    auto* parser = dynamic_cast<antlr4::Parser*>(recognizer);
    if (!parser || !offending) return;
    try {
      first_ = describe(parser, offending);
    } catch (const std::exception&) {
      // Describing is best effort; an ANTLR internal state we did not foresee must not turn a
      // user's syntax error into a crash.
      Diagnostic d;
      d.id = diag::Syntax.text();
      d.loc = token_location(offending, file_);
      d.message = "unexpected " + found_text(offending);
      first_ = d;
      return;
    }
    // At the real end of the file, point just past the last token rather than at an EOF
    // token whose position the chunked parse may have guessed.
    antlr4::Token* previous = parser->getTokenStream()->LT(-1);
    if (offending->getType() == antlr4::Token::EOF && !next_declaration_ && previous &&
        first_->loc.line == static_cast<int>(offending->getLine()) &&
        first_->loc.column == static_cast<int>(offending->getCharPositionInLine()) + 1) {
      first_->loc = token_location(previous, file_);
      first_->loc.column = first_->loc.end_column;
      first_->loc.end_column = first_->loc.column + 1;
    }
    if (offending->getType() == antlr4::Token::EOF && next_declaration_) {
      first_->loc = token_location(next_declaration_, file_);
      const std::string eof = "the end of the file";
      size_t at = first_->message.find(eof);
      if (at != std::string::npos)
        first_->message.replace(at, eof.size(), found_text(next_declaration_));
    }
  }

  std::optional<Diagnostic> first_;
  const antlr4::Token* next_declaration_ = nullptr;

 private:
  // The first syntax error as a user would say it: what was expected, in what, found what.
  Diagnostic describe(antlr4::Parser* parser, antlr4::Token* offending) {
    Expected x = expected_tokens(parser);
    // A declaration's first word (or the end of the file) where a block could close: a '}' is
    // missing. Declaration words are keywords, so no statement or expression can take them.
    // (The end of the file in the middle of a statement is that statement's error.)
    bool declaration_start = offending->getType() == antlr4::Token::EOF ||
                             kDeclKeywords.count(offending->getText()) ||
                             offending->getText() == "after";
    if (declaration_start && x.has("}")) {
      if (auto unclosed = describe_unclosed_block(parser->getTokenStream(), offending, file_))
        return *unclosed;
    }
    Diagnostic d;
    d.id = diag::Syntax.text();
    d.loc = token_location(offending, file_);
    if (describe_mistaken_operator(parser, offending, x, d)) return d;
    if (describe_keyword_after_declaring_word(parser, offending, d)) return d;
    if (describe_when_after_hold(parser, offending, d)) return d;
    if (describe_negated_absence(parser, offending, d)) return d;
    if (describe_misplaced_then(parser, offending, d)) return d;
    if (!describe_set_of_a_port(parser, offending, x, d) &&
        !describe_construct(parser, offending, x, d))
      describe_by_position(parser, offending, x, d);
    note_spaced_unit(parser, offending, d);
    note_nested_comment(parser, offending, d);
    // `accept len(objects) = 0;`: a lone `=` right after an operand, where no `=` may come, is
    // almost surely a comparison.
    antlr4::Token* before = parser->getTokenStream()->LT(-1);
    bool after_operand =
        before && (before->getType() == ArbcParser::ID || before->getType() == ArbcParser::NUMBER ||
                   before->getType() == ArbcParser::STRING || before->getText() == ")" ||
                   before->getText() == "]");
    if (offending->getText() == "=" && !x.has("=") && after_operand) {
      Diagnostic note;
      note.severity = Severity::Note;
      note.message = "to compare, write `==` (a single `=` only assigns, as in `NAME = VALUE;`)";
      d.notes.push_back(std::move(note));
    }
    return d;
  }

  // Operators of other languages where this one has its own: `o -> o.dist` for the lambda
  // `o => o.dist`, `let x == 1;` for `let x = 1;`. Each gets "did you mean", which an editor
  // offers as a fix of the operator alone.
  bool describe_mistaken_operator(antlr4::Parser* parser, const antlr4::Token* offending,
                                  const Expected& x, Diagnostic& d) {
    const std::string text = offending->getText();
    antlr4::Token* previous = parser->getTokenStream()->LT(-1);
    bool after_name = previous && previous->getType() == ArbcParser::ID;
    std::string meant;
    size_t rule = parser->getContext()->getRuleIndex();
    bool in_expression = rule != ArbcParser::RuleConnectDecl && rule != ArbcParser::RuleAssertDecl;
    if (text == "->" && !x.has("->") && after_name && in_expression) {
      // `->` joins ports in `connect` and a rule to its property in `assert`, nowhere else.
      d.message = "a lambda is written with '=>', not '->': `" + previous->getText() + " => ...`";
      meant = "=>";
    } else if (text == "==" && x.wanted.size() == 1 && x.has("=") && after_name) {
      // `let x == 1;`, `const K == 2;`: only '=' binds a name; '==' compares.
      d.message = "expected '=' after '" + previous->getText() + "' in " +
                  describe_context(parser->getContext()) + ", found '==': '=' gives a name its " +
                  "value, '==' compares two values";
      meant = "=";
    } else {
      return false;
    }
    Diagnostic note;
    note.severity = Severity::Note;
    note.message = "did you mean '" + meant + "'?";
    d.notes.push_back(std::move(note));
    return true;
  }

  // `event when;`: a keyword right after a word that only a name may follow. `event` starts
  // two declarations, so the parser fails before it expects the name and would say "expected a
  // declaration"; the word before the keyword says what was being named.
  bool describe_keyword_after_declaring_word(antlr4::Parser* parser, const antlr4::Token* offending,
                                             Diagnostic& d) {
    static const std::map<std::string, std::string> kNamedBy = {
        {"app", "the app declaration"},
        {"type", "the type declaration"},
        {"const", "the constant declaration"},
        {"module", "the module declaration"},
        {"event", "the event declaration"},
        {"let", "the statement"},
        {"var", "the statement"}};
    const antlr4::dfa::Vocabulary& vocabulary = parser->getVocabulary();
    // The token before the keyword, not LT(-1): a failed prediction leaves the stream at the
    // declaration's start.
    size_t index = offending->getTokenIndex();
    if (index == 0 || index > parser->getTokenStream()->size()) return false;
    antlr4::Token* previous = parser->getTokenStream()->get(index - 1);
    if (!is_keyword(vocabulary, offending) || !previous || !is_keyword(vocabulary, previous))
      return false;
    auto named = kNamedBy.find(previous->getText());
    if (named == kNamedBy.end()) return false;
    d.message = "expected a name in " + named->second + ", found " + found_text(offending);
    note_keyword_as_name(d);
    return true;
  }

  // `a: from M.p hold 1s when e;`: the rule's parts in the wrong order.
  bool describe_when_after_hold(antlr4::Parser* parser, const antlr4::Token* offending,
                                Diagnostic& d) {
    if (offending->getText() != "when" || !in_rule(parser->getContext(), ArbcParser::RuleRuleDecl))
      return false;
    antlr4::Token* hold = parser->getTokenStream()->LT(-2);
    if (!hold || hold->getText() != "hold") return false;
    d.message =
        "`when` goes before `hold` in a rule: write `NAME: from Module.port when CONSTRAINT "
        "hold D`";
    return true;
  }

  // `then set e for 1s` (the lifetime is the event's) and `{ ... } then set e` (the clause
  // goes before the body, with the rule's other clauses): docs/language.md#events-set-on-delivery.
  static bool describe_misplaced_then(antlr4::Parser* parser, const antlr4::Token* offending,
                                      Diagnostic& d) {
    antlr4::TokenStream* tokens = parser->getTokenStream();
    antlr4::Token* before = tokens->LT(-1);
    antlr4::Token* op = tokens->LT(-2);
    if (offending->getText() == "for" && op && (op->getText() == "set") && before &&
        enclosing(parser->getContext(), ArbcParser::RuleRuleDecl)) {
      d.message = "a `then set` lasts for the event's declared lifetime: declare it `event " +
                  before->getText() + " lifetime D;` and write `then set " + before->getText() +
                  "`";
      return true;
    }
    if (offending->getText() == "then" && before && before->getText() == "}" &&
        enclosing(parser->getContext(), ArbcParser::RuleArbitrateDecl)) {
      d.message =
          "`then set ...` goes before the rule's body: `NAME: from Module.port when C then set "
          "E { ... }`";
      return true;
    }
    return false;
  }

  // `never nav while not e_ok;`: the absence property reads one event, present; a rule kept
  // from delivering while an event is absent is what its `when` says.
  static bool describe_negated_absence(antlr4::Parser* parser, const antlr4::Token* offending,
                                       Diagnostic& d) {
    antlr4::TokenStream* tokens = parser->getTokenStream();
    antlr4::Token* before = tokens->LT(-1);
    antlr4::Token* rule = tokens->LT(-2);
    if (offending->getText() != "not" || !before || before->getText() != "while" || !rule ||
        !enclosing(parser->getContext(), ArbcParser::RuleNeverDecl))
      return false;
    antlr4::Token* event = tokens->LT(2);
    std::string name = event && event->getType() == ArbcParser::ID ? event->getText() : "EVENT";
    d.message = "`never RULE while EVENT` takes one event, not its negation: it says that '" +
                rule->getText() + "' never delivers while the event is present";
    Diagnostic note;
    note.severity = Severity::Note;
    note.message = "to keep '" + rule->getText() + "' from delivering while " + name +
                   " is absent, add `" + name + "` to its `when`: it is then never selected " +
                   "without it, which `arbc verify` proves in every state";
    d.notes.push_back(std::move(note));
    return true;
  }

  // What to do about a keyword written as a name.
  static void note_keyword_as_name(Diagnostic& d) {
    d.message += " (a keyword cannot be used as a name)";
    Diagnostic note;
    note.severity = Severity::Note;
    note.message = "choose another name; docs/language.md#lexical-structure lists the keywords";
    d.notes.push_back(std::move(note));
  }

  // `/* a /* b */ c */`: block comments do not nest, so the first `*/` ended the comment and
  // its rest reads as code. Seen as two `/*` in the text skipped just before the offending
  // token, which ends in `*/`.
  static void note_nested_comment(antlr4::Parser* parser, const antlr4::Token* offending,
                                  Diagnostic& d) {
    size_t index = offending->getTokenIndex();
    if (offending->getType() == antlr4::Token::EOF || index == 0 ||
        index > parser->getTokenStream()->size())
      return;
    const antlr4::Token* next = index + 1 < parser->getTokenStream()->size()
                                    ? parser->getTokenStream()->get(index + 1)
                                    : nullptr;
    if (offending->getText() == "*" && next && next->getText() == "/" &&
        next->getStartIndex() == offending->getStopIndex() + 1) {
      // A `*/` in code: the comment it was meant to close ended at an earlier `*/`.
      Diagnostic note;
      note.severity = Severity::Note;
      note.message =
          "this '*/' closes no comment: block comments do not nest, so an earlier '*/' closed "
          "it; use // for the inner comment";
      d.notes.push_back(std::move(note));
      return;
    }
    const antlr4::Token* previous = parser->getTokenStream()->get(index - 1);
    if (!previous || previous->getStopIndex() + 1 >= offending->getStartIndex()) return;
    std::string skipped = offending->getInputStream()->getText(
        antlr4::misc::Interval(previous->getStopIndex() + 1, offending->getStartIndex() - 1));
    size_t end = skipped.find_last_not_of(" \t\r\n");
    if (end == std::string::npos || end < 1 || skipped.compare(end - 1, 2, "*/") != 0) return;
    size_t first = skipped.find("/*");
    if (first == std::string::npos || skipped.find("/*", first + 2) == std::string::npos) return;
    Diagnostic note;
    note.severity = Severity::Note;
    note.message =
        "block comments do not nest: the first '*/' closed the comment, and the rest reads as "
        "code; use // for the inner comment";
    d.notes.push_back(std::move(note));
  }

  // `lifetime 0.5 s;`: the unit, apart from its number, reads as a name, and the message says
  // only what the parser expected there. Whatever the construct, the fix is to join them.
  // `hold 1e-3s` is the same parse (a number, then the unit as a name), though written without
  // a space: a duration's number has no exponent. The note then gives the duration as it is
  // written.
  void note_spaced_unit(antlr4::Parser* parser, const antlr4::Token* offending, Diagnostic& d) {
    antlr4::Token* previous = parser->getTokenStream()->LT(-1);
    if (!previous || previous->getType() != ArbcParser::NUMBER ||
        offending->getType() != ArbcParser::ID || previous->getLine() != offending->getLine())
      return;
    auto unit = duration_unit(offending->getText());
    if (!unit) return;
    Diagnostic note;
    note.severity = Severity::Note;
    std::string number = previous->getText();
    if (number.find_first_of("eE") == std::string::npos) {
      note.message = "a duration is written without a space: " + number + *unit;
    } else {
      note.message = "a duration's number is written without an exponent" +
                     exponent_free_duration(number, *unit);
    }
    d.notes.push_back(std::move(note));
  }

  // `at 0s set Bumper.hit;`: a port where `set` takes an event. Publishing on the port is the
  // step meant, or setting the event its feed would set.
  bool describe_set_of_a_port(antlr4::Parser* parser, const antlr4::Token* offending,
                              const Expected& x, Diagnostic& d) {
    antlr4::TokenStream* tokens = parser->getTokenStream();
    antlr4::Token* port = tokens->LT(-1);
    if (!enclosing(parser->getContext(), ArbcParser::RuleTestStep) || offending->getText() != "." ||
        !x.has(";") || !port || port->getType() != ArbcParser::ID || port->getTokenIndex() == 0)
      return false;
    std::string verb = tokens->get(port->getTokenIndex() - 1)->getText();
    if (verb != "set" && verb != "unset") return false;
    antlr4::Token* field = tokens->LT(2);
    bool named = field && field->getType() == ArbcParser::ID;
    std::string name = port->getText() + "." + (named ? field->getText() : "port");
    d.message = "`" + verb + "` takes an event, not a port such as " + name;
    d.loc = token_location(port, file_);
    if (named) d.loc.end_column += 1 + static_cast<int>(field->getText().size());
    Diagnostic note;
    note.severity = Severity::Note;
    note.message = "to publish on the port write `at TIME " + name +
                   " <- VALUE;`; to give an event directly, `at TIME " + verb + " EVENT;`";
    d.notes.push_back(std::move(note));
    return true;
  }

  // When the expected tokens show which construct comes next (a declaration, a port, a
  // statement, a type, an expression, a duration, a rule): "expected a statement ...".
  bool describe_construct(antlr4::Parser* parser, antlr4::Token* offending, const Expected& x,
                          Diagnostic& d) {
    antlr4::ParserRuleContext* ctx = parser->getContext();
    std::string found = found_text(offending);
    bool decl_start = false;
    for (const std::string& k : kDeclKeywords) decl_start |= x.has(k.c_str());
    if (decl_start || (x.kinds.size() == 1 && x.kinds.count(antlr4::Token::EOF))) {
      d.message =
          "expected a declaration (app, type, const, module, event, events, exclusive, "
          "invariant, never, only, assume, after, stable, given, arbitrate, connect, assert, "
          "resource, test or tests), found " +
          found;
      if (!note_foreign_word(declaration_for_word(offending->getText()), d))
        suggest_keyword(offending,
                        std::vector<std::string>(kDeclKeywords.begin(), kDeclKeywords.end()), d);
    } else if (x.has("in") && x.has("out")) {
      d.message =
          "expected a port declaration ('in NAME: TYPE;' or 'out NAME: TYPE;') or '}', "
          "found " +
          found;
      suggest_keyword(offending, {"in", "out"}, d);
    } else if (x.has("let") && x.has("emit")) {
      d.message =
          "expected a statement (let, var, accept, set, unset, if, emit, throttle, "
          "every, script) or '}', found " +
          found;
      if (!note_foreign_word(statement_for_word(offending->getText()), d))
        suggest_keyword(offending, kStatementKeywords, d);
    } else if (x.kinds.count(ArbcParser::ID) && x.has("{") &&
               (in_rule(ctx, ArbcParser::RuleTypeExpr) ||
                ctx->getRuleIndex() == ArbcParser::RuleTypeDecl ||
                ctx->getRuleIndex() == ArbcParser::RulePortDecl ||
                ctx->getRuleIndex() == ArbcParser::RuleFieldType)) {
      d.message = "expected a type such as float, vec3 or list<T>, found " + found;
    } else if (x.kinds.count(ArbcParser::NUMBER) && x.kinds.count(ArbcParser::STRING)) {
      d.message = "expected an expression in " + describe_context(ctx) + ", found " + found;
    } else if (x.kinds.count(ArbcParser::DURATION)) {
      d.message = "expected a duration such as 500ms, 1s or 2min, found " + found;
    } else if (ctx->getRuleIndex() == ArbcParser::RuleNeverDecl && x.has("after") &&
               offending->getText() == ";") {
      // `never RULE within D;`: the user forgot `two`, or the rule the window starts after.
      d.message = "expected 'after' in the `never` property, found ';'";
      Diagnostic note;
      note.severity = Severity::Note;
      note.message =
          "a spacing property reads `never two RULE within D;` (RULE never delivers twice less "
          "than D apart) or `never RULE within D after OTHER;` (nor less than D after OTHER)";
      d.notes.push_back(std::move(note));
    } else if (auto* step = enclosing(ctx, ArbcParser::RuleTestStep);
               step && step->getStart() && step->getStart()->getText() == "at" &&
               x.kinds.size() == 1 && x.has(".")) {
      // `at 1s sett e_face;`: a name where a port or set/unset goes, read as a port's module.
      // The name is what is wrong: point at it, not at the token after it.
      antlr4::Token* name = parser->getTokenStream()->LT(-1);
      bool named = name && name->getType() == ArbcParser::ID;
      const antlr4::Token* wrong = named ? name : offending;
      describe_test_step(step->getStart(), wrong, found_text(wrong), d);
      d.loc = token_location(wrong, file_);
      if (named) suggest_keyword(name, {"set", "unset"}, d);
    } else if (ctx->getRuleIndex() == ArbcParser::RuleTestStep && x.has("at") && x.has("expect") &&
               ctx->getStart() && ctx->getStart()->getTokenIndex() < offending->getTokenIndex()) {
      describe_test_step(ctx->getStart(), offending, found, d);
    } else if (ctx->getRuleIndex() == ArbcParser::RuleArbitrateDecl && x.has("}") &&
               x.kinds.count(ArbcParser::ID)) {
      d.message = "expected a rule ('NAME: from Module.port ...') or '}', found " + found;
    } else {
      return false;
    }
    return true;
  }

  // Otherwise by what was written before: a missing ';', a misspelled statement, a name, or
  // the few tokens that could come next.
  void describe_by_position(antlr4::Parser* parser, antlr4::Token* offending, const Expected& x,
                            Diagnostic& d) {
    antlr4::ParserRuleContext* ctx = parser->getContext();
    std::string context = describe_context(ctx);
    std::string found = found_text(offending);
    antlr4::Token* previous = parser->getTokenStream()->LT(-1);
    const std::vector<std::string>& wanted = x.wanted;
    if (std::find(wanted.begin(), wanted.end(), "';'") != wanted.end() &&
        (wanted.size() == 1 || (previous && (previous->getLine() < offending->getLine() ||
                                             offending->getType() == antlr4::Token::EOF)))) {
      d.message = "expected ';' after " + context;
      // Point just past the previous token, where the ';' belongs, as compilers do.
      if (previous && (previous->getLine() != offending->getLine() ||
                       offending->getType() == antlr4::Token::EOF)) {
        next_declaration_ = nullptr;  // the caret goes after the previous token
        d.loc = token_location(previous, file_);
        d.loc.column = d.loc.end_column;
        d.loc.end_column = d.loc.column + 1;
      } else {
        d.message += ", found " + found;
      }
    } else if (wanted.size() == 1 && wanted[0] == "'='" && previous &&
               previous->getType() == ArbcParser::ID &&
               ctx->getRuleIndex() == ArbcParser::RuleStmt && ctx->getStart() == previous) {
      // `emitt face;` parses as the start of an assignment `emitt = ...`.
      d.loc = token_location(previous, file_);
      d.message = "unknown statement '" + previous->getText() +
                  "': a statement is let, var, accept, set, unset, if, emit, throttle, every, "
                  "script, or an assignment NAME = VALUE;";
      if (!note_foreign_word(statement_for_word(previous->getText()), d))
        suggest_keyword(previous, kStatementKeywords, d);
    } else if (wanted.size() == 1 && x.kinds.count(ArbcParser::ID)) {
      d.message = "expected a name in " + context + ", found " + found;
      if (is_keyword(parser->getVocabulary(), offending)) note_keyword_as_name(d);
    } else if (!wanted.empty() && wanted.size() <= 6) {
      d.message = "expected " + join(wanted, ", ", " or ") + " in " + context + ", found " + found;
      if (x.kinds.count(ArbcParser::ID) && is_keyword(parser->getVocabulary(), offending))
        note_keyword_as_name(d);
      std::vector<std::string> keywords;
      for (const std::string& l : x.literals)
        if (!l.empty() && std::isalpha(static_cast<unsigned char>(l[0]))) keywords.push_back(l);
      suggest_keyword(offending, keywords, d);
    } else {
      d.message = "unexpected " + found + " in " + context;
    }
  }

  // Adds "did you mean 'module'?" when a misspelled keyword was written as a name.
  // A word from elsewhere (foreign_words.h): a note on how the spec language says it.
  static bool note_foreign_word(const std::optional<std::string>& how, Diagnostic& d) {
    if (!how) return false;
    Diagnostic note;
    note.severity = Severity::Note;
    note.message = *how;
    d.notes.push_back(std::move(note));
    return true;
  }

  void suggest_keyword(const antlr4::Token* offending, const std::vector<std::string>& keywords,
                       Diagnostic& d) {
    if (offending->getType() != ArbcParser::ID) return;
    if (auto best = closest_name(offending->getText(), keywords)) {
      Diagnostic note;
      note.severity = Severity::Note;
      note.message = "did you mean '" + *best + "'?";
      d.notes.push_back(std::move(note));
    }
  }

  std::string file_;
};

SyntaxErrors::SyntaxErrors(std::string file)
    : collector_(std::make_unique<SyntaxErrorCollector>(std::move(file))) {}
SyntaxErrors::~SyntaxErrors() = default;
antlr4::BaseErrorListener* SyntaxErrors::listener() { return collector_.get(); }
void SyntaxErrors::set_next_declaration(const antlr4::Token* token) {
  collector_->next_declaration_ = token;
}
const std::optional<Diagnostic>& SyntaxErrors::first_error() const { return collector_->first_; }

}  // namespace arbc::frontend

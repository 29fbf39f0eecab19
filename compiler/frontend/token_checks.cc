#include "compiler/frontend/token_checks.h"

#include <ArbcLexer.h>
#include <antlr4-runtime.h>

#include "compiler/frontend/unit_words.h"
#include "core/check_ids.h"

namespace arbc::frontend {

using arbc_grammar::ArbcLexer;

model::SourceLocation token_location(const antlr4::Token* token, const model::FileName& file) {
  model::SourceLocation loc;
  loc.file = file;
  loc.line = static_cast<int>(token->getLine());
  loc.column = static_cast<int>(token->getCharPositionInLine()) + 1;
  loc.end_line = loc.line;
  size_t length = token->getType() == antlr4::Token::EOF
                      ? 1
                      : token->getStopIndex() + 1 - token->getStartIndex();
  // A token spanning lines (an unterminated comment) underlines only its first character.
  // (getText() converts from UTF-32, so it is called only for the one token type that can.)
  if (token->getType() == ArbcLexer::UNTERMINATED_COMMENT) length = 1;
  loc.end_column = loc.column + static_cast<int>(length);
  return loc;
}

namespace {

Diagnostic error_at(const antlr4::Token* token, const std::string& file, std::string message,
                    DiagId id) {
  Diagnostic d;
  d.loc = token_location(token, file);
  d.message = std::move(message);
  d.id = id.text();
  return d;
}

// The printable form of a stray character, for messages.
std::string describe_char(const std::string& text) {
  if (text.size() == 1) {
    unsigned char c = static_cast<unsigned char>(text[0]);
    if (c < 0x20 || c == 0x7F) {
      char buffer[16];
      std::snprintf(buffer, sizeof buffer, "\\x%02X", c);
      return buffer;
    }
  }
  return text;
}

// The spec language's word for a C-style logical operator a newcomer may type (`!`, `&&`,
// `||`), or "" for any other character. `!=` is a token of its own and never reaches here.
std::string logic_word(const std::string& text) {
  if (text == "!") return "not";
  if (text == "&") return "and";
  if (text == "|") return "or";
  return "";
}

// A number with letters glued to it: a time unit spelled another way (`5sec`) gets the
// spelling to use; anything else (`0.40m`, `40cm`) is a unit the language does not have.
std::string bad_number_message(const std::string& text) {
  auto [digits, suffix] = split_number_suffix(text);
  if (auto unit = duration_unit(suffix))
    return "'" + text + "' is not a duration: write " + digits + *unit +
           " (durations end in ms, s or min)";
  return "'" + text +
         "' is not a number or a duration: a number carries no unit (write the bare number, in "
         "the unit the modules use), and durations end in ms, s or min (e.g. 500ms, 1s)";
}

// `'take'`: a string quoted as in Python or Lua. One error from the quote to its partner on
// the same line, with the string to write; returns the index of the last token it covers.
size_t report_single_quotes(const std::vector<antlr4::Token*>& tokens, size_t open,
                            const std::string& file, std::vector<Diagnostic>& out) {
  const antlr4::Token* t = tokens[open];
  size_t close = open + 1;
  while (close < tokens.size() && tokens[close]->getLine() == t->getLine() &&
         !(tokens[close]->getType() == ArbcLexer::ERROR_CHAR && tokens[close]->getText() == "'"))
    ++close;
  if (close >= tokens.size() || tokens[close]->getLine() != t->getLine()) {
    out.push_back(error_at(
        t, file, "unexpected character \"'\": strings are written in double quotes, \"like this\"",
        diag::BadCharacter));
    return open;
  }
  std::string inside = close == open + 1 && tokens[close]->getStartIndex() == t->getStartIndex() + 1
                           ? ""
                           : t->getInputStream()->getText(antlr4::misc::Interval(
                                 t->getStartIndex() + 1, tokens[close]->getStartIndex() - 1));
  Diagnostic d = error_at(
      t, file,
      "strings are written in double quotes: write \"" + inside + "\", not '" + inside + "'",
      diag::BadCharacter);
  d.loc.end_column = error_at(tokens[close], file, "", diag::BadCharacter).loc.end_column;
  // The note an editor turns into a quick fix that rewrites the quotes.
  Diagnostic note;
  note.severity = Severity::Note;
  note.message = "did you mean '\"" + inside + "\"'?";
  d.notes.push_back(std::move(note));
  out.push_back(std::move(d));
  return close;
}

}  // namespace

void check_lexical(const std::vector<antlr4::Token*>& tokens, const std::string& file,
                   std::vector<Diagnostic>& out) {
  for (size_t i = 0; i < tokens.size(); ++i) {
    const antlr4::Token* t = tokens[i];
    switch (t->getType()) {
      case ArbcLexer::BAD_NUMBER:
        out.push_back(error_at(t, file, bad_number_message(t->getText()), diag::BadNumber));
        break;
      case ArbcLexer::UNTERMINATED_STRING:
        out.push_back(error_at(t, file, "string literal is missing its closing '\"'",
                               diag::UnterminatedString));
        break;
      case ArbcLexer::UNTERMINATED_COMMENT:
        out.push_back(error_at(t, file, "comment opened with '/*' is never closed with '*/'",
                               diag::UnterminatedComment));
        break;
      case ArbcLexer::ERROR_CHAR: {
        std::string text = t->getText();
        if (text == "'") {
          i = report_single_quotes(tokens, i, file, out);
          break;
        }
        if (text == "?") {  // C's `c ? a : b`
          out.push_back(error_at(t, file,
                                 "'?' is not an operator of the spec language: choose with "
                                 "`if C { emit A; } else { emit B; }`",
                                 diag::BadCharacter));
          break;
        }
        std::string word = logic_word(text);
        if (word.empty()) {
          out.push_back(error_at(t, file,
                                 "unexpected character '" + describe_char(text) +
                                     "': names use only ASCII letters, digits and '_'",
                                 diag::BadCharacter));
          break;
        }
        // `&&` and `||` are one mistake: one error, underlining both characters.
        bool doubled = text != "!" && i + 1 < tokens.size() &&
                       tokens[i + 1]->getType() == ArbcLexer::ERROR_CHAR &&
                       tokens[i + 1]->getStartIndex() == t->getStopIndex() + 1 &&
                       tokens[i + 1]->getText() == text;
        Diagnostic d =
            error_at(t, file,
                     "'" + (doubled ? text + text : text) +
                         "' is not an operator of the spec language: write `" + word + "`",
                     diag::BadCharacter);
        if (doubled) {
          d.loc.end_column += 1;
          ++i;
        }
        out.push_back(std::move(d));
        break;
      }
      default:
        break;
    }
  }
}

bool check_nesting(const std::vector<antlr4::Token*>& tokens,
                   const antlr4::dfa::Vocabulary& vocabulary, const std::string& file,
                   std::vector<Diagnostic>& out) {
  // Token types by role, looked up once: comparing types avoids converting every token's
  // text back from UTF-32.
  enum Role : char { kOther, kOpen, kClose, kPrefix, kMinus, kArrow, kOperandEnd };
  std::vector<Role> role(vocabulary.getMaxTokenType() + 2, kOther);
  for (size_t type = 0; type <= vocabulary.getMaxTokenType(); ++type) {
    std::string literal = vocabulary.getLiteralName(type);
    if (literal == "'('" || literal == "'['" || literal == "'{'") role[type] = kOpen;
    if (literal == "')'" || literal == "']'" || literal == "'}'") role[type] = kClose;
    if (literal == "'not'") role[type] = kPrefix;
    if (literal == "'=>'") role[type] = kArrow;
    if (literal == "'-'") role[type] = kMinus;
    if (literal == "'true'" || literal == "'false'" || type == ArbcLexer::ID ||
        type == ArbcLexer::NUMBER || type == ArbcLexer::DURATION || type == ArbcLexer::STRING)
      role[type] = role[type] == kOther ? kOperandEnd : role[type];
  }
  // The parser recurses once per open bracket and once per prefix operator in an unbroken
  // run (`not not -x`, `a => b => c`); a run ends at the first other token. An open bracket
  // keeps the run before it on the stack until the bracket closes.
  std::vector<int> frozen;  // per open bracket: 1 + the run of prefix operators before it
  int depth = 0;            // sum of frozen
  int run = 0;              // prefix operators in the current unbroken run
  Role previous = kOther;
  for (const antlr4::Token* t : tokens) {
    size_t type = t->getType();
    Role r = type < role.size() ? role[type] : kOther;
    switch (r) {
      case kOpen:
        frozen.push_back(1 + run);
        depth += frozen.back();
        run = 0;
        break;
      case kClose:
        if (!frozen.empty()) {
          depth -= frozen.back();
          frozen.pop_back();
        }
        run = 0;
        break;
      case kPrefix:
      case kArrow:
        ++run;
        break;
      case kMinus:
        // Binary after an operand or a closing bracket, prefix otherwise.
        run = (previous == kOperandEnd || previous == kClose) ? 0 : run + 1;
        break;
      default:
        // A name right after `=>` may be the next lambda's parameter (`a => b => c`), so it
        // keeps the run going; anything else ends it.
        if (!(type == ArbcLexer::ID && previous == kArrow)) run = 0;
    }
    if (depth + run > kMaxNesting) {
      out.push_back(error_at(t, file,
                             "nesting is deeper than " + std::to_string(kMaxNesting) +
                                 " levels (brackets and prefix operators): split the expression "
                                 "with `let` or named constants",
                             diag::NestingTooDeep));
      return false;
    }
    previous = r;
  }
  return true;
}

}  // namespace arbc::frontend

#include "compiler/frontend/token_checks.h"

#include <ArbcLexer.h>
#include <antlr4-runtime.h>

namespace arbc::frontend {

using arbc_grammar::ArbcLexer;

model::SourceLocation token_location(const antlr4::Token* token, const std::string& file) {
  model::SourceLocation loc;
  loc.file = file;
  loc.line = static_cast<int>(token->getLine());
  loc.column = static_cast<int>(token->getCharPositionInLine()) + 1;
  loc.end_line = loc.line;
  size_t length = token->getType() == antlr4::Token::EOF
                      ? 1
                      : token->getStopIndex() + 1 - token->getStartIndex();
  // A token spanning lines (a block comment) underlines only its first character.
  if (token->getText().find('\n') != std::string::npos) length = 1;
  loc.end_column = loc.column + static_cast<int>(length);
  return loc;
}

namespace {

Diagnostic error_at(const antlr4::Token* token, const std::string& file, std::string message,
                    std::string id) {
  Diagnostic d;
  d.loc = token_location(token, file);
  d.message = std::move(message);
  d.id = std::move(id);
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

}  // namespace

void check_lexical(const std::vector<antlr4::Token*>& tokens, const std::string& file,
                   std::vector<Diagnostic>& out) {
  for (const antlr4::Token* t : tokens) {
    switch (t->getType()) {
      case ArbcLexer::BAD_NUMBER:
        out.push_back(error_at(t, file,
                               "'" + t->getText() +
                                   "' is not a number or a duration: durations end in ms, s or "
                                   "min (e.g. 500ms, 1s)",
                               "bad-number"));
        break;
      case ArbcLexer::UNTERMINATED_STRING:
        out.push_back(error_at(t, file, "string literal is missing its closing '\"'",
                               "unterminated-string"));
        break;
      case ArbcLexer::UNTERMINATED_COMMENT:
        out.push_back(error_at(t, file, "comment opened with '/*' is never closed with '*/'",
                               "unterminated-comment"));
        break;
      case ArbcLexer::ERROR_CHAR:
        out.push_back(error_at(t, file,
                               "unexpected character '" + describe_char(t->getText()) +
                                   "': names use only letters, digits and '_'",
                               "bad-character"));
        break;
      default:
        break;
    }
  }
}

namespace {

bool is_operand_end(size_t type) {
  switch (type) {
    case ArbcLexer::ID:
    case ArbcLexer::NUMBER:
    case ArbcLexer::DURATION:
    case ArbcLexer::STRING:
      return true;
    default:
      return false;
  }
}

}  // namespace

bool check_nesting(const std::vector<antlr4::Token*>& tokens, const std::string& file,
                   std::vector<Diagnostic>& out) {
  // Each open bracket is one level, and so is each prefix operator until the end of the
  // list item or statement it starts (`,` `;` or the closing bracket).
  struct Level {
    int prefix_ops = 0;
  };
  std::vector<Level> levels(1);
  int depth = 0;
  std::string previous;
  size_t previous_type = 0;
  for (const antlr4::Token* t : tokens) {
    std::string text = t->getText();
    size_t type = t->getType();
    bool prefix = false;
    if (type != ArbcLexer::STRING) {
      if (text == "(" || text == "[" || text == "{") {
        levels.push_back({});
        ++depth;
      } else if (text == ")" || text == "]" || text == "}") {
        if (levels.size() > 1) {
          depth -= 1 + levels.back().prefix_ops;
          levels.pop_back();
        }
      } else if (text == "," || text == ";") {
        depth -= levels.back().prefix_ops;
        levels.back().prefix_ops = 0;
      } else if (text == "not" || text == "=>") {
        prefix = true;
      } else if (text == "-") {
        bool after_operand = is_operand_end(previous_type) || previous == ")" ||
                             previous == "]" || previous == "}" || previous == "true" ||
                             previous == "false";
        prefix = !after_operand;
      }
    }
    if (prefix) {
      ++levels.back().prefix_ops;
      ++depth;
    }
    if (depth > kMaxNesting) {
      out.push_back(error_at(t, file,
                             "nesting is deeper than " + std::to_string(kMaxNesting) +
                                 " levels (brackets and prefix operators): split the expression "
                                 "with `let` or named constants",
                             "nesting-too-deep"));
      return false;
    }
    previous = std::move(text);
    previous_type = type;
  }
  return true;
}

}  // namespace arbc::frontend

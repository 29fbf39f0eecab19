#include "compiler/frontend/unclosed_block.h"

#include <antlr4-runtime.h>

#include <map>
#include <vector>

#include "compiler/frontend/token_checks.h"
#include "core/check_ids.h"

namespace arbc::frontend {

namespace {

size_t length(const antlr4::Token* t) { return t->getStopIndex() + 1 - t->getStartIndex(); }

// What opens the block at `open`, as written: the tokens since the end of the previous
// statement or declaration ("arbitrate Hand.cmd", "if obj.dist < 1.0", "else"), with the
// source's spacing between tokens of one line and one space across lines; long heads are cut.
std::string block_head(antlr4::TokenStream* tokens, size_t open) {
  size_t first = open;
  while (first > 0) {
    std::string text = tokens->get(first - 1)->getText();
    if (text == ";" || text == "{" || text == "}") break;
    --first;
  }
  std::string head;
  for (size_t i = first; i < open; ++i) {
    const antlr4::Token* t = tokens->get(i);
    if (i > first) {
      const antlr4::Token* before = tokens->get(i - 1);
      bool glued = before->getLine() == t->getLine() &&
                   before->getCharPositionInLine() + length(before) == t->getCharPositionInLine();
      if (!glued) head += ' ';
    }
    head += t->getText();
  }
  if (head.size() > 40) head = head.substr(0, 37) + "...";
  return head.empty() ? "{" : head + " {";
}

// `stable: from M.p ...;` in an `arbitrate` block: a keyword that starts a declaration,
// written as a rule's name. The parser takes it for the next declaration, so the block looks
// unclosed; the name is the mistake.
std::optional<Diagnostic> keyword_as_rule_name(antlr4::TokenStream* tokens,
                                               const antlr4::Token* stop, const std::string& file) {
  if (stop->getType() == antlr4::Token::EOF || stop->getTokenIndex() + 1 >= tokens->size() ||
      tokens->get(stop->getTokenIndex() + 1)->getText() != ":")
    return std::nullopt;
  Diagnostic d;
  d.id = diag::Syntax.text();
  d.loc = token_location(stop, file);
  d.message = "'" + stop->getText() +
              "' is a keyword, so it cannot name a rule: choose another name (such as '" +
              stop->getText() + "_rule')";
  Diagnostic note;
  note.severity = Severity::Note;
  note.message = "docs/language.md#lexical-structure lists the keywords";
  d.notes.push_back(std::move(note));
  return d;
}

}  // namespace

std::optional<Diagnostic> describe_unclosed_block(antlr4::TokenStream* tokens,
                                                  const antlr4::Token* stop,
                                                  const std::string& file) {
  std::vector<size_t> open;              // the '{' not closed yet, innermost last
  std::map<size_t, size_t> indentation;  // line -> column of its first token
  std::optional<size_t> suspect;         // the first '{' closed by a '}' indented unlike it
  const antlr4::Token* suspect_close = nullptr;
  for (size_t i = 0; i < stop->getTokenIndex(); ++i) {
    const antlr4::Token* t = tokens->get(i);
    bool starts_line = indentation.emplace(t->getLine(), t->getCharPositionInLine()).second;
    std::string text = t->getText();  // a string token keeps its quotes: never "{"
    if (text == "{") {
      open.push_back(i);
    } else if (text == "}" && !open.empty()) {
      size_t opener = open.back();
      open.pop_back();
      // With one '}' missing, the '}' written for the block that lacks it closes the block
      // around it instead: the first '}' whose indentation is not its '{' line's shows where.
      if (!suspect && starts_line &&
          indentation[tokens->get(opener)->getLine()] != t->getCharPositionInLine()) {
        suspect = opener;
        suspect_close = t;
      }
    }
  }
  if (open.empty()) return std::nullopt;
  if (auto named = keyword_as_rule_name(tokens, stop, file)) return named;

  const antlr4::Token* brace = tokens->get(open.back());
  bool at_end = stop->getType() == antlr4::Token::EOF;
  Diagnostic d;
  d.id = diag::Syntax.text();
  d.loc = token_location(brace, file);
  d.message = "the block `" + block_head(tokens, open.back()) + "` opened on line " +
              std::to_string(brace->getLine()) + " is not closed: a '}' is missing before " +
              (at_end ? std::string("the end of the file")
                      : "'" + stop->getText() + "' on line " + std::to_string(stop->getLine()));
  if (!at_end) {
    Diagnostic noticed;
    noticed.severity = Severity::Note;
    noticed.loc = token_location(stop, file);
    noticed.message = "noticed here: '" + stop->getText() +
                      "' starts a declaration, and declarations cannot be inside a block";
    d.notes.push_back(std::move(noticed));
  }
  if (suspect) {
    const antlr4::Token* inner = tokens->get(*suspect);
    Diagnostic note;
    note.severity = Severity::Note;
    note.loc = token_location(inner, file);
    note.message = "by the indentation, the '}' missing is probably this block's (`" +
                   block_head(tokens, *suspect) + "`): the '}' on line " +
                   std::to_string(suspect_close->getLine()) +
                   " that closes it is not indented like line " + std::to_string(inner->getLine());
    d.notes.push_back(std::move(note));
  }
  return d;
}

}  // namespace arbc::frontend

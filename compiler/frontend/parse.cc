#include "compiler/frontend/parse.h"

#include <ArbcLexer.h>
#include <ArbcParser.h>
#include <antlr4-runtime.h>

#include <algorithm>
#include <optional>
#include <set>
#include <thread>
#include <tuple>
#include <utility>

#include "compiler/frontend/ast_builder.h"
#include "compiler/frontend/lexed_text.h"
#include "compiler/frontend/parse_declarations.h"
#include "compiler/frontend/parse_halves.h"
#include "compiler/frontend/syntax_errors.h"
#include "compiler/frontend/token_checks.h"
#include "compiler/frontend/utf8.h"
#include "core/check_ids.h"

namespace arbc::frontend {

using arbc_grammar::ArbcLexer;
using arbc_grammar::ArbcParser;

namespace {

const std::set<std::string> kDeclStarts = {
    "app",       "use",       "type",      "const",   "module", "events", "event",
    "exclusive", "invariant", "arbitrate", "connect", "assert", "test",   "resource",
    "never",     "only",      "assume",    "given",   "stable"};
// What a declared name follows: a declaration word, or a comma at depth 0 (`event a, b;`).
const std::set<std::string> kNamingWords = {"app", "type", "const", "module", "event", ","};

// Token ranges [begin, end) of top-level declarations: a declaration keyword at bracket
// depth 0 starts a new one. Text before the first keyword is a range of its own.
std::vector<std::pair<size_t, size_t>> split_declarations(
    const std::vector<antlr4::Token*>& tokens) {
  std::vector<std::pair<size_t, size_t>> ranges;
  size_t start = 0;
  int depth = 0;
  size_t last = tokens.size() - 1;  // the EOF token
  for (size_t i = 0; i < last; ++i) {
    const std::string text = tokens[i]->getText();
    if (tokens[i]->getType() != ArbcLexer::STRING) {
      if (text == "{" || text == "(" || text == "[") ++depth;
      if ((text == "}" || text == ")" || text == "]") && depth > 0) --depth;
    }
    // `after` also sits inside `only R after O;`: it starts a response only after a `;` or `}`.
    // `only` also sits inside `assume E only after R;`: there it follows `assume E`.
    bool inside_assume = text == "only" && i > 1 && tokens[i - 2]->getText() == "assume";
    // `event test;`: a keyword where the declaration's name goes is that declaration's one
    // error (a keyword used as a name), not the start of the next.
    bool as_name = i > 0 && kNamingWords.count(tokens[i - 1]->getText()) &&
                   tokens[i - 1]->getType() != ArbcLexer::STRING;
    bool starts = (kDeclStarts.count(text) && !inside_assume && !as_name) ||
                  (text == "after" && i > 0 &&
                   (tokens[i - 1]->getText() == ";" || tokens[i - 1]->getText() == "}"));
    if (depth == 0 && i > start && starts && tokens[i]->getType() != ArbcLexer::STRING) {
      ranges.emplace_back(start, i);
      start = i;
    }
  }
  if (start < last) ranges.emplace_back(start, last);
  return ranges;
}

bool lexical_error(const antlr4::Token* t) {
  size_t type = t->getType();
  return type == ArbcLexer::ERROR_CHAR || type == ArbcLexer::BAD_NUMBER ||
         type == ArbcLexer::UNTERMINATED_STRING || type == ArbcLexer::UNTERMINATED_COMMENT;
}

// Parses each declaration on its own so that every broken declaration gets exactly one
// error, and errors do not cascade from one declaration into the next. With
// `skip_lexical_errors`, a declaration holding a lexical error (already reported) is left out.
void report_syntax_errors(const std::vector<antlr4::Token*>& tokens, const std::string& file,
                          std::vector<Diagnostic>& out, bool skip_lexical_errors = false) {
  for (auto [begin, end] : split_declarations(tokens)) {
    if (skip_lexical_errors &&
        std::any_of(tokens.begin() + begin, tokens.begin() + end, lexical_error))
      continue;
    std::vector<std::unique_ptr<antlr4::Token>> copies;
    for (size_t i = begin; i < end; ++i)
      copies.push_back(std::make_unique<antlr4::CommonToken>(tokens[i]));
    antlr4::ListTokenSource source(std::move(copies));
    antlr4::CommonTokenStream stream(&source);
    ArbcParser parser(&stream);
    parser.removeErrorListeners();
    SyntaxErrors errors(file);
    if (end < tokens.size() - 1) errors.set_next_declaration(tokens[end]);
    parser.addErrorListener(errors.listener());
    parser.declOnly();
    if (errors.first_error()) out.push_back(*errors.first_error());
  }
}

Diagnostic file_error(const std::string& file, int line, int column, std::string message,
                      DiagId id) {
  Diagnostic d;
  d.loc.file = file;
  d.loc.line = line;
  d.loc.column = column;
  d.loc.end_line = line;
  d.loc.end_column = column + 1;
  d.message = std::move(message);
  d.id = id.text();
  return d;
}

// The line and column (in code points) of the first carriage return that no line feed follows.
// ANTLR, the diagnostics and editors count lines by LF, so a file with CR-only line endings is
// one line to all of them: refused before anything reports places in it.
std::optional<std::pair<int, int>> find_lone_carriage_return(std::string_view text) {
  for (size_t at = text.find('\r'); at != std::string_view::npos; at = text.find('\r', at + 1)) {
    if (at + 1 < text.size() && text[at + 1] == '\n') continue;
    size_t start = text.rfind('\n', at);
    start = start == std::string_view::npos ? 0 : start + 1;
    int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + start, '\n'));
    int column = 1;
    for (size_t i = start; i < at; ++i)
      column += (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80;
    return std::make_pair(line, column);
  }
  return std::nullopt;
}

// Placeholders for over-deep expressions would only cause follow-on type errors.
void without_deep_placeholders(ParseResult& result) {
  for (const Diagnostic& d : result.diagnostics)
    if (d.id == diag::NestingTooDeep.text()) result.spec.reset();
}

}  // namespace

ParseResult parse_spec(std::string_view text, const std::string& file, size_t two_thread_bytes) {
  ParseResult result;
  if (auto bad = find_invalid_utf8(text)) {
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(text[bad->offset]));
    result.diagnostics.push_back(
        file_error(file, bad->line, bad->column,
                   "the file is not valid UTF-8 (byte " + std::string(byte) + " at offset " +
                       std::to_string(bad->offset) + "): save it as UTF-8 text",
                   diag::InvalidUtf8));
    return result;
  }

  if (auto cr = find_lone_carriage_return(text)) {
    result.diagnostics.push_back(file_error(
        file, cr->first, cr->second,
        "this line ends in a carriage return alone (the old Mac OS line ending), which does not "
        "end a line here: the file would read as one line; save it with LF (or CR LF) line "
        "endings, e.g. `tr '\\r' '\\n' < " +
            file + " > fixed.spec`",
        diag::LineEndings));
    return result;
  }

  std::u32string code_points = decode_utf8(text);
  if (text.size() >= two_thread_bytes && std::thread::hardware_concurrency() >= 2) {
    if (auto split = find_split(text)) {
      if (auto halves = parse_halves(text, code_points, file, *split)) {
        without_deep_placeholders(*halves);
        return std::move(*halves);
      }
    }
  }

  LexedText lexed(code_points, 0, code_points.size(), 1, text.size());
  const std::vector<antlr4::Token*>& tokens = lexed.tokens;
  check_lexical(tokens, file, result.diagnostics);
  if (!result.diagnostics.empty()) {
    // The other declarations' syntax errors too, so that one stray character does not hide
    // them until it is fixed; in file order.
    if (check_nesting(tokens, lexed.lexer.getVocabulary(), file, result.diagnostics))
      report_syntax_errors(tokens, file, result.diagnostics, true);
    std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                     [](const Diagnostic& a, const Diagnostic& b) {
                       return std::tie(a.loc.line, a.loc.column) <
                              std::tie(b.loc.line, b.loc.column);
                     });
    return result;
  }
  if (tokens.size() == 1) {  // only EOF
    result.diagnostics.push_back(
        file_error(file, 0, 0, "the spec is empty: declare the app, its modules and their rules",
                   diag::EmptySpec));
    return result;
  }
  if (!check_nesting(tokens, lexed.lexer.getVocabulary(), file, result.diagnostics)) return result;

  AstBuilder builder(file, text, result.diagnostics);
  bool syntax_ok = parse_declarations(lexed.stream, builder);
  if (!syntax_ok) {
    report_syntax_errors(tokens, file, result.diagnostics);
    if (result.diagnostics.empty()) {  // cannot happen, but never stay silent
      result.diagnostics.push_back(
          file_error(file, 1, 1, "the spec does not follow the grammar", diag::Syntax));
    }
    return result;
  }
  result.spec = builder.finish();
  without_deep_placeholders(result);
  return result;
}

}  // namespace arbc::frontend

#include "compiler/frontend/parse.h"

#include <ArbcLexer.h>
#include <ArbcParser.h>
#include <antlr4-runtime.h>

#include <set>

#include "compiler/frontend/ast_builder.h"
#include "compiler/frontend/compact_token.h"
#include "compiler/frontend/syntax_errors.h"
#include "compiler/frontend/thread_dfa.h"
#include "compiler/frontend/token_checks.h"
#include "compiler/frontend/utf8.h"

namespace arbc::frontend {

using arbc_grammar::ArbcLexer;
using arbc_grammar::ArbcParser;

namespace {

const std::set<std::string> kDeclStarts = {
    "app",       "type",      "const",     "module",  "event",  "events",
    "exclusive", "invariant", "arbitrate", "connect", "assert", "test",
    "resource",  "never",     "only",      "assume",  "given",  "stable"};

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
    bool starts = kDeclStarts.count(text) ||
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

// Parses each declaration on its own so that every broken declaration gets exactly one
// error, and errors do not cascade from one declaration into the next.
void report_syntax_errors(const std::vector<antlr4::Token*>& tokens, const std::string& file,
                          std::vector<Diagnostic>& out) {
  for (auto [begin, end] : split_declarations(tokens)) {
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

// ANTLR's input stream decodes UTF-8 with std::wstring_convert, which is slow on large specs.
// The text is already validated, so decode it directly into the stream's UTF-32 buffer.
class Utf8InputStream : public antlr4::ANTLRInputStream {
 public:
  explicit Utf8InputStream(std::string_view utf8) {
    _data.clear();
    _data.reserve(utf8.size());
    for (size_t i = 0; i < utf8.size();) {
      unsigned char b = static_cast<unsigned char>(utf8[i]);
      size_t len = b < 0x80 ? 1 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : 4;
      char32_t code = len == 1 ? b : len == 2 ? (b & 0x1F) : len == 3 ? (b & 0x0F) : (b & 0x07);
      for (size_t k = 1; k < len && i + k < utf8.size(); ++k)
        code = (code << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
      _data.push_back(code);
      i += len;
    }
    p = 0;
  }
};

// A token stream whose buffer is reserved for `expected` tokens up front. Growing it by doubling
// touches fresh memory at every step, and fresh memory costs a page fault (docs/benchmarks.md);
// a reservation only touches what the lexer fills.
class ReservedTokenStream : public antlr4::CommonTokenStream {
 public:
  ReservedTokenStream(antlr4::TokenSource* source, size_t expected)
      : antlr4::CommonTokenStream(source) {
    _tokens.reserve(expected);
  }
};

Diagnostic file_error(const std::string& file, int line, int column, std::string message,
                      std::string id) {
  Diagnostic d;
  d.loc.file = file;
  d.loc.line = line;
  d.loc.column = column;
  d.loc.end_line = line;
  d.loc.end_column = column + 1;
  d.message = std::move(message);
  d.id = std::move(id);
  return d;
}

// The spec parser, predicting over this thread's own DFA cache (thread_dfa.h): use it on one
// thread.
class ThreadDfaParser : public ArbcParser {
 public:
  explicit ThreadDfaParser(antlr4::TokenStream* input) : ArbcParser(input) {
    delete _interpreter;  // the generated constructor's, over the process-wide cache
    _interpreter = make_thread_parser_simulator(this).release();  // deleted by ~ArbcParser
  }
};

// One declaration at a time: SLL prediction first (fast), full LL if SLL fails, and each
// declaration's parse tree is freed once its AST is built, so memory stays proportional to
// the AST rather than to ANTLR's much larger trees. False at the first declaration that does
// not parse (the caller then reports syntax errors with report_syntax_errors).
bool parse_declarations(antlr4::CommonTokenStream& stream, AstBuilder& builder) {
  ThreadDfaParser parser(&stream);
  parser.removeErrorListeners();
  parser.setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
  auto* simulator = parser.getInterpreter<antlr4::atn::ParserATNSimulator>();
  while (stream.LA(1) != antlr4::Token::EOF) {
    size_t start = stream.index();
    ArbcParser::DeclContext* decl = nullptr;
    for (auto mode : {antlr4::atn::PredictionMode::SLL, antlr4::atn::PredictionMode::LL}) {
      simulator->setPredictionMode(mode);
      try {
        decl = parser.decl();
        break;
      } catch (const antlr4::ParseCancellationException&) {
        parser.reset();
        stream.seek(start);
      }
    }
    if (!decl) return false;
    builder.add_declaration(decl);
    size_t next = stream.index();
    parser.reset();  // frees this declaration's parse tree; also rewinds the stream
    stream.seek(next);
  }
  return true;
}

}  // namespace

ParseResult parse_spec(std::string_view text, const std::string& file) {
  ParseResult result;
  if (auto bad = find_invalid_utf8(text)) {
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(text[bad->offset]));
    result.diagnostics.push_back(
        file_error(file, bad->line, bad->column,
                   "the file is not valid UTF-8 (byte " + std::string(byte) + " at offset " +
                       std::to_string(bad->offset) + "): save it as UTF-8 text",
                   "invalid-utf8"));
    return result;
  }

  Utf8InputStream input(text);
  CompactTokenLexer lexer(&input);
  lexer.removeErrorListeners();  // ERROR_CHAR catches everything the lexer cannot match
  // At most one token per byte, plus EOF; specs average one per four to five bytes.
  ReservedTokenStream stream(&lexer, text.size() / 2 + 16);
  stream.fill();
  std::vector<antlr4::Token*> tokens;
  tokens.reserve(stream.size());
  // stream.get(i), not getTokens(): that returns a fresh copy of the whole buffer.
  for (size_t i = 0; i < stream.size(); ++i) {
    antlr4::Token* t = stream.get(i);
    if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL) tokens.push_back(t);
  }

  check_lexical(tokens, file, result.diagnostics);
  if (!result.diagnostics.empty()) return result;
  if (tokens.size() == 1) {  // only EOF
    result.diagnostics.push_back(
        file_error(file, 0, 0, "the spec is empty: declare the app, its modules and their rules",
                   "empty-spec"));
    return result;
  }
  if (!check_nesting(tokens, lexer.getVocabulary(), file, result.diagnostics)) return result;

  AstBuilder builder(file, text, result.diagnostics);
  bool syntax_ok = parse_declarations(stream, builder);
  if (!syntax_ok) {
    report_syntax_errors(tokens, file, result.diagnostics);
    if (result.diagnostics.empty()) {  // cannot happen, but never stay silent
      result.diagnostics.push_back(
          file_error(file, 1, 1, "the spec does not follow the grammar", "syntax"));
    }
    return result;
  }
  result.spec = builder.finish();
  // Placeholders for over-deep expressions would only cause follow-on type errors.
  for (const Diagnostic& d : result.diagnostics)
    if (d.id == "nesting-too-deep") result.spec.reset();
  return result;
}

}  // namespace arbc::frontend

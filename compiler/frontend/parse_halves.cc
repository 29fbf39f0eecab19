#include "compiler/frontend/parse_halves.h"

#include <algorithm>
#include <array>
#include <exception>
#include <iterator>
#include <thread>

#include "compiler/frontend/ast_builder.h"
#include "compiler/frontend/lexed_text.h"
#include "compiler/frontend/parse_declarations.h"
#include "compiler/frontend/token_checks.h"

namespace arbc::frontend {

namespace {

// Keywords that start a declaration and nothing else. (`after` and `only` also appear inside
// declarations; a cut before one there would only make parse_halves give up.)
constexpr std::array<std::string_view, 18> kStarts = {
    "app",    "use",       "type",      "const",     "module",  "event",
    "events", "exclusive", "invariant", "arbitrate", "connect", "assert",
    "test",   "tests",     "resource",  "never",     "assume",  "stable"};

bool starts_declaration(std::string_view line) {
  for (std::string_view k : kStarts) {
    if (line.substr(0, k.size()) != k || line.size() == k.size()) continue;
    char next = line[k.size()];
    if (next == ' ' || next == '\t' || next == '\r' || next == '\n') return true;
  }
  return false;
}

struct Half {
  std::vector<Diagnostic> diagnostics;  // the AST builder's
  std::unique_ptr<ast::Spec> spec;      // null if the half did not parse cleanly
};

// Lexes, checks, parses and builds code points [begin, end) on the calling thread.
void parse_half(std::string_view text, const std::u32string& code_points, const std::string& file,
                size_t begin, size_t end, size_t line, size_t bytes, Half& half) {
  LexedText lexed(code_points, begin, end, line, bytes);
  std::vector<Diagnostic> problems;
  check_lexical(lexed.tokens, file, problems);
  if (!problems.empty() ||
      !check_nesting(lexed.tokens, lexed.lexer.getVocabulary(), file, problems))
    return;
  AstBuilder builder(file, text, half.diagnostics);
  if (parse_declarations(lexed.stream, builder)) half.spec = builder.finish();
}

template <typename T>
void append(std::vector<T>& to, std::vector<T>& from) {
  to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

// `second`'s declarations after `first`'s. False if both declare the app or name the app they
// test: the one-thread parse reports the second of those against the first.
bool join(ast::Spec& first, ast::Spec& second) {
  if ((first.app && second.app) || (first.tests_for && second.tests_for)) return false;
  if (second.app) first.app = std::move(second.app);
  if (second.tests_for) first.tests_for = std::move(second.tests_for);
  append(first.types, second.types);
  append(first.consts, second.consts);
  append(first.modules, second.modules);
  append(first.events, second.events);
  append(first.status_events, second.status_events);
  append(first.derived_events, second.derived_events);
  append(first.exclusives, second.exclusives);
  append(first.invariants, second.invariants);
  append(first.arbitrations, second.arbitrations);
  append(first.connects, second.connects);
  append(first.asserts, second.asserts);
  append(first.temporal, second.temporal);
  append(first.assumptions, second.assumptions);
  append(first.rates, second.rates);
  append(first.resources, second.resources);
  append(first.tests, second.tests);
  return true;
}

}  // namespace

std::optional<size_t> find_split(std::string_view text) {
  for (size_t at = text.find('\n', text.size() / 2); at != std::string_view::npos;
       at = text.find('\n', at + 1)) {
    if (starts_declaration(text.substr(at + 1))) return at + 1;
  }
  return std::nullopt;
}

std::optional<ParseResult> parse_halves(std::string_view text, const std::u32string& code_points,
                                        const std::string& file, size_t split) {
  if (split == 0 || split >= text.size() || text[split - 1] != '\n') return std::nullopt;
  // The cut in code points, and the line it starts (the lexer counts '\n' only).
  std::string_view head = text.substr(0, split);
  size_t cut = static_cast<size_t>(std::count_if(head.begin(), head.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
  size_t line = 1 + static_cast<size_t>(std::count(head.begin(), head.end(), '\n'));

  Half first, second;
  std::exception_ptr failure;
  std::thread other([&] {
    try {
      parse_half(text, code_points, file, cut, code_points.size(), line, text.size() - split,
                 second);
    } catch (...) {
      failure = std::current_exception();
    }
  });
  try {
    parse_half(text, code_points, file, 0, cut, 1, split, first);
  } catch (...) {
    other.join();
    throw;
  }
  other.join();
  if (failure) std::rethrow_exception(failure);

  // A block comment open across the cut ends the first half in an unterminated comment (a
  // lexical error); a cut inside a declaration ends it in a syntax error. Either way the first
  // half failed. Otherwise the first half is whole declarations, so one parse would have
  // started a declaration at the cut too, and seen the same tokens from there: no token spans
  // the cut (only comments span lines).
  if (!first.spec || !second.spec || !join(*first.spec, *second.spec)) return std::nullopt;
  ParseResult result;
  result.spec = std::move(first.spec);
  result.diagnostics = std::move(first.diagnostics);
  append(result.diagnostics, second.diagnostics);
  return result;
}

}  // namespace arbc::frontend

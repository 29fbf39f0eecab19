// Turns the ANTLR parser's syntax errors into messages in the user's words ("expected ';'
// after the port declaration", "expected a type such as float, vec3 or list<T>"), never a
// token dump. One listener per parse; it keeps only the first error it sees, because the
// front end parses one declaration at a time when a file has errors (see parse.cc).
#pragma once

#include <optional>
#include <string>

#include "core/diagnostic.h"

namespace antlr4 {
class BaseErrorListener;
class Token;
}  // namespace antlr4

namespace arbc::frontend {

class SyntaxErrorCollector;

// Creates a listener for a parser (owned by the caller); `first_error()` is the first error.
class SyntaxErrors {
 public:
  explicit SyntaxErrors(std::string file);
  ~SyntaxErrors();
  antlr4::BaseErrorListener* listener();
  // When parsing one declaration of a larger file, its end is where the next declaration
  // starts: errors at the end name and point at that token instead of "the end of the file".
  void set_next_declaration(const antlr4::Token* token);
  const std::optional<Diagnostic>& first_error() const;

 private:
  std::unique_ptr<SyntaxErrorCollector> collector_;
};

}  // namespace arbc::frontend

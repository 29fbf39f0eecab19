// A forgotten '}'. The parser notices it only where the block should long have ended: at the
// next declaration, or at the end of the file, and would say "expected a rule or '}', found
// 'arbitrate'" there. This names the block left open instead, and, when the indentation shows
// it, the inner block that probably lost its '}' (each '}' after it then closes the block
// around the one it was written for, so the parser's open block is the outermost one).
#pragma once

#include <optional>
#include <string>

#include "core/diagnostic.h"

namespace antlr4 {
class Token;
class TokenStream;
}  // namespace antlr4

namespace arbc::frontend {

// The diagnostic when a '{' among `tokens` before `stop` (a token that can only start a
// declaration, or the end of the file) is still open; nothing otherwise. It points at that
// '{', says where the parser noticed, and notes the block the indentation suspects.
std::optional<Diagnostic> describe_unclosed_block(antlr4::TokenStream* tokens,
                                                  const antlr4::Token* stop,
                                                  const std::string& file);

}  // namespace arbc::frontend

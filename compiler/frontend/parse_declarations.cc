#include "compiler/frontend/parse_declarations.h"

#include <ArbcParser.h>

#include "compiler/frontend/thread_dfa.h"

namespace arbc::frontend {

namespace {

// The spec parser, predicting over this thread's own DFA cache (thread_dfa.h): use it on one
// thread.
class ThreadDfaParser : public arbc_grammar::ArbcParser {
 public:
  explicit ThreadDfaParser(antlr4::TokenStream* input) : ArbcParser(input) {
    delete _interpreter;  // the generated constructor's, over the process-wide cache
    _interpreter = make_thread_parser_simulator(this).release();  // deleted by ~ArbcParser
  }
};

}  // namespace

// One declaration at a time: SLL prediction first (fast), full LL if SLL fails, and each
// declaration's parse tree is freed once its AST is built, so memory stays proportional to
// the AST rather than to ANTLR's much larger trees.
bool parse_declarations(antlr4::CommonTokenStream& stream, AstBuilder& builder) {
  ThreadDfaParser parser(&stream);
  parser.removeErrorListeners();
  parser.setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
  auto* simulator = parser.getInterpreter<antlr4::atn::ParserATNSimulator>();
  while (stream.LA(1) != antlr4::Token::EOF) {
    size_t start = stream.index();
    arbc_grammar::ArbcParser::DeclContext* decl = nullptr;
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

}  // namespace arbc::frontend

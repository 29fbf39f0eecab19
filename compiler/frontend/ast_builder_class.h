// The builder behind AstBuilder (ast_builder.h), one class whose methods are defined by what
// they build: ast_builder.cc (errors, literals, types), ast_build_expr.cc (expressions and
// statements) and ast_build_decls.cc (declarations, rules, tests). Each definition quotes the
// grammar rule it reads. Internal to those three files.
#pragma once

#include <ArbcParser.h>
#include <antlr4-runtime.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include "compiler/frontend/ast.h"
#include "compiler/frontend/token_checks.h"
#include "compiler/frontend/token_text.h"
#include "core/check_ids.h"
#include "core/diagnostic.h"

namespace arbc::frontend {

using arbc_grammar::ArbcParser;

// The parse tree node as a `T` if it is exactly one (labelled alternatives are leaf classes),
// else null. typeid comparison is much cheaper than dynamic_cast on large specs.
template <typename T, typename Node>
T* as(Node* node) {
  return node && typeid(*node) == typeid(T) ? static_cast<T*>(node) : nullptr;
}

// Child `i` of an `expr` alternative, where the grammar puts a sub-expression (`T` =
// ExprContext) or a token (`T` = TerminalNode): 0 and 2 of `expr op expr`, 1 of `'not' expr`.
// The generated accessors (`c->expr(1)`, `c->ID()`) find a child by a dynamic_cast of every
// child in turn, which was 10 % of `arbc check` on a 10,000-rule spec (docs/benchmarks.md).
// The positions are fixed by the grammar, and the builder only sees trees that parsed.
template <typename T>
T* child(antlr4::ParserRuleContext* ctx, size_t i) {
  return static_cast<T*>(ctx->children[i]);
}
inline ArbcParser::ExprContext* operand(antlr4::ParserRuleContext* ctx, size_t i) {
  return child<ArbcParser::ExprContext>(ctx, i);
}

class Builder {
 public:
  Builder(const std::string& file, std::string_view source, std::vector<Diagnostic>& out)
      : file_(file), text_(source), out_(out) {}
  std::string tx(antlr4::Token* token) const { return text_.text(token); }
  std::string tx(antlr4::tree::TerminalNode* node) const { return text_.text(node->getSymbol()); }
  ast::Loc loc(antlr4::Token* token) const { return token_location(token, file_); }
  ast::Loc loc(antlr4::tree::TerminalNode* node) const { return loc(node->getSymbol()); }
  ast::Loc loc(antlr4::ParserRuleContext* ctx) const {
    ast::Loc l = loc(ctx->getStart());
    antlr4::Token* stop = ctx->getStop();
    if (stop && stop->getTokenIndex() >= ctx->getStart()->getTokenIndex()) {
      // The end of the stop token, computed without building a second location.
      l.end_line = static_cast<int>(stop->getLine());
      l.end_column = static_cast<int>(stop->getCharPositionInLine()) + 1 +
                     static_cast<int>(stop->getStopIndex() + 1 - stop->getStartIndex());
    }
    return l;
  }

  // ast_builder.cc
  void error(const ast::Loc& where, std::string message, DiagId id);
  std::string decode_string(antlr4::tree::TerminalNode* node);
  static double seconds_of_duration(const std::string& text);
  ast::TypeExpr type_expr(ArbcParser::TypeExprContext* ctx, int depth = 0);
  ast::TypeExpr named_type(ArbcParser::NamedTypeContext* named, int depth);
  int type_size(antlr4::Token* token);

  // ast_build_expr.cc
  ast::ExprPtr make(ast::Expr::Kind kind, ast::Loc where);
  ast::ExprPtr placeholder(ast::Loc where);
  bool too_deep(int depth, const ast::Loc& where);
  ast::ExprPtr expr(ArbcParser::ExprContext* ctx, int depth);
  ast::ExprPtr unary(const std::string& op, ArbcParser::ExprContext* operand, ast::Loc where,
                     int depth);
  ast::ExprPtr binary(const std::string& op, ArbcParser::ExprContext* left,
                      ArbcParser::ExprContext* right, ast::Loc where, int depth);
  ast::ExprPtr primary(ArbcParser::PrimaryContext* ctx, int depth);
  ast::Duration duration(ArbcParser::DurationContext* ctx);
  std::optional<ast::Duration> optional_duration(ArbcParser::DurationContext* ctx);
  ast::Block block(ArbcParser::BlockContext* ctx, int depth);
  std::unique_ptr<ast::Stmt> make_stmt(ast::Stmt::Kind kind, antlr4::ParserRuleContext* ctx);
  void set_name(ast::Stmt& s, antlr4::tree::TerminalNode* id);
  std::unique_ptr<ast::Stmt> stmt(ArbcParser::StmtContext* ctx, int depth);
  std::unique_ptr<ast::Stmt> if_chain(ArbcParser::IfStmtContext* c, int depth);

  // ast_build_decls.cc
  ast::PortRef port_ref(ArbcParser::PortRefContext* ctx);  // portRef : ID '.' ID ;
  void add_decl(ast::Spec& spec, ArbcParser::DeclContext* ctx);
  void add_app(ast::Spec& spec, ArbcParser::AppDeclContext* c);
  ast::UseDecl use_decl(ArbcParser::UseDeclContext* c);
  ast::TypeDecl type_decl(ArbcParser::TypeDeclContext* c);
  ast::ConstDecl const_decl(ArbcParser::ConstDeclContext* c);
  ast::ModuleDecl module_decl(ArbcParser::ModuleDeclContext* c);
  ast::EventDecl event_decl(ArbcParser::EventDeclContext* c);
  ast::ResourceDecl resource_decl(ArbcParser::ResourceDeclContext* c);
  std::optional<ast::FailOpen> fail_open(ArbcParser::FailOpenContext* c);
  ast::DerivedEventDecl derived_event_decl(ArbcParser::DerivedEventDeclContext* c);
  ast::LockDecl lock_event_decl(ArbcParser::LockEventDeclContext* c);
  ast::StatusEventDecl status_events_decl(ArbcParser::StatusEventsDeclContext* c);
  ast::ExclusiveDecl exclusive_decl(ArbcParser::ExclusiveDeclContext* c);
  ast::InvariantDecl invariant_decl(ArbcParser::InvariantDeclContext* c);
  ast::ArbitrateDecl arbitrate_decl(ArbcParser::ArbitrateDeclContext* c);
  ast::ConnectDecl connect_decl(ArbcParser::ConnectDeclContext* c);
  ast::AssertDecl assert_decl(ArbcParser::AssertDeclContext* c);
  ast::TemporalDecl never_decl(ArbcParser::NeverDeclContext* c);
  ast::TemporalDecl only_after_decl(ArbcParser::OnlyAfterDeclContext* c);
  ast::AssumeDecl assume_decl(ArbcParser::AssumeDeclContext* c);
  ast::TemporalDecl response_decl(ArbcParser::ResponseDeclContext* c);
  ast::TemporalDecl stable_decl(ArbcParser::StableDeclContext* c);
  void add_tests_for(ast::Spec& spec, ArbcParser::TestsForDeclContext* c);
  ast::TestDecl test_decl(ArbcParser::TestDeclContext* c);
  void add_test_step(ast::TestDecl& t, ArbcParser::TestStepContext* step);
  ast::TestExpect test_expect(ArbcParser::TestStepContext* step);
  std::string spaced_text(antlr4::ParserRuleContext* ctx);
  static void collect_tokens(antlr4::tree::ParseTree* node, std::vector<antlr4::Token*>& out);
  ast::Rule rule(ArbcParser::RuleDeclContext* c);
  std::vector<ast::DeliveryEffect> on_delivery(ArbcParser::OnDeliveryContext* c);

 private:
  model::FileName file_;  // interned once: every location copies it
  TokenText text_;
  std::vector<Diagnostic>& out_;
  bool reported_depth_ = false;
};

}  // namespace arbc::frontend

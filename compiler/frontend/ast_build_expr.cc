#include <charconv>
#include <limits>

#include "compiler/frontend/ast_builder_class.h"

namespace arbc::frontend {

using namespace ast;

namespace {

// An int literal's exact value (the double in `number` rounds above 2^53); digits that do not
// fit in 64 bits are marked for sema to report.
void set_integer(Expr& e, const std::string& digits) {
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), e.integer);
  e.int_too_big = ec != std::errc() || end != digits.data() + digits.size();
  if (e.int_too_big) e.text = digits;  // for `-9223372036854775808` (Builder::unary)
}

// `-9223372036854775808`, INT64_MIN, is one int literal (docs/language.md#numbers): its digits
// alone do not fit in 64 bits, but arbc prints the value so in counterexamples and tests, which
// must read back. Lua would read it as `-` of a float; the generated Lua writes math.mininteger.
bool is_int64_min_digits(const Expr& e) {
  return e.kind == Expr::Kind::Number && e.is_int && e.int_too_big &&
         e.text == "9223372036854775808";
}

}  // namespace

// Copies `where` into the node: each copy of a location allocates the file name, and a
// 10,000-rule spec has ~200,000 expression nodes (docs/benchmarks.md).
ExprPtr Builder::make(Expr::Kind kind, Loc where) {
  auto e = std::make_unique<Expr>();
  e->kind = kind;
  e->loc = std::move(where);
  return e;
}

// A stand-in where an expression could not be built (nesting too deep).
ExprPtr Builder::placeholder(Loc where) {
  auto e = make(Expr::Kind::Bool, std::move(where));
  return e;
}

bool Builder::too_deep(int depth, const Loc& where) {
  if (depth <= kMaxNesting) return false;
  if (!reported_depth_) {
    error(where,
          "expression nested deeper than " + std::to_string(kMaxNesting) +
              " levels: split it with `let` or named constants",
          diag::NestingTooDeep);
  }
  reported_depth_ = true;
  return true;
}

// expr : expr '.' ID | expr '[' expr ']' | '-' expr | expr op expr | 'not' expr
//      | ID '=>' expr | primary ;
ExprPtr Builder::expr(ArbcParser::ExprContext* ctx, int depth) {
  // A primary has the same location as its expression: primary() computes it, once.
  if (auto* c = as<ArbcParser::PrimaryExprContext>(ctx); c && depth <= kMaxNesting)
    return primary(child<ArbcParser::PrimaryContext>(c, 0), depth);
  Loc where = loc(ctx);
  if (too_deep(depth, where)) return placeholder(std::move(where));
  if (auto* c = as<ArbcParser::FieldExprContext>(ctx)) {
    auto e = make(Expr::Kind::Field, std::move(where));  // expr '.' ID
    e->text = tx(child<antlr4::tree::TerminalNode>(c, 2));
    e->args.push_back(expr(operand(c, 0), depth + 1));
    return e;
  }
  if (auto* c = as<ArbcParser::IndexExprContext>(ctx)) {
    auto e = make(Expr::Kind::Index, std::move(where));
    e->args.push_back(expr(operand(c, 0), depth + 1));  // expr '[' expr ']'
    e->args.push_back(expr(operand(c, 2), depth + 1));
    return e;
  }
  if (auto* c = as<ArbcParser::NegExprContext>(ctx))
    return unary("-", operand(c, 1), std::move(where), depth);
  if (auto* c = as<ArbcParser::NotExprContext>(ctx))
    return unary("not", operand(c, 1), std::move(where), depth);
  if (auto* c = as<ArbcParser::MulExprContext>(ctx))
    return binary(tx(c->op), operand(c, 0), operand(c, 2), std::move(where), depth);
  if (auto* c = as<ArbcParser::AddExprContext>(ctx))
    return binary(tx(c->op), operand(c, 0), operand(c, 2), std::move(where), depth);
  if (auto* c = as<ArbcParser::CompareExprContext>(ctx))
    return binary(tx(c->op), operand(c, 0), operand(c, 2), std::move(where), depth);
  if (auto* c = as<ArbcParser::AndExprContext>(ctx))
    return binary("and", operand(c, 0), operand(c, 2), std::move(where), depth);
  if (auto* c = as<ArbcParser::OrExprContext>(ctx))
    return binary("or", operand(c, 0), operand(c, 2), std::move(where), depth);
  if (auto* c = as<ArbcParser::LambdaExprContext>(ctx)) {
    auto e = make(Expr::Kind::Lambda, std::move(where));  // ID '=>' expr
    auto* parameter = child<antlr4::tree::TerminalNode>(c, 0);
    e->text = tx(parameter);
    e->names.push_back({e->text, loc(parameter)});
    e->args.push_back(expr(operand(c, 2), depth + 1));
    return e;
  }
  return placeholder(std::move(where));
}

ExprPtr Builder::unary(const std::string& op, ArbcParser::ExprContext* operand, Loc where,
                       int depth) {
  ExprPtr inner = expr(operand, depth + 1);
  if (op == "-" && is_int64_min_digits(*inner)) {
    auto e = make(Expr::Kind::Number, std::move(where));
    e->is_int = true;
    e->integer = std::numeric_limits<int64_t>::min();
    e->number = static_cast<double>(e->integer);
    return e;
  }
  auto e = make(Expr::Kind::Unary, std::move(where));
  e->op = operator_spelling(op);
  e->args.push_back(std::move(inner));
  return e;
}

ExprPtr Builder::binary(const std::string& op, ArbcParser::ExprContext* left,
                        ArbcParser::ExprContext* right, Loc where, int depth) {
  auto e = make(Expr::Kind::Binary, std::move(where));
  e->op = operator_spelling(op);
  e->args.reserve(2);
  e->args.push_back(expr(left, depth + 1));
  e->args.push_back(expr(right, depth + 1));
  return e;
}

// primary : NUMBER | DURATION | STRING | 'true' | 'false' | 'otherwise'
//         | ID '(' args ')' | ID | '(' expr ')' | '{' fieldInits '}' | '[' exprs ']' ;
ExprPtr Builder::primary(ArbcParser::PrimaryContext* ctx, int depth) {
  Loc where = loc(ctx);
  if (auto* c = as<ArbcParser::NumberLitContext>(ctx)) {
    auto e = make(Expr::Kind::Number, std::move(where));
    std::string text = tx(child<antlr4::tree::TerminalNode>(c, 0));
    e->number = std::strtod(text.c_str(), nullptr);
    e->is_int = text.find_first_of(".eE") == std::string::npos;
    if (e->is_int) set_integer(*e, text);
    return e;
  }
  if (auto* c = as<ArbcParser::DurationLitContext>(ctx)) {
    auto e = make(Expr::Kind::Duration, std::move(where));
    e->text = tx(child<antlr4::tree::TerminalNode>(c, 0));
    e->number = seconds_of_duration(e->text);
    return e;
  }
  if (auto* c = as<ArbcParser::StringLitContext>(ctx)) {
    auto e = make(Expr::Kind::String, std::move(where));
    e->text = decode_string(child<antlr4::tree::TerminalNode>(c, 0));
    return e;
  }
  if (as<ArbcParser::TrueLitContext>(ctx) || as<ArbcParser::FalseLitContext>(ctx)) {
    auto e = make(Expr::Kind::Bool, std::move(where));
    e->boolean = as<ArbcParser::TrueLitContext>(ctx) != nullptr;
    return e;
  }
  if (as<ArbcParser::OtherwiseLitContext>(ctx))
    return make(Expr::Kind::Otherwise, std::move(where));
  if (auto* c = as<ArbcParser::CallExprContext>(ctx)) {
    auto e = make(Expr::Kind::Call, std::move(where));
    auto* callee = child<antlr4::tree::TerminalNode>(c, 0);
    e->text = tx(callee);
    e->names.push_back({e->text, loc(callee)});
    for (ArbcParser::ExprContext* arg : c->expr()) e->args.push_back(expr(arg, depth + 1));
    return e;
  }
  if (auto* c = as<ArbcParser::NameExprContext>(ctx)) {
    auto e = make(Expr::Kind::Name, std::move(where));
    e->text = tx(child<antlr4::tree::TerminalNode>(c, 0));
    return e;
  }
  if (auto* c = as<ArbcParser::ParenExprContext>(ctx)) {
    return expr(operand(c, 1), depth + 1);  // '(' expr ')'
  }
  if (auto* c = as<ArbcParser::RecordLitContext>(ctx)) {
    auto e = make(Expr::Kind::Record, std::move(where));
    for (ArbcParser::FieldInitContext* field : c->fieldInit()) {
      e->names.push_back({tx(field->ID()), loc(field->ID())});
      e->args.push_back(expr(field->expr(), depth + 1));
    }
    return e;
  }
  if (auto* c = as<ArbcParser::ListLitContext>(ctx)) {
    auto e = make(Expr::Kind::List, std::move(where));
    for (ArbcParser::ExprContext* item : c->expr()) e->args.push_back(expr(item, depth + 1));
    return e;
  }
  return placeholder(std::move(where));
}

// duration : DURATION | NUMBER | ID ;
Duration Builder::duration(ArbcParser::DurationContext* ctx) {
  Duration d;
  Loc where = loc(ctx);
  if (ctx->DURATION()) {
    d.expr = make(Expr::Kind::Duration, where);
    d.expr->text = tx(ctx->DURATION());
    d.expr->number = seconds_of_duration(d.expr->text);
  } else if (ctx->NUMBER()) {
    d.expr = make(Expr::Kind::Number, where);
    std::string text = tx(ctx->NUMBER());
    d.expr->number = std::strtod(text.c_str(), nullptr);
    d.expr->is_int = text.find_first_of(".eE") == std::string::npos;
    if (d.expr->is_int) set_integer(*d.expr, text);
  } else {
    d.expr = make(Expr::Kind::Name, where);
    d.expr->text = tx(ctx->ID());
  }
  return d;
}

std::optional<Duration> Builder::optional_duration(ArbcParser::DurationContext* ctx) {
  if (!ctx) return std::nullopt;
  return duration(ctx);
}

// block : '{' stmt* '}' ;
Block Builder::block(ArbcParser::BlockContext* ctx, int depth) {
  Block b;
  if (too_deep(depth, loc(ctx))) return b;
  for (ArbcParser::StmtContext* s : ctx->stmt()) b.push_back(stmt(s, depth));
  return b;
}

std::unique_ptr<Stmt> Builder::make_stmt(Stmt::Kind kind, antlr4::ParserRuleContext* ctx) {
  auto s = std::make_unique<Stmt>();
  s->kind = kind;
  s->loc = loc(ctx);
  return s;
}

void Builder::set_name(Stmt& s, antlr4::tree::TerminalNode* id) {
  s.name = tx(id);
  s.name_loc = loc(id);
}

// stmt : let | var | assign | accept | set | unset | if | emit | throttle | every | script
std::unique_ptr<Stmt> Builder::stmt(ArbcParser::StmtContext* ctx, int depth) {
  if (auto* c = as<ArbcParser::LetStmtContext>(ctx)) {
    auto s = make_stmt(Stmt::Kind::Let, c);
    set_name(*s, c->ID());
    s->expr = expr(c->expr(), depth + 1);
    return s;
  }
  if (auto* c = as<ArbcParser::VarStmtContext>(ctx)) {
    auto s = make_stmt(Stmt::Kind::Var, c);
    set_name(*s, c->ID());
    s->expr = expr(c->expr(), depth + 1);
    return s;
  }
  if (auto* c = as<ArbcParser::AssignStmtContext>(ctx)) {
    auto s = make_stmt(Stmt::Kind::Assign, c);
    set_name(*s, c->ID());
    s->expr = expr(c->expr(), depth + 1);
    return s;
  }
  if (auto* c = as<ArbcParser::AcceptStmtContext>(ctx)) {
    auto s = make_stmt(Stmt::Kind::Accept, c);
    s->expr = expr(c->expr(), depth + 1);
    return s;
  }
  if (auto* c = as<ArbcParser::SetStmtContext>(ctx)) {
    auto s = make_stmt(Stmt::Kind::Set, c);
    set_name(*s, c->ID());
    s->duration = optional_duration(c->duration());
    return s;
  }
  if (auto* c = as<ArbcParser::UnsetStmtContext>(ctx)) {
    auto s = make_stmt(Stmt::Kind::Unset, c);
    set_name(*s, c->ID());
    return s;
  }
  if (auto* c = as<ArbcParser::IfStmtContext>(ctx)) return if_chain(c, depth);
  if (auto* c = as<ArbcParser::EmitStmtContext>(ctx)) {
    auto s = make_stmt(Stmt::Kind::Emit, c);
    s->expr = expr(c->expr(), depth + 1);
    return s;
  }
  if (auto* c = as<ArbcParser::ThrottleStmtContext>(ctx)) {
    auto s = make_stmt(Stmt::Kind::Throttle, c);
    s->duration = duration(c->duration());
    return s;
  }
  if (auto* c = as<ArbcParser::EveryStmtContext>(ctx)) {
    auto s = make_stmt(Stmt::Kind::Every, c);
    s->duration = duration(c->duration());
    s->body = block(c->block(), depth + 1);
    return s;
  }
  auto* c = as<ArbcParser::ScriptStmtContext>(ctx);
  auto s = make_stmt(Stmt::Kind::Script, ctx);
  if (c) s->text = decode_string(c->STRING());
  return s;
}

// 'if' expr block ('else' 'if' expr block)* ('else' block)?
// An else-if chain becomes nested If statements, built from the last link backwards.
std::unique_ptr<Stmt> Builder::if_chain(ArbcParser::IfStmtContext* c, int depth) {
  std::vector<ArbcParser::ExprContext*> conditions = c->expr();
  std::vector<ArbcParser::BlockContext*> blocks = c->block();
  if (too_deep(depth + static_cast<int>(conditions.size()), loc(c))) {
    return make_stmt(Stmt::Kind::If, c);  // condition-less placeholder; never checked further
  }
  std::unique_ptr<Stmt> next;
  bool has_final_else = blocks.size() > conditions.size();
  for (size_t i = conditions.size(); i-- > 0;) {
    auto s = make_stmt(Stmt::Kind::If, c);
    s->loc = loc(conditions[i]->getStart());
    if (i > 0)
      s->loc = loc(conditions[i]);  // an else-if link: point at its condition
    else
      s->loc = loc(c->getStart());
    int link_depth = depth + static_cast<int>(i);
    s->expr = expr(conditions[i], link_depth + 1);
    s->body = block(blocks[i], link_depth + 1);
    if (next) {
      s->else_body.push_back(std::move(next));
      s->has_else = true;
    } else if (has_final_else) {
      s->else_body = block(blocks.back(), link_depth + 1);
      s->has_else = true;
    }
    next = std::move(s);
  }
  return next;
}

}  // namespace arbc::frontend

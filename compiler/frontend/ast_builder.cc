#include "compiler/frontend/ast_builder.h"

#include <ArbcParser.h>
#include <antlr4-runtime.h>

#include <cctype>
#include <cstdlib>
#include <typeinfo>

#include "compiler/frontend/token_checks.h"
#include "compiler/frontend/token_text.h"

namespace arbc::frontend {

using arbc_grammar::ArbcParser;
using namespace ast;

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
ArbcParser::ExprContext* operand(antlr4::ParserRuleContext* ctx, size_t i) {
  return child<ArbcParser::ExprContext>(ctx, i);
}

class Builder {
 public:
  Builder(const std::string& file, std::string_view source, std::vector<Diagnostic>& out)
      : file_(file), text_(source), out_(out) {}

  // decl : appDecl | typeDecl | ... | assertDecl ;   (add_decl, below)

  std::string tx(antlr4::Token* token) const { return text_.text(token); }
  std::string tx(antlr4::tree::TerminalNode* node) const { return text_.text(node->getSymbol()); }

  // ---- locations --------------------------------------------------------------------------
  Loc loc(antlr4::Token* token) const { return token_location(token, file_); }
  Loc loc(antlr4::tree::TerminalNode* node) const { return loc(node->getSymbol()); }
  Loc loc(antlr4::ParserRuleContext* ctx) const {
    Loc l = loc(ctx->getStart());
    antlr4::Token* stop = ctx->getStop();
    if (stop && stop->getTokenIndex() >= ctx->getStart()->getTokenIndex()) {
      // The end of the stop token, computed without building a second location.
      l.end_line = static_cast<int>(stop->getLine());
      l.end_column = static_cast<int>(stop->getCharPositionInLine()) + 1 +
                     static_cast<int>(stop->getStopIndex() + 1 - stop->getStartIndex());
    }
    return l;
  }

  void error(const Loc& where, std::string message, std::string id) {
    Diagnostic d;
    d.loc = where;
    d.message = std::move(message);
    d.id = std::move(id);
    out_.push_back(std::move(d));
  }

  // ---- literals -----------------------------------------------------------------------------
  // STRING : '"' (~["\\\r\n] | '\\' ~[\r\n])* '"' ;   escapes: \" \\ \n \t \r
  std::string decode_string(antlr4::tree::TerminalNode* node) {
    std::string raw = tx(node);
    std::string out;
    for (size_t i = 1; i + 1 < raw.size(); ++i) {
      if (raw[i] != '\\') {
        out += raw[i];
        continue;
      }
      char c = raw[++i];
      switch (c) {
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        case 'n':
          out += '\n';
          break;
        case 't':
          out += '\t';
          break;
        case 'r':
          out += '\r';
          break;
        default: {
          Loc where = loc(node);
          where.column += static_cast<int>(i) - 1;
          where.end_column = where.column + 2;
          error(where,
                std::string("unknown escape sequence '\\") + c +
                    "' in a string: use \\\", \\\\, \\n, \\t or \\r",
                "bad-escape");
        }
      }
    }
    return out;
  }

  static double seconds_of_duration(const std::string& text) {
    size_t unit = text.find_first_not_of("0123456789.");
    double value = std::strtod(text.substr(0, unit).c_str(), nullptr);
    std::string suffix = text.substr(unit);
    if (suffix == "ms") return value / 1000.0;
    if (suffix == "min") return value * 60.0;
    return value;
  }

  // ---- types --------------------------------------------------------------------------------
  // typeExpr : ID ('<' typeExpr '>')? | '{' (fieldType (',' fieldType)* ','?)? '}' ;
  TypeExpr type_expr(ArbcParser::TypeExprContext* ctx, int depth = 0) {
    TypeExpr t;
    t.loc = loc(ctx);
    if (depth > kMaxNesting) {
      error(t.loc, "type nested deeper than " + std::to_string(kMaxNesting) + " levels",
            "nesting-too-deep");
      t.kind = TypeExpr::Kind::Bool;
      return t;
    }
    if (auto* named = as<ArbcParser::NamedTypeContext>(ctx)) {
      std::string name = tx(named->ID());
      static const std::pair<const char*, TypeExpr::Kind> kScalars[] = {
          {"bool", TypeExpr::Kind::Bool},
          {"int", TypeExpr::Kind::Int},
          {"float", TypeExpr::Kind::Float},
          {"string", TypeExpr::Kind::String},
          {"vec3", TypeExpr::Kind::Vec3}};
      if (name == "list") {
        t.kind = TypeExpr::Kind::List;
        if (named->typeExpr()) {
          t.element = std::make_unique<TypeExpr>(type_expr(named->typeExpr(), depth + 1));
        } else {
          error(t.loc, "'list' needs an element type, e.g. list<string>", "bad-type");
          t.element = std::make_unique<TypeExpr>();
          t.element->loc = t.loc;
        }
        return t;
      }
      t.kind = TypeExpr::Kind::Named;
      t.name = name;
      for (auto [scalar, kind] : kScalars)
        if (name == scalar) t.kind = kind;
      if (named->typeExpr())
        error(loc(named->typeExpr()),
              "type '" + name + "' takes no type argument; only list<T> does", "bad-type");
      return t;
    }
    auto* record = as<ArbcParser::RecordTypeContext>(ctx);
    t.kind = TypeExpr::Kind::Record;
    for (ArbcParser::FieldTypeContext* field : record->fieldType()) {
      t.fields.emplace_back(tx(field->ID()),
                            std::make_unique<TypeExpr>(type_expr(field->typeExpr(), depth + 1)));
      t.field_locs.push_back(loc(field->ID()));
    }
    return t;
  }

  // ---- expressions --------------------------------------------------------------------------
  // Copies `where` into the node: each copy of a location allocates the file name, and a
  // 10,000-rule spec has ~200,000 expression nodes (docs/benchmarks.md).
  ExprPtr make(Expr::Kind kind, Loc where) {
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    e->loc = std::move(where);
    return e;
  }

  // A stand-in where an expression could not be built (nesting too deep).
  ExprPtr placeholder(Loc where) {
    auto e = make(Expr::Kind::Bool, std::move(where));
    return e;
  }

  bool too_deep(int depth, const Loc& where) {
    if (depth <= kMaxNesting) return false;
    if (!reported_depth_) {
      error(where,
            "expression nested deeper than " + std::to_string(kMaxNesting) +
                " levels: split it with `let` or named constants",
            "nesting-too-deep");
    }
    reported_depth_ = true;
    return true;
  }

  // expr : expr '.' ID | expr '[' expr ']' | '-' expr | expr op expr | 'not' expr
  //      | ID '=>' expr | primary ;
  ExprPtr expr(ArbcParser::ExprContext* ctx, int depth) {
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

  ExprPtr unary(const std::string& op, ArbcParser::ExprContext* operand, Loc where, int depth) {
    auto e = make(Expr::Kind::Unary, std::move(where));
    e->op = operator_spelling(op);
    e->args.push_back(expr(operand, depth + 1));
    return e;
  }

  ExprPtr binary(const std::string& op, ArbcParser::ExprContext* left,
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
  ExprPtr primary(ArbcParser::PrimaryContext* ctx, int depth) {
    Loc where = loc(ctx);
    if (auto* c = as<ArbcParser::NumberLitContext>(ctx)) {
      auto e = make(Expr::Kind::Number, std::move(where));
      std::string text = tx(child<antlr4::tree::TerminalNode>(c, 0));
      e->number = std::strtod(text.c_str(), nullptr);
      e->is_int = text.find_first_of(".eE") == std::string::npos;
      return e;
    }
    if (auto* c = as<ArbcParser::DurationLitContext>(ctx)) {
      auto e = make(Expr::Kind::Duration, std::move(where));
      e->number = seconds_of_duration(tx(child<antlr4::tree::TerminalNode>(c, 0)));
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
  Duration duration(ArbcParser::DurationContext* ctx) {
    Duration d;
    Loc where = loc(ctx);
    if (ctx->DURATION()) {
      d.expr = make(Expr::Kind::Duration, where);
      d.expr->number = seconds_of_duration(tx(ctx->DURATION()));
    } else if (ctx->NUMBER()) {
      d.expr = make(Expr::Kind::Number, where);
      std::string text = tx(ctx->NUMBER());
      d.expr->number = std::strtod(text.c_str(), nullptr);
      d.expr->is_int = text.find_first_of(".eE") == std::string::npos;
    } else {
      d.expr = make(Expr::Kind::Name, where);
      d.expr->text = tx(ctx->ID());
    }
    return d;
  }

  std::optional<Duration> optional_duration(ArbcParser::DurationContext* ctx) {
    if (!ctx) return std::nullopt;
    return duration(ctx);
  }

  // ---- statements ---------------------------------------------------------------------------
  // block : '{' stmt* '}' ;
  Block block(ArbcParser::BlockContext* ctx, int depth) {
    Block b;
    if (too_deep(depth, loc(ctx))) return b;
    for (ArbcParser::StmtContext* s : ctx->stmt()) b.push_back(stmt(s, depth));
    return b;
  }

  std::unique_ptr<Stmt> make_stmt(Stmt::Kind kind, antlr4::ParserRuleContext* ctx) {
    auto s = std::make_unique<Stmt>();
    s->kind = kind;
    s->loc = loc(ctx);
    return s;
  }

  void set_name(Stmt& s, antlr4::tree::TerminalNode* id) {
    s.name = tx(id);
    s.name_loc = loc(id);
  }

  // stmt : let | var | assign | accept | set | unset | if | emit | throttle | every | script
  std::unique_ptr<Stmt> stmt(ArbcParser::StmtContext* ctx, int depth) {
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
  std::unique_ptr<Stmt> if_chain(ArbcParser::IfStmtContext* c, int depth) {
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

  // ---- declarations -------------------------------------------------------------------------
  PortRef port_ref(ArbcParser::PortRefContext* ctx) {  // portRef : ID '.' ID ;
    PortRef p;
    auto* module = child<antlr4::tree::TerminalNode>(ctx, 0);
    auto* port = child<antlr4::tree::TerminalNode>(ctx, 2);
    p.module = tx(module);
    p.port = tx(port);
    p.loc = loc(ctx);
    p.module_loc = loc(module);
    p.port_loc = loc(port);
    return p;
  }

  void add_decl(Spec& spec, ArbcParser::DeclContext* ctx) {
    reported_depth_ = false;
    if (auto* c = ctx->appDecl()) {
      add_app(spec, c);
    } else if (auto* c = ctx->typeDecl()) {
      spec.types.push_back(type_decl(c));
    } else if (auto* c = ctx->constDecl()) {
      spec.consts.push_back(const_decl(c));
    } else if (auto* c = ctx->moduleDecl()) {
      spec.modules.push_back(module_decl(c));
    } else if (auto* c = ctx->eventDecl()) {
      spec.events.push_back(event_decl(c));
    } else if (auto* c = ctx->derivedEventDecl()) {
      spec.derived_events.push_back(derived_event_decl(c));
    } else if (auto* c = ctx->statusEventsDecl()) {
      spec.status_events.push_back(status_events_decl(c));
    } else if (auto* c = ctx->exclusiveDecl()) {
      spec.exclusives.push_back(exclusive_decl(c));
    } else if (auto* c = ctx->invariantDecl()) {
      spec.invariants.push_back(invariant_decl(c));
    } else if (auto* c = ctx->arbitrateDecl()) {
      spec.arbitrations.push_back(arbitrate_decl(c));
    } else if (auto* c = ctx->connectDecl()) {
      spec.connects.push_back(connect_decl(c));
    } else if (auto* c = ctx->assertDecl()) {
      spec.asserts.push_back(assert_decl(c));
    } else if (auto* c = ctx->neverDecl()) {
      spec.temporal.push_back(never_decl(c));
    } else if (auto* c = ctx->onlyAfterDecl()) {
      spec.temporal.push_back(only_after_decl(c));
    } else if (auto* c = ctx->assumeDecl()) {
      spec.assumptions.push_back(assume_decl(c));
    } else if (auto* c = ctx->responseDecl()) {
      spec.temporal.push_back(response_decl(c));
    } else if (auto* c = ctx->stableDecl()) {
      TemporalDecl n;
      n.kind = TemporalDecl::Kind::Stability;
      n.loc = loc(c->getStart());
      n.port = port_ref(c->portRef());
      n.window = duration(c->duration());
      spec.temporal.push_back(std::move(n));
    } else if (auto* c = ctx->givenDecl()) {
      spec.rates.push_back({port_ref(c->portRef()), duration(c->duration()), loc(c->getStart())});
    } else if (auto* c = ctx->resourceDecl()) {
      spec.resources.push_back(resource_decl(c));
    } else if (auto* c = ctx->testDecl()) {
      spec.tests.push_back(test_decl(c));
    } else if (auto* c = ctx->testsForDecl()) {
      add_tests_for(spec, c);
    }
  }

  // appDecl : 'app' ID STRING? ';' ;   at most one per spec
  void add_app(Spec& spec, ArbcParser::AppDeclContext* c) {
    AppDecl app;
    app.name = tx(c->ID());
    if (c->STRING()) app.doc = decode_string(c->STRING());
    app.loc = loc(c->ID());
    if (spec.app) {
      error(app.loc,
            "the app is already declared as '" + spec.app->name + "' at line " +
                std::to_string(spec.app->loc.line) + ": a spec describes one app",
            "duplicate");
      return;
    }
    spec.app = std::move(app);
  }

  // typeDecl : 'type' ID '=' typeExpr ';' ;
  TypeDecl type_decl(ArbcParser::TypeDeclContext* c) {
    TypeDecl t;
    t.name = tx(c->ID());
    t.loc = loc(c->ID());
    t.type = type_expr(c->typeExpr());
    return t;
  }

  // constDecl : 'const' ID '=' expr ';' ;
  ConstDecl const_decl(ArbcParser::ConstDeclContext* c) {
    ConstDecl k;
    k.name = tx(c->ID());
    k.loc = loc(c->ID());
    k.value = expr(c->expr(), 0);
    return k;
  }

  // moduleDecl : 'module' ID STRING? '{' portDecl* '}' ;
  ModuleDecl module_decl(ArbcParser::ModuleDeclContext* c) {
    ModuleDecl m;
    m.name = tx(c->ID());
    m.loc = loc(c->ID());
    if (c->STRING()) m.doc = decode_string(c->STRING());
    for (ArbcParser::PortDeclContext* p : c->portDecl()) {
      PortDecl port;
      port.name = tx(p->ID());
      port.loc = loc(p->ID());
      port.direction = tx(p->direction) == "in" ? model::Direction::In : model::Direction::Out;
      port.type = type_expr(p->typeExpr());
      m.ports.push_back(std::move(port));
    }
    return m;
  }

  // eventDecl : 'event' ID (',' ID)* ('lifetime' duration)? ';' ;
  EventDecl event_decl(ArbcParser::EventDeclContext* c) {
    EventDecl e;
    e.loc = loc(c);
    for (antlr4::tree::TerminalNode* id : c->ID()) e.names.push_back({tx(id), loc(id)});
    e.lifetime = optional_duration(c->duration());
    return e;
  }

  // resourceDecl : 'resource' ID '{' portRef (',' portRef)* ','? '}' ('when' expr)? ';' ;
  ResourceDecl resource_decl(ArbcParser::ResourceDeclContext* c) {
    ResourceDecl r;
    r.name = tx(c->ID());
    r.loc = loc(c->ID());
    for (ArbcParser::PortRefContext* p : c->portRef()) r.ports.push_back(port_ref(p));
    if (c->expr()) r.uses = expr(c->expr(), 0);
    return r;
  }

  // derivedEventDecl : 'event' ID '=' portRef ':' expr ('for' duration)? ';' ;
  DerivedEventDecl derived_event_decl(ArbcParser::DerivedEventDeclContext* c) {
    DerivedEventDecl e;
    e.name = tx(c->ID());
    e.loc = loc(c->ID());
    e.source = port_ref(c->portRef());
    e.predicate = expr(c->expr(), 0);
    e.lifetime = optional_duration(c->duration());
    return e;
  }

  // statusEventsDecl : 'events' 'from' portRef '{' statusEntry (',' statusEntry)* '}'
  //                    ('lifetime' duration)? ';' ;
  StatusEventDecl status_events_decl(ArbcParser::StatusEventsDeclContext* c) {
    StatusEventDecl e;
    e.loc = loc(c);
    e.source = port_ref(c->portRef());
    for (ArbcParser::StatusEntryContext* entry : c->statusEntry()) {
      StatusEventDecl::Entry x;
      x.event = tx(entry->ID());
      x.flag = entry->STRING() ? decode_string(entry->STRING()) : x.event;
      x.loc = loc(entry);
      e.entries.push_back(std::move(x));
    }
    e.lifetime = optional_duration(c->duration());
    return e;
  }

  // exclusiveDecl : 'exclusive' '{' ID (',' ID)* '}' ';' ;
  ExclusiveDecl exclusive_decl(ArbcParser::ExclusiveDeclContext* c) {
    ExclusiveDecl x;
    x.loc = loc(c);
    for (antlr4::tree::TerminalNode* id : c->ID()) x.events.push_back({tx(id), loc(id)});
    return x;
  }

  // invariantDecl : 'invariant' expr ';' ;
  InvariantDecl invariant_decl(ArbcParser::InvariantDeclContext* c) {
    InvariantDecl inv;
    inv.loc = loc(c);
    inv.formula = expr(c->expr(), 0);
    return inv;
  }

  // arbitrateDecl : 'arbitrate' portRef ('by' 'priority')? 'complete'? '{' ruleDecl* '}' ;
  ArbitrateDecl arbitrate_decl(ArbcParser::ArbitrateDeclContext* c) {
    ArbitrateDecl a;
    a.loc = loc(c->getStart());
    a.port = port_ref(c->portRef());
    a.by_priority = c->byPriority != nullptr;
    a.complete = c->isComplete != nullptr;
    std::vector<ArbcParser::RuleDeclContext*> rules = c->ruleDecl();
    a.rules.reserve(rules.size());  // a Rule is ~400 bytes: growing by doubling touches twice that
    for (ArbcParser::RuleDeclContext* r : rules) a.rules.push_back(rule(r));
    return a;
  }

  // connectDecl : 'connect' portRef '->' portRef (block | ';') ;
  ConnectDecl connect_decl(ArbcParser::ConnectDeclContext* c) {
    ConnectDecl k;
    k.loc = loc(c->getStart());
    k.source = port_ref(c->portRef(0));
    k.destination = port_ref(c->portRef(1));
    if (c->block()) {
      k.has_body = true;
      k.body = block(c->block(), 0);
    }
    return k;
  }

  // assertDecl : 'assert' portRef ':' ID '->' expr ';' ;
  AssertDecl assert_decl(ArbcParser::AssertDeclContext* c) {
    AssertDecl a;
    a.loc = loc(c->getStart());
    a.port = port_ref(c->portRef());
    a.rule = tx(c->ID());
    a.rule_loc = loc(c->ID());
    a.property = expr(c->expr(), 0);
    return a;
  }

  // neverDecl : 'never' ('two' ID 'within' duration
  //                       | ID ('within' duration 'after' ID | 'while' ID)) ';' ;
  TemporalDecl never_decl(ArbcParser::NeverDeclContext* c) {
    TemporalDecl n;
    n.loc = loc(c->getStart());
    n.rule = tx(c->ID(0));
    n.rule_loc = loc(c->ID(0));
    if (c->duration()) {
      n.kind = TemporalDecl::Kind::Spacing;
      n.window = duration(c->duration());
      if (c->ID().size() > 1) {  // `never RULE within D after OTHER;`
        n.other = tx(c->ID(1));
        n.other_loc = loc(c->ID(1));
      }
    } else {
      n.kind = TemporalDecl::Kind::Absence;
      n.event = tx(c->ID(1));
      n.event_loc = loc(c->ID(1));
    }
    return n;
  }

  // onlyAfterDecl : 'only' ID 'after' ID ';' ;
  TemporalDecl only_after_decl(ArbcParser::OnlyAfterDeclContext* c) {
    TemporalDecl n;
    n.kind = TemporalDecl::Kind::Precedence;
    n.loc = loc(c->getStart());
    n.rule = tx(c->ID(0));
    n.rule_loc = loc(c->ID(0));
    n.other = tx(c->ID(1));
    n.other_loc = loc(c->ID(1));
    return n;
  }

  // assumeDecl : 'assume' (ID 'only' 'after' ID ('until' ID)?
  //                        | 'not' ID 'for' duration 'after' ID) ';' ;
  AssumeDecl assume_decl(ArbcParser::AssumeDeclContext* c) {
    AssumeDecl a;
    a.loc = loc(c->getStart());
    a.event = tx(c->ID(0));
    a.event_loc = loc(c->ID(0));
    a.after = tx(c->ID(1));
    a.after_loc = loc(c->ID(1));
    if (c->duration()) a.absent_for = duration(c->duration());
    if (c->ID().size() > 2) {
      a.until = tx(c->ID(2));
      a.until_loc = loc(c->ID(2));
    }
    return a;
  }

  // responseDecl : 'after' ID 'stops'? ',' (ID | portRef) 'within' duration ('while' expr)? ';' ;
  // The trigger is a rule or an event: sema tells which (TemporalDecl::other).
  TemporalDecl response_decl(ArbcParser::ResponseDeclContext* c) {
    TemporalDecl n;
    n.kind = TemporalDecl::Kind::Response;
    n.loc = loc(c->getStart());
    n.other = tx(c->ID(0));
    n.other_loc = loc(c->ID(0));
    n.stops = c->stops != nullptr;
    if (c->served) {
      n.port = port_ref(c->served);
    } else {
      n.rule = tx(c->ID(1));
      n.rule_loc = loc(c->ID(1));
    }
    n.window = duration(c->duration());
    if (c->expr()) n.condition = expr(c->expr(), 0);
    return n;
  }

  // testsForDecl : 'tests' 'for' STRING ';' ;   at most one per file
  void add_tests_for(Spec& spec, ArbcParser::TestsForDeclContext* c) {
    TestsFor f{decode_string(c->STRING()), loc(c->STRING())};
    if (spec.tests_for) {
      error(f.loc,
            "this file already names the app it tests (\"" + spec.tests_for->path + "\" at line " +
                std::to_string(spec.tests_for->loc.line) +
                "); a tests file tests one app: keep one `tests for`",
            "duplicate");
      return;
    }
    spec.tests_for = std::move(f);
  }

  // testDecl : 'test' STRING ('on' ID)? '{' testStep* '}' ;
  TestDecl test_decl(ArbcParser::TestDeclContext* c) {
    TestDecl t;
    t.name = decode_string(c->STRING());
    t.loc = loc(c->STRING());
    if (c->ID()) {
      t.on = tx(c->ID());
      t.on_loc = loc(c->ID());
    }
    for (ArbcParser::TestStepContext* step : c->testStep()) add_test_step(t, step);
    return t;
  }

  // ---- rules (private below) --------------------------------------------------------------
 private:
  // testStep : 'at' duration portRef '<-' expr ';' | 'at' duration ('set'|'unset') ID ';'
  //          | 'expect' ... ;   (the four expectations of ast::TestExpect)
  void add_test_step(TestDecl& t, ArbcParser::TestStepContext* step) {
    if (auto* c = as<ArbcParser::TestInputContext>(step)) {
      TestStep s;
      s.loc = loc(c);
      s.at = duration(c->duration());
      s.port = port_ref(c->portRef());
      s.value = expr(c->expr(), 0);
      t.steps.push_back(std::move(s));
    } else if (auto* c = as<ArbcParser::TestEventContext>(step)) {
      TestStep s;
      s.kind = tx(c->op) == "set" ? TestStep::Kind::Set : TestStep::Kind::Unset;
      s.loc = loc(c);
      s.at = duration(c->duration());
      s.event = tx(c->ID());
      s.event_loc = loc(c->ID());
      t.steps.push_back(std::move(s));
    } else {
      t.expects.push_back(test_expect(step));
    }
  }

  TestExpect test_expect(ArbcParser::TestStepContext* step) {
    TestExpect e;
    e.loc = loc(step);
    e.text = spaced_text(step);
    ArbcParser::TestWindowContext* window = nullptr;
    if (auto* c = as<ArbcParser::ExpectReceivesContext>(step)) {
      e.kind = c->nothing ? TestExpect::Kind::Nothing : TestExpect::Kind::Receives;
      e.port = port_ref(c->portRef());
      if (c->expr()) e.value = expr(c->expr(), 0);
      window = c->testWindow();
    } else if (auto* c = as<ArbcParser::ExpectDropsContext>(step)) {
      e.kind = TestExpect::Kind::Drops;
      e.rule = tx(c->ID());
      e.rule_loc = loc(c->ID());
      if (c->STRING()) {
        e.reason = decode_string(c->STRING());
        e.reason_loc = loc(c->STRING());
      }
      window = c->testWindow();
    } else if (auto* c = as<ArbcParser::ExpectStateContext>(step)) {
      e.kind = TestExpect::Kind::State;
      e.value = expr(c->expr(), 0);
      window = c->testWindow();
    }
    if (window) {
      e.window.present = true;
      e.window.loc = loc(window);
      e.window.from = duration(window->duration(0));
      if (window->duration().size() > 1) e.window.to = duration(window->duration(1));
    }
    return e;
  }

  // The text of an expectation as written, minus `expect` and `;`, tokens joined by single
  // spaces except around `.`, `,`, brackets and `..`: for a test's failure message.
  std::string spaced_text(antlr4::ParserRuleContext* ctx) {
    std::vector<antlr4::Token*> tokens;
    collect_tokens(ctx, tokens);
    std::string out;
    std::string previous;
    for (size_t i = 1; i + 1 < tokens.size(); ++i) {
      std::string text = tx(tokens[i]);
      bool glue = previous == "." || previous == "(" || previous == "[" || previous == ".." ||
                  text == "." || text == "," || text == ")" || text == "]" || text == ".." ||
                  text == ":" ||
                  (text == "(" && !previous.empty() &&
                   std::isalnum(static_cast<unsigned char>(previous.back())));
      if (!out.empty() && !glue) out += ' ';
      out += text;
      previous = text;
    }
    return out;
  }

  static void collect_tokens(antlr4::tree::ParseTree* node, std::vector<antlr4::Token*>& out) {
    if (auto* leaf = dynamic_cast<antlr4::tree::TerminalNode*>(node)) {
      out.push_back(leaf->getSymbol());
      return;
    }
    for (antlr4::tree::ParseTree* child : node->children) collect_tokens(child, out);
  }

  // ruleDecl : ID ':' 'from' portRef ('when' expr)? ('hold' duration)? (block | ';') ;
  // The optional parts are found in one pass over the children, not by the generated accessors,
  // each of which dynamic_casts every child: a spec's rules are most of its declarations.
  Rule rule(ArbcParser::RuleDeclContext* c) {
    Rule r;
    auto* name = child<antlr4::tree::TerminalNode>(c, 0);
    r.name = tx(name);
    r.loc = loc(name);
    r.source = port_ref(child<ArbcParser::PortRefContext>(c, 3));
    for (size_t i = 4; i < c->children.size(); ++i) {
      auto* part = dynamic_cast<antlr4::ParserRuleContext*>(c->children[i]);
      if (!part) continue;  // 'when', 'hold', ';'
      switch (part->getRuleIndex()) {
        case ArbcParser::RuleExpr:
          r.when = expr(static_cast<ArbcParser::ExprContext*>(part), 0);
          break;
        case ArbcParser::RuleDuration:
          r.hold = duration(static_cast<ArbcParser::DurationContext*>(part));
          break;
        case ArbcParser::RuleBlock:
          r.has_body = true;
          r.body = block(static_cast<ArbcParser::BlockContext*>(part), 0);
          break;
        default:
          break;
      }
    }
    return r;
  }

  model::FileName file_;  // interned once: every location copies it
  TokenText text_;
  std::vector<Diagnostic>& out_;
  bool reported_depth_ = false;
};

AstBuilder::AstBuilder(const std::string& file, std::string_view source,
                       std::vector<Diagnostic>& out)
    : builder_(std::make_unique<Builder>(file, source, out)), spec_(std::make_unique<Spec>()) {
  spec_->file = file;
}

AstBuilder::~AstBuilder() = default;

void AstBuilder::add_declaration(void* decl) {
  builder_->add_decl(*spec_, static_cast<ArbcParser::DeclContext*>(decl));
}

std::unique_ptr<Spec> AstBuilder::finish() { return std::move(spec_); }

}  // namespace arbc::frontend

#include "import/yarp/lua_parser.h"

#include <vector>

#include "import/yarp/lua_lexer.h"

namespace arbc::yarp {
namespace {

using Kind = LuaToken::Kind;
constexpr int kMaxDepth = 200;

// Binary operator priorities (left, right) from lparser.c: right < left means right-assoc.
struct BinaryOp {
  std::string_view op;
  int left, right;
};
constexpr BinaryOp kBinary[] = {
    {"or", 1, 1},   {"and", 2, 2}, {"<", 3, 3},   {">", 3, 3},   {"<=", 3, 3},  {">=", 3, 3},
    {"~=", 3, 3},   {"==", 3, 3},  {"|", 4, 4},   {"~", 5, 5},   {"&", 6, 6},   {"<<", 7, 7},
    {">>", 7, 7},   {"..", 9, 8},  {"+", 10, 10}, {"-", 10, 10}, {"*", 11, 11}, {"/", 11, 11},
    {"//", 11, 11}, {"%", 11, 11}, {"^", 14, 13}};
constexpr int kUnaryPriority = 12;

// A recursive-descent parser. Errors set `error_` once; every loop checks ok() so a failed
// parse stops quickly, and the caller discards the partial tree.
class Parser {
 public:
  explicit Parser(std::vector<LuaToken> tokens) : t_(std::move(tokens)) {}

  std::shared_ptr<LuaFunction> chunk(std::string* err) {
    auto f = std::make_shared<LuaFunction>();
    f->vararg = true;
    f->line = 1;
    f->body = block();
    if (ok() && peek().kind != Kind::End) fail("'<eof>' expected");
    f->end_line = peek().line;
    if (!ok()) {
      if (err) *err = error_;
      return nullptr;
    }
    return f;
  }

 private:
  bool ok() const { return error_.empty(); }
  const LuaToken& peek(size_t ahead = 0) const {
    size_t i = pos_ + ahead;
    return i < t_.size() ? t_[i] : t_.back();
  }
  bool is(std::string_view text) const {
    const LuaToken& t = peek();
    return (t.kind == Kind::Keyword || t.kind == Kind::Symbol) && t.text == text;
  }
  bool accept(std::string_view text) {
    if (!is(text)) return false;
    ++pos_;
    return true;
  }
  void fail(const std::string& what) {
    if (!ok()) return;
    const LuaToken& t = peek();
    std::string near = t.kind == Kind::End ? "<eof>" : t.text;
    error_ = std::to_string(t.line) + ": " + what + " near '" + near + "'";
  }
  void expect(std::string_view text) {
    if (!accept(text)) fail("'" + std::string(text) + "' expected");
  }
  std::string name() {
    if (peek().kind != Kind::Name) {
      fail("<name> expected");
      return "";
    }
    return t_[pos_++].text;
  }
  bool block_ends() const {
    return peek().kind == Kind::End || is("end") || is("else") || is("elseif") || is("until");
  }
  // Guards recursion depth for hostile input.
  bool enter() {
    if (++depth_ > kMaxDepth) fail("nesting too deep");
    return ok();
  }

  LuaBlock block() {
    LuaBlock b;
    if (!enter()) return b;
    while (ok() && !block_ends()) {
      if (is("return")) {
        b.stats.push_back(return_stat());
        break;
      }
      if (accept(";")) continue;
      b.stats.push_back(statement());
    }
    --depth_;
    return b;
  }

  LuaStat return_stat() {
    LuaStat s;
    s.kind = LuaStat::Kind::Return;
    s.line = peek().line;
    expect("return");
    if (!block_ends() && !is(";")) s.exprs = expr_list();
    accept(";");
    return s;
  }

  LuaStat statement() {
    LuaStat s;
    s.line = peek().line;
    if (accept("break")) {
      s.kind = LuaStat::Kind::Break;
    } else if (accept("goto")) {
      s.kind = LuaStat::Kind::Goto;
      s.names.push_back(name());
    } else if (accept("::")) {
      s.kind = LuaStat::Kind::Label;
      s.names.push_back(name());
      expect("::");
    } else if (accept("do")) {
      s.kind = LuaStat::Kind::Do;
      s.blocks.push_back(block());
      expect("end");
    } else if (accept("while")) {
      s.kind = LuaStat::Kind::While;
      s.exprs.push_back(expr());
      expect("do");
      s.blocks.push_back(block());
      expect("end");
    } else if (accept("repeat")) {
      s.kind = LuaStat::Kind::Repeat;
      s.blocks.push_back(block());
      expect("until");
      s.exprs.push_back(expr());
    } else if (is("if")) {
      if_stat(s);
    } else if (accept("for")) {
      for_stat(s);
    } else if (accept("function")) {
      s.kind = LuaStat::Kind::Function;
      function_stat(s);
    } else if (accept("local")) {
      local_stat(s);
    } else {
      expr_stat(s);
    }
    return s;
  }

  void if_stat(LuaStat& s) {
    s.kind = LuaStat::Kind::If;
    do {
      ++pos_;  // `if` or `elseif`
      s.exprs.push_back(expr());
      expect("then");
      s.blocks.push_back(block());
    } while (ok() && is("elseif"));
    if (accept("else")) s.blocks.push_back(block());
    expect("end");
  }

  void for_stat(LuaStat& s) {
    s.names.push_back(name());
    if (accept("=")) {
      s.kind = LuaStat::Kind::NumericFor;
      s.exprs.push_back(expr());
      expect(",");
      s.exprs.push_back(expr());
      if (accept(",")) s.exprs.push_back(expr());
    } else {
      s.kind = LuaStat::Kind::GenericFor;
      while (ok() && accept(",")) s.names.push_back(name());
      expect("in");
      s.exprs = expr_list();
    }
    expect("do");
    s.blocks.push_back(block());
    expect("end");
  }

  // function a.b.c:m (...) ... end: targets[0] is the Index chain a.b.c.m; a method gets `self`.
  void function_stat(LuaStat& s) {
    int line = peek().line;
    LuaExprPtr target = name_expr(name(), line);
    bool method = false;
    while (ok() && (is(".") || is(":"))) {
      method = is(":");
      ++pos_;
      target = index(std::move(target), string_expr(name(), line), line);
      if (method) break;
    }
    s.targets.push_back(std::move(target));
    s.function = function_body(line);
    if (method && s.function) s.function->params.insert(s.function->params.begin(), "self");
  }

  void local_stat(LuaStat& s) {
    if (accept("function")) {
      s.kind = LuaStat::Kind::LocalFunction;
      s.names.push_back(name());
      s.function = function_body(s.line);
      return;
    }
    s.kind = LuaStat::Kind::Local;
    do {
      s.names.push_back(name());
      if (accept("<")) {  // <const> or <close>
        name();
        expect(">");
      }
    } while (ok() && accept(","));
    if (accept("=")) s.exprs = expr_list();
  }

  void expr_stat(LuaStat& s) {
    LuaExprPtr first = suffixed_expr();
    if (!ok()) return;
    if (is("=") || is(",")) {
      s.kind = LuaStat::Kind::Assign;
      s.targets.push_back(std::move(first));
      while (ok() && accept(",")) s.targets.push_back(suffixed_expr());
      expect("=");
      s.exprs = expr_list();
      for (const LuaExprPtr& t : s.targets) {
        if (t && t->kind != LuaExpr::Kind::Name && t->kind != LuaExpr::Kind::Index) {
          fail("syntax error");
        }
      }
      return;
    }
    if (first->kind != LuaExpr::Kind::Call && first->kind != LuaExpr::Kind::Method) {
      fail("syntax error");
      return;
    }
    s.kind = LuaStat::Kind::Call;
    s.exprs.push_back(std::move(first));
  }

  std::shared_ptr<LuaFunction> function_body(int line) {
    auto f = std::make_shared<LuaFunction>();
    f->line = line;
    expect("(");
    if (!is(")")) {
      do {
        if (accept("...")) {
          f->vararg = true;
          break;
        }
        f->params.push_back(name());
      } while (ok() && accept(","));
    }
    expect(")");
    f->body = block();
    f->end_line = peek().line;
    expect("end");
    return f;
  }

  std::vector<LuaExprPtr> expr_list() {
    std::vector<LuaExprPtr> out;
    out.push_back(expr());
    while (ok() && accept(",")) out.push_back(expr());
    return out;
  }

  static LuaExprPtr make(LuaExpr::Kind kind, int line) {
    auto e = std::make_unique<LuaExpr>();
    e->kind = kind;
    e->line = line;
    return e;
  }
  static LuaExprPtr name_expr(std::string n, int line) {
    LuaExprPtr e = make(LuaExpr::Kind::Name, line);
    e->text = std::move(n);
    return e;
  }
  static LuaExprPtr string_expr(std::string s, int line) {
    LuaExprPtr e = make(LuaExpr::Kind::String, line);
    e->text = std::move(s);
    return e;
  }
  static LuaExprPtr index(LuaExprPtr object, LuaExprPtr key, int line) {
    LuaExprPtr e = make(LuaExpr::Kind::Index, line);
    e->items.push_back(std::move(object));
    e->items.push_back(std::move(key));
    return e;
  }

  const BinaryOp* binary_op() const {
    const LuaToken& t = peek();
    if (t.kind != Kind::Keyword && t.kind != Kind::Symbol) return nullptr;
    for (const BinaryOp& op : kBinary) {
      if (t.text == op.op) return &op;
    }
    return nullptr;
  }

  // subexpr of lparser.c: operators with a left priority above `limit`.
  LuaExprPtr expr(int limit = 0) {
    if (!enter()) return make(LuaExpr::Kind::Nil, peek().line);
    LuaExprPtr left;
    int line = peek().line;
    if (is("not") || is("-") || is("#") || is("~")) {
      LuaExprPtr u = make(LuaExpr::Kind::Unary, line);
      u->text = t_[pos_++].text;
      u->items.push_back(expr(kUnaryPriority));
      left = std::move(u);
    } else {
      left = simple_expr();
    }
    for (const BinaryOp* op = binary_op(); ok() && op && op->left > limit; op = binary_op()) {
      LuaExprPtr b = make(LuaExpr::Kind::Binary, peek().line);
      b->text = t_[pos_++].text;
      b->items.push_back(std::move(left));
      b->items.push_back(expr(op->right));
      left = std::move(b);
    }
    --depth_;
    return left;
  }

  LuaExprPtr simple_expr() {
    const LuaToken& t = peek();
    int line = t.line;
    if (t.kind == Kind::Number) {
      LuaExprPtr e = make(LuaExpr::Kind::Number, line);
      e->number = t.number;
      e->text = t.text;
      ++pos_;
      return e;
    }
    if (t.kind == Kind::String) {
      ++pos_;
      return string_expr(t.text, line);
    }
    if (accept("nil")) return make(LuaExpr::Kind::Nil, line);
    if (accept("true")) return make(LuaExpr::Kind::True, line);
    if (accept("false")) return make(LuaExpr::Kind::False, line);
    if (accept("...")) return make(LuaExpr::Kind::Vararg, line);
    if (is("{")) return table();
    if (accept("function")) {
      LuaExprPtr e = make(LuaExpr::Kind::Function, line);
      e->function = function_body(line);
      return e;
    }
    return suffixed_expr();
  }

  LuaExprPtr primary_expr() {
    int line = peek().line;
    if (peek().kind == Kind::Name) return name_expr(t_[pos_++].text, line);
    if (accept("(")) {
      LuaExprPtr e = make(LuaExpr::Kind::Paren, line);
      e->items.push_back(expr());
      expect(")");
      return e;
    }
    fail("unexpected symbol");
    return make(LuaExpr::Kind::Nil, line);
  }

  LuaExprPtr suffixed_expr() {
    LuaExprPtr e = primary_expr();
    while (ok()) {
      int line = peek().line;
      if (accept(".")) {
        e = index(std::move(e), string_expr(name(), line), line);
      } else if (accept("[")) {
        LuaExprPtr key = expr();
        expect("]");
        e = index(std::move(e), std::move(key), line);
      } else if (accept(":")) {
        LuaExprPtr m = make(LuaExpr::Kind::Method, line);
        m->text = name();
        m->items.push_back(std::move(e));
        call_args(*m);
        e = std::move(m);
      } else if (is("(") || is("{") || peek().kind == Kind::String) {
        LuaExprPtr c = make(LuaExpr::Kind::Call, line);
        c->items.push_back(std::move(e));
        call_args(*c);
        e = std::move(c);
      } else {
        return e;
      }
    }
    return e;
  }

  void call_args(LuaExpr& call) {
    if (peek().kind == Kind::String) {
      call.items.push_back(string_expr(peek().text, peek().line));
      ++pos_;
    } else if (is("{")) {
      call.items.push_back(table());
    } else {
      expect("(");
      if (!is(")")) {
        for (LuaExprPtr& a : expr_list()) call.items.push_back(std::move(a));
      }
      expect(")");
    }
  }

  LuaExprPtr table() {
    LuaExprPtr e = make(LuaExpr::Kind::Table, peek().line);
    expect("{");
    while (ok() && !is("}")) {
      if (accept("[")) {
        e->items.push_back(expr());
        expect("]");
        expect("=");
      } else if (peek().kind == Kind::Name && peek(1).kind == Kind::Symbol && peek(1).text == "=") {
        e->items.push_back(string_expr(peek().text, peek().line));
        pos_ += 2;
      }
      e->items.push_back(expr());
      if (!accept(",") && !accept(";")) break;
    }
    expect("}");
    return e;
  }

  std::vector<LuaToken> t_;
  size_t pos_ = 0;
  int depth_ = 0;
  std::string error_;
};

}  // namespace

std::shared_ptr<LuaFunction> parse_lua(std::string_view source, std::string* err) {
  std::optional<std::vector<LuaToken>> tokens = lua_tokens(source, err);
  if (!tokens) return nullptr;
  return Parser(std::move(*tokens)).chunk(err);
}

}  // namespace arbc::yarp

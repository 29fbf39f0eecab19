#include "core/body_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/json_text.h"

namespace arbc::model {

namespace {

const char* const kBinaryOps[] = {
    "+", "-", "*", "/", "%", "<", "<=", ">", ">=", "==", "!=", "and", "or"};

bool is_binary_op(std::string_view s) {
  for (const char* op : kBinaryOps)
    if (s == op) return true;
  return false;
}

void append_number(std::string& out, const BodyExpr& e) {
  if (e.op == BodyExpr::Op::Int) {
    // A uint64 literal as its unsigned digits, which the reader types uint64 (above 2^63 - 1).
    out += e.text == kUint64Literal ? std::to_string(static_cast<uint64_t>(e.integer))
                                    : std::to_string(e.integer);
  } else if (!std::isfinite(e.number)) {
    out += std::isnan(e.number) ? "nan" : (e.number > 0 ? "inf" : "-inf");
  } else {
    append_json_double(out, e.number);  // keeps a ".0" on integral values: a float
  }
}

void append_expr(std::string& out, const BodyExpr& e) {
  using Op = BodyExpr::Op;
  auto node = [&](const char* head, const std::string* name) {
    out += '(';
    out += head;
    if (name) out += ' ' + *name;
    for (const BodyExpr& a : e.args) {
      out += ' ';
      append_expr(out, a);
    }
    out += ')';
  };
  switch (e.op) {
    case Op::Message:
      out += "msg";
      return;
    case Op::Int:
    case Op::Float:
      append_number(out, e);
      return;
    case Op::String:
      append_json_string(out, e.text);
      return;
    case Op::Bool:
      out += e.boolean ? "true" : "false";
      return;
    case Op::Local:
      return node("local", &e.text);
    case Op::Param:
      return node("param", &e.text);
    case Op::Field:
      return node("field", &e.text);
    case Op::Index:
      return node("index", nullptr);
    case Op::Neg:
      return node("neg", nullptr);
    case Op::Not:
      return node("not", nullptr);
    case Op::Binary:
      return node(e.text.c_str(), nullptr);
    case Op::Record:
      out += "(record";
      for (size_t i = 0; i < e.args.size() && i < e.names.size(); ++i) {
        out += ' ' + e.names[i] + ' ';
        append_expr(out, e.args[i]);
      }
      out += ')';
      return;
    case Op::List:
      return node("list", nullptr);
    case Op::Lambda:
      return node("lambda", &e.text);
    case Op::Call:
      return node("call", &e.text);
    case Op::ToFloat:
      return node("float", nullptr);
  }
}

const char* stmt_head(BodyStmt::Kind k) {
  switch (k) {
    case BodyStmt::Kind::Let:
      return "let";
    case BodyStmt::Kind::Var:
      return "var";
    case BodyStmt::Kind::Assign:
      return "assign";
    case BodyStmt::Kind::Accept:
      return "accept";
    case BodyStmt::Kind::Set:
      return "set";
    case BodyStmt::Kind::Unset:
      return "unset";
    case BodyStmt::Kind::If:
      return "if";
    case BodyStmt::Kind::Emit:
      return "emit";
    case BodyStmt::Kind::Throttle:
      return "throttle";
    case BodyStmt::Kind::Every:
      return "every";
  }
  return "?";
}

void append_block(std::string& out, const std::vector<BodyStmt>& b);

void append_stmt(std::string& out, const BodyStmt& s) {
  using Kind = BodyStmt::Kind;
  out += '(';
  out += stmt_head(s.kind);
  out += ' ' + std::to_string(s.line);
  switch (s.kind) {
    case Kind::Let:
    case Kind::Var:
    case Kind::Assign:
      out += ' ' + s.name + ' ';
      append_expr(out, s.expr);
      break;
    case Kind::Accept:
    case Kind::Emit:
      out += ' ';
      append_expr(out, s.expr);
      break;
    case Kind::Set:
    case Kind::Unset:
      out += ' ' + s.name;
      if (s.lifetime) {
        out += ' ';
        append_json_seconds(out, *s.lifetime);  // exact (core/instant.h)
      }
      break;
    case Kind::If:
      out += ' ';
      append_expr(out, s.expr);
      out += ' ';
      append_block(out, s.then_body);
      out += ' ';
      append_block(out, s.else_body);
      break;
    case Kind::Every:
      out += ' ';
      append_block(out, s.then_body);
      break;
    case Kind::Throttle:
      break;
  }
  out += ')';
}

void append_block(std::string& out, const std::vector<BodyStmt>& b) {
  out += '(';
  for (size_t i = 0; i < b.size(); ++i) {
    if (i) out += ' ';
    append_stmt(out, b[i]);
  }
  out += ')';
}

// A recursive-descent reader of the text above. Depth is bounded so that a hostile app.json
// cannot overflow the stack.
class Reader {
 public:
  explicit Reader(std::string_view text) : t_(text) {}

  bool fail(const std::string& what) {
    if (err_.empty()) err_ = what + " at offset " + std::to_string(pos_);
    return false;
  }
  const std::string& error() const { return err_; }

  void space() {
    while (pos_ < t_.size() && (t_[pos_] == ' ' || t_[pos_] == '\n' || t_[pos_] == '\t')) ++pos_;
  }
  bool at(char c) {
    space();
    return pos_ < t_.size() && t_[pos_] == c;
  }
  bool eat(char c) {
    if (!at(c)) return fail(std::string("expected '") + c + "'");
    ++pos_;
    return true;
  }
  bool at_end() {
    space();
    return pos_ == t_.size();
  }

  // A bare word: a name, a number or an operator.
  std::string word() {
    space();
    size_t b = pos_;
    while (pos_ < t_.size() && t_[pos_] != ' ' && t_[pos_] != '(' && t_[pos_] != ')' &&
           t_[pos_] != '"' && t_[pos_] != '\n' && t_[pos_] != '\t')
      ++pos_;
    return std::string(t_.substr(b, pos_ - b));
  }

  bool string_literal(std::string& out);
  bool number(const std::string& w, BodyExpr& e);
  bool expr(BodyExpr& e, int depth);
  bool node(BodyExpr& e, int depth);
  bool stmt(BodyStmt& s, int depth);
  bool block(std::vector<BodyStmt>& b, int depth);

 private:
  std::string_view t_;
  size_t pos_ = 0;
  std::string err_;
};

constexpr int kMaxDepth = 400;

bool Reader::string_literal(std::string& out) {
  if (!eat('"')) return false;
  while (pos_ < t_.size() && t_[pos_] != '"') {
    char c = t_[pos_++];
    if (c != '\\') {
      out += c;
      continue;
    }
    if (pos_ >= t_.size()) break;
    char n = t_[pos_++];
    switch (n) {
      case 'n':
        out += '\n';
        break;
      case 't':
        out += '\t';
        break;
      case 'r':
        out += '\r';
        break;
      case 'u': {
        if (pos_ + 4 > t_.size()) return fail("bad \\u escape");
        unsigned v = static_cast<unsigned>(
            std::strtoul(std::string(t_.substr(pos_, 4)).c_str(), nullptr, 16));
        if (v > 0x7f) return fail("\\u escape above 0x7f");
        out += static_cast<char>(v);
        pos_ += 4;
        break;
      }
      default:
        out += n;
    }
  }
  return eat('"');
}

bool Reader::number(const std::string& w, BodyExpr& e) {
  char* end = nullptr;
  double v = std::strtod(w.c_str(), &end);
  if (w.empty() || *end != '\0') return fail("expected an expression, got '" + w + "'");
  bool is_float = w.find_first_of(".eEna") != std::string::npos;
  e.op = is_float ? BodyExpr::Op::Float : BodyExpr::Op::Int;
  e.number = v;
  if (!is_float) {  // an int exactly: the double rounds above 2^53
    auto [last, ec] = std::from_chars(w.data(), w.data() + w.size(), e.integer);
    if (ec != std::errc() || last != w.data() + w.size()) {
      uint64_t u = 0;  // above 2^63 - 1: a uint64 literal
      auto [ulast, uec] = std::from_chars(w.data(), w.data() + w.size(), u);
      if (uec != std::errc() || ulast != w.data() + w.size())
        return fail("the int '" + w + "' does not fit in 64 bits");
      e.integer = static_cast<int64_t>(u);
      e.text = kUint64Literal;
    }
  }
  return true;
}

bool Reader::expr(BodyExpr& e, int depth) {
  if (depth > kMaxDepth) return fail("nested too deeply");
  if (at('"')) {
    e.op = BodyExpr::Op::String;
    return string_literal(e.text);
  }
  if (at('(')) return node(e, depth);
  std::string w = word();
  if (w == "msg") {
    e.op = BodyExpr::Op::Message;
    return true;
  }
  if (w == "true" || w == "false") {
    e.op = BodyExpr::Op::Bool;
    e.boolean = w == "true";
    return true;
  }
  return number(w, e);
}

bool Reader::node(BodyExpr& e, int depth) {
  using Op = BodyExpr::Op;
  if (!eat('(')) return false;
  std::string head = word();
  struct Named {
    const char* head;
    Op op;
  };
  static const Named kNamed[] = {{"local", Op::Local},
                                 {"param", Op::Param},
                                 {"field", Op::Field},
                                 {"lambda", Op::Lambda},
                                 {"call", Op::Call}};
  static const Named kPlain[] = {{"index", Op::Index},
                                 {"neg", Op::Neg},
                                 {"not", Op::Not},
                                 {"list", Op::List},
                                 {"float", Op::ToFloat}};
  bool known = false;
  for (const Named& n : kNamed)
    if (head == n.head) {
      e.op = n.op;
      e.text = word();
      if (e.text.empty()) return fail("expected a name after '" + head + "'");
      known = true;
    }
  for (const Named& n : kPlain)
    if (head == n.head) e.op = n.op, known = true;
  if (is_binary_op(head)) e.op = Op::Binary, e.text = head, known = true;
  if (head == "record") e.op = Op::Record, known = true;
  if (!known) return fail("unknown expression '" + head + "'");
  while (!at(')')) {
    if (at_end()) return fail("unterminated expression");
    if (e.op == Op::Record) {
      e.names.push_back(word());
      if (e.names.back().empty()) return fail("expected a field name");
    }
    BodyExpr a;
    if (!expr(a, depth + 1)) return false;
    e.args.push_back(std::move(a));
  }
  bool unary = e.op == Op::Neg || e.op == Op::Not || e.op == Op::Field || e.op == Op::Lambda ||
               e.op == Op::ToFloat;
  size_t want = e.op == Op::Index || e.op == Op::Binary  ? 2
                : unary                                  ? 1
                : e.op == Op::Local || e.op == Op::Param ? 0
                                                         : e.args.size();
  if (e.args.size() != want) return fail("wrong number of operands of '" + head + "'");
  if (e.op == Op::Call)  // a name no builtin has reads as one: the proof calls it opaque
    if (const BuiltinInfo* b = find_builtin(e.text)) e.builtin = b->id;
  return eat(')');
}

bool Reader::block(std::vector<BodyStmt>& b, int depth) {
  if (depth > kMaxDepth) return fail("nested too deeply");
  if (!eat('(')) return false;
  while (!at(')')) {
    if (at_end()) return fail("unterminated block");
    BodyStmt s;
    if (!stmt(s, depth + 1)) return false;
    b.push_back(std::move(s));
  }
  return eat(')');
}

bool Reader::stmt(BodyStmt& s, int depth) {
  using Kind = BodyStmt::Kind;
  if (!eat('(')) return false;
  std::string head = word();
  bool known = false;
  for (Kind k : {Kind::Let, Kind::Var, Kind::Assign, Kind::Accept, Kind::Set, Kind::Unset, Kind::If,
                 Kind::Emit, Kind::Throttle, Kind::Every})
    if (head == stmt_head(k)) s.kind = k, known = true;
  if (!known) return fail("unknown statement '" + head + "'");
  std::string line = word();
  char* end = nullptr;
  s.line = static_cast<int>(std::strtol(line.c_str(), &end, 10));
  if (line.empty() || *end != '\0') return fail("expected a line number");
  bool ok = true;
  switch (s.kind) {
    case Kind::Let:
    case Kind::Var:
    case Kind::Assign:
      s.name = word();
      ok = !s.name.empty() && expr(s.expr, depth + 1);
      break;
    case Kind::Accept:
    case Kind::Emit:
      ok = expr(s.expr, depth + 1);
      break;
    case Kind::Set:
    case Kind::Unset:
      s.name = word();
      ok = !s.name.empty();
      if (ok && s.kind == Kind::Set && !at(')')) {  // `(set LINE NAME SECONDS)`
        // Whole nanoseconds, as every duration of app.json (core/instant.h).
        BodyExpr seconds;
        ok = number(word(), seconds) && seconds.number > 0;
        if (ok) s.lifetime = whole_nanos(seconds.number);
        ok = ok && s.lifetime.has_value();
      }
      break;
    case Kind::If:
      ok =
          expr(s.expr, depth + 1) && block(s.then_body, depth + 1) && block(s.else_body, depth + 1);
      break;
    case Kind::Every:
      ok = block(s.then_body, depth + 1);
      break;
    case Kind::Throttle:
      break;
  }
  if (!ok) return fail("malformed '" + head + "'");
  return eat(')');
}

}  // namespace

std::string body_expr_text(const BodyExpr& e) {
  std::string out;
  append_expr(out, e);
  return out;
}

std::string body_stmt_text(const BodyStmt& s) {
  std::string out;
  append_stmt(out, s);
  return out;
}

std::optional<BodyStmt> parse_body_stmt(std::string_view text, std::string* err) {
  Reader r(text);
  BodyStmt s;
  if (!r.stmt(s, 0) || (!r.at_end() && !r.fail("trailing text after the statement"))) {
    if (err) *err = r.error();
    return std::nullopt;
  }
  return s;
}

}  // namespace arbc::model

namespace arbc::model {

std::optional<BodyExpr> parse_body_expr(std::string_view text, std::string* err) {
  Reader r(text);
  BodyExpr e;
  if (!r.expr(e, 0) || (!r.at_end() && !r.fail("trailing text after the expression"))) {
    if (err) *err = r.error();
    return std::nullopt;
  }
  return e;
}

}  // namespace arbc::model

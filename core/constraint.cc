#include "core/constraint.h"

#include <algorithm>
#include <cctype>

namespace arbc {

Constraint Constraint::constant(bool value) {
  Constraint c;
  c.op = value ? Op::True : Op::False;
  return c;
}

Constraint Constraint::event_ref(std::string name) {
  Constraint c;
  c.op = Op::Event;
  c.event = std::move(name);
  return c;
}

Constraint Constraint::negate(Constraint inner) {
  Constraint c;
  c.op = Op::Not;
  c.args.push_back(std::move(inner));
  return c;
}

namespace {

Constraint nary(Constraint::Op op, std::vector<Constraint> args) {
  size_t total = 0;
  for (const Constraint& a : args) total += a.op == op ? a.args.size() : 1;
  // `a and b and c` parses as `(a and b) and c`: the first operand is the chain so far. Its
  // operands are kept in place and the rest appended, so a chain of n costs n moves, not n^2.
  std::vector<Constraint> flat;
  auto rest = args.begin();
  if (rest != args.end() && rest->op == op) flat = std::move((rest++)->args);
  flat.reserve(total);
  for (; rest != args.end(); ++rest) {
    if (rest->op == op) {
      for (Constraint& inner : rest->args) flat.push_back(std::move(inner));
    } else {
      flat.push_back(std::move(*rest));
    }
  }
  if (flat.empty()) return Constraint::constant(op == Constraint::Op::And);
  if (flat.size() == 1) return std::move(flat.front());
  Constraint c;
  c.op = op;
  c.args = std::move(flat);
  return c;
}

// Binding strength, to print only the parentheses the grammar needs.
int precedence(Constraint::Op op) {
  switch (op) {
    case Constraint::Op::Or:
      return 1;
    case Constraint::Op::And:
      return 2;
    case Constraint::Op::Not:
      return 3;
    default:
      return 4;
  }
}

void print(const Constraint& c, int parent_precedence, std::string& out) {
  bool parens = precedence(c.op) < parent_precedence;
  if (parens) out += '(';
  switch (c.op) {
    case Constraint::Op::True:
      out += "true";
      break;
    case Constraint::Op::False:
      out += "false";
      break;
    case Constraint::Op::Event:
      out += c.event;
      break;
    case Constraint::Op::Not:
      out += "not ";
      print(c.args[0], precedence(Constraint::Op::Not), out);
      break;
    case Constraint::Op::And:
    case Constraint::Op::Or: {
      const char* sep = c.op == Constraint::Op::And ? " and " : " or ";
      for (size_t i = 0; i < c.args.size(); ++i) {
        if (i) out += sep;
        // Children of equal precedence are flattened already; +1 keeps nested same ops explicit.
        print(c.args[i], precedence(c.op) + 1, out);
      }
      break;
    }
  }
  if (parens) out += ')';
}

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  ConstraintParse run() {
    ConstraintParse result;
    next();
    Constraint c = parse_or(0);
    if (error_.empty() && token_kind_ != Tok::End)
      fail("unexpected '" + std::string(token_) + "' after the end of the constraint");
    if (!error_.empty()) {
      result.error = error_;
      result.offset = error_offset_;
      return result;
    }
    result.ok = true;
    result.constraint = std::move(c);
    return result;
  }

 private:
  enum class Tok { End, Ident, Not, And, Or, True, False, LParen, RParen, Bad };

  Constraint parse_or(int depth) {
    std::vector<Constraint> args;
    args.push_back(parse_and(depth));
    while (error_.empty() && token_kind_ == Tok::Or) {
      next();
      args.push_back(parse_and(depth));
    }
    return nary(Constraint::Op::Or, std::move(args));
  }

  Constraint parse_and(int depth) {
    std::vector<Constraint> args;
    args.push_back(parse_unary(depth));
    while (error_.empty() && token_kind_ == Tok::And) {
      next();
      args.push_back(parse_unary(depth));
    }
    return nary(Constraint::Op::And, std::move(args));
  }

  Constraint parse_unary(int depth) {
    if (depth > kMaxConstraintDepth) {
      fail("constraint nested too deeply");
      return {};
    }
    if (!error_.empty()) return {};
    switch (token_kind_) {
      case Tok::Not:
        next();
        return Constraint::negate(parse_unary(depth + 1));
      case Tok::True:
        next();
        return Constraint::constant(true);
      case Tok::False:
        next();
        return Constraint::constant(false);
      case Tok::Ident: {
        Constraint c = Constraint::event_ref(std::string(token_));
        next();
        return c;
      }
      case Tok::LParen: {
        next();
        Constraint c = parse_or(depth + 1);
        if (error_.empty() && token_kind_ != Tok::RParen) fail("expected ')'");
        next();
        return c;
      }
      case Tok::End:
        fail("expected an event name, 'not', 'true', 'false' or '('");
        return {};
      default:
        fail("expected an event name, 'not', 'true', 'false' or '(' but found '" +
             std::string(token_) + "'");
        return {};
    }
  }

  void next() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    token_offset_ = pos_;
    if (pos_ >= text_.size()) {
      token_kind_ = Tok::End;
      token_ = {};
      return;
    }
    char ch = text_[pos_];
    if (ch == '(' || ch == ')') {
      token_kind_ = ch == '(' ? Tok::LParen : Tok::RParen;
      token_ = text_.substr(pos_++, 1);
      return;
    }
    if (std::isalpha(static_cast<unsigned char>(ch)) || ch == '_') {
      size_t start = pos_;
      while (pos_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
        ++pos_;
      token_ = text_.substr(start, pos_ - start);
      token_kind_ = token_ == "not"     ? Tok::Not
                    : token_ == "and"   ? Tok::And
                    : token_ == "or"    ? Tok::Or
                    : token_ == "true"  ? Tok::True
                    : token_ == "false" ? Tok::False
                                        : Tok::Ident;
      return;
    }
    token_kind_ = Tok::Bad;
    token_ = text_.substr(pos_++, 1);
  }

  void fail(std::string message) {
    if (!error_.empty()) return;
    error_ = std::move(message);
    error_offset_ = token_offset_;
  }

  std::string_view text_;
  size_t pos_ = 0;
  Tok token_kind_ = Tok::End;
  std::string_view token_;
  size_t token_offset_ = 0;
  std::string error_;
  size_t error_offset_ = 0;
};

}  // namespace

// The builders fold constants (the parser keeps what the user wrote): `true` vanishes from a
// conjunction and `false` absorbs it; dually for disjunctions.
// The front end builds a chain of n operands in n calls (one per `and`), so these work in place
// rather than copying the operands into new vectors at every call.
Constraint Constraint::conjunction(std::vector<Constraint> args) {
  for (const Constraint& a : args)
    if (a.op == Op::False) return constant(false);
  std::erase_if(args, [](const Constraint& a) { return a.op == Op::True; });
  Constraint c = nary(Op::And, std::move(args));
  // `a and a` says nothing more than `a` (an effective guard adds events its constraint may
  // already require); small conjunctions only, so building stays linear for large ones.
  if (c.op == Op::And && c.args.size() <= 64) {
    size_t unique = 0;  // c.args[0, unique) are the first occurrences, in order
    for (size_t i = 0; i < c.args.size(); ++i) {
      auto end = c.args.begin() + static_cast<std::ptrdiff_t>(unique);
      if (std::find(c.args.begin(), end, c.args[i]) != end) continue;
      if (i != unique) c.args[unique] = std::move(c.args[i]);
      ++unique;
    }
    c.args.resize(unique);
    if (unique == 1) return std::move(c.args.front());
  }
  return c;
}

Constraint Constraint::disjunction(std::vector<Constraint> args) {
  for (const Constraint& a : args)
    if (a.op == Op::True) return constant(true);
  std::erase_if(args, [](const Constraint& a) { return a.op == Op::False; });
  return nary(Op::Or, std::move(args));
}

std::string Constraint::to_string() const {
  std::string out;
  print(*this, 0, out);
  return out;
}

void Constraint::collect_events(std::set<std::string>& out) const {
  if (op == Op::Event) out.insert(event);
  for (const Constraint& a : args) a.collect_events(out);
}

ConstraintParse parse_constraint(std::string_view text) { return Parser(text).run(); }

std::optional<Constraint> parse_constraint(std::string_view text, std::string* err) {
  ConstraintParse parsed = Parser(text).run();
  if (parsed.ok) return std::move(parsed.constraint);
  *err = parsed.error + " at offset " + std::to_string(parsed.offset);
  return std::nullopt;
}

bool evaluate(const Constraint& c, const std::set<std::string>& present) {
  return evaluate_with(c, [&present](const std::string& e) { return present.count(e) > 0; });
}

}  // namespace arbc

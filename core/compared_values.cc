#include "core/compared_values.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace arbc::model {

namespace {

using Op = BodyExpr::Op;

bool is_comparison(const std::string& op) {
  return op == "<" || op == "<=" || op == ">" || op == ">=" || op == "==" || op == "!=";
}

// The walk over one body or predicate: which names (`let`s, lambda parameters) stand for which
// part of the message, and what was found.
class Walk {
 public:
  explicit Walk(ComparedParts* out) : out_(out) {}

  void body(const Body& b) {
    for (const BodyStmt& s : b) {
      if (s.kind == BodyStmt::Kind::Let || s.kind == BodyStmt::Kind::Var) {
        if (std::optional<std::string> p = part(s.expr)) names_[s.name] = *p;
      }
      expr(s.expr);
      body(s.then_body);
      body(s.else_body);
    }
  }

  void expr(const BodyExpr& e) {
    if (e.op == Op::Binary && is_comparison(e.text) && e.args.size() == 2) {
      compared(e.args[0], e.args[1]);
      compared(e.args[1], e.args[0]);
    }
    // min_by(xs, x => ...): x is each element of xs.
    if (e.op == Op::Call && e.args.size() == 2 && e.args[1].op == Op::Lambda) {
      if (std::optional<std::string> p = part(e.args[0])) names_[e.args[1].text] = *p + "[]";
    }
    for (const BodyExpr& a : e.args) expr(a);
  }

 private:
  // The part of the message `e` is, if it is one.
  std::optional<std::string> part(const BodyExpr& e) const {
    switch (e.op) {
      case Op::Message:
        return "";
      case Op::Local:
      case Op::Param: {
        auto it = names_.find(e.text);
        if (it == names_.end()) return std::nullopt;
        return it->second;
      }
      case Op::Field: {
        std::optional<std::string> base = e.args.empty() ? std::nullopt : part(e.args[0]);
        if (!base) return std::nullopt;
        return base->empty() ? e.text : *base + "." + e.text;
      }
      case Op::Index: {
        std::optional<std::string> base = e.args.empty() ? std::nullopt : part(e.args[0]);
        return base ? std::optional(*base + "[]") : std::nullopt;
      }
      case Op::ToFloat:
        return e.args.empty() ? std::nullopt : part(e.args[0]);
      case Op::Call: {
        bool one_part =
            !e.args.empty() && (e.builtin == Builtin::MinBy || e.builtin == Builtin::MaxBy ||
                                e.builtin == Builtin::Len);
        std::optional<std::string> base = one_part ? part(e.args[0]) : std::nullopt;
        if (!base) return std::nullopt;
        return e.builtin == Builtin::Len ? "len(" + *base + ")" : *base + "[]";
      }
      default:
        return std::nullopt;
    }
  }

  // A number constant `e` folds to, if it is one.
  static std::optional<double> number(const BodyExpr& e) {
    if (e.op == Op::Float) return e.number;
    if (e.op == Op::Int) return static_cast<double>(e.integer);
    if ((e.op == Op::Neg || e.op == Op::ToFloat) && e.args.size() == 1) {
      std::optional<double> n = number(e.args[0]);
      if (n && e.op == Op::Neg) return -*n;
      return n;
    }
    return std::nullopt;
  }

  void compared(const BodyExpr& side, const BodyExpr& other) {
    std::optional<std::string> p = part(side);
    if (!p) return;
    if (std::optional<double> n = number(other)) {
      if (!std::isnan(*n)) (*out_)[*p].numbers.push_back(*n);  // NaN equals nothing
    } else if (other.op == Op::String) {
      (*out_)[*p].strings.push_back(other.text);
    }
  }

  ComparedParts* out_;
  std::map<std::string, std::string> names_;
};

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

ComparedParts compared_parts(const App& app, const std::string& port) {
  ComparedParts out;
  for (const Connection& c : app.connections) {
    if (c.source == port && c.body) Walk(&out).body(*c.body);
  }
  for (const Event& e : app.events) {
    if (e.source == port && e.predicate) Walk(&out).expr(*e.predicate);
  }
  for (auto& [part, values] : out) {
    sort_unique(values.numbers);
    sort_unique(values.strings);
  }
  return out;
}

}  // namespace arbc::model

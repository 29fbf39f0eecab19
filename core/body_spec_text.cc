#include "core/body_spec_text.h"

#include "core/json_text.h"

namespace arbc::model {

namespace {

using Op = BodyExpr::Op;

bool is_operator(const BodyExpr& e) {
  return e.op == Op::Binary || e.op == Op::Neg || e.op == Op::Not || e.op == Op::Lambda ||
         (e.op == Op::ToFloat && !e.args.empty() && is_operator(e.args[0]));
}

std::string list_text(const std::vector<BodyExpr>& args, size_t from, const std::string& m) {
  std::string out;
  for (size_t i = from; i < args.size(); ++i)
    out += (i > from ? ", " : "") + body_expr_spec_text(args[i], m);
  return out;
}

// An operand of an operator, a field access or an index.
std::string operand(const BodyExpr& e, const std::string& m) {
  std::string text = body_expr_spec_text(e, m);
  return is_operator(e) ? "(" + text + ")" : text;
}

}  // namespace

std::string body_expr_spec_text(const BodyExpr& e, const std::string& m) {
  switch (e.op) {
    case Op::Message:
      return m;
    case Op::Int:
      return e.text == kUint64Literal ? std::to_string(static_cast<uint64_t>(e.integer))
                                      : std::to_string(e.integer);
    case Op::Float:
      return float_spec_text(e.number);
    case Op::String: {
      std::string out;
      append_json_string(out, e.text);
      return out;
    }
    case Op::Bool:
      return e.boolean ? "true" : "false";
    case Op::Local:
    case Op::Param:
      return e.text;
    case Op::Field:
      return operand(e.args[0], m) + "." + e.text;
    case Op::Index:
      return operand(e.args[0], m) + "[" + body_expr_spec_text(e.args[1], m) + "]";
    case Op::Neg:
      return "-" + operand(e.args[0], m);
    case Op::Not:
      return "not " + operand(e.args[0], m);
    case Op::Binary:
      return operand(e.args[0], m) + " " + e.text + " " + operand(e.args[1], m);
    case Op::Record: {
      std::string out = "{ ";
      for (size_t i = 0; i < e.args.size(); ++i)
        out += (i ? ", " : "") + e.names[i] + ": " + body_expr_spec_text(e.args[i], m);
      return out + " }";
    }
    case Op::List:
      return "[" + list_text(e.args, 0, m) + "]";
    case Op::Lambda:
      return e.text + " => " + body_expr_spec_text(e.args[0], m);
    case Op::Call:
      return e.text + "(" + list_text(e.args, 0, m) + ")";
    case Op::ToFloat:  // the spec wrote the int; its float type is the context's
      return body_expr_spec_text(e.args[0], m);
  }
  return "";
}

}  // namespace arbc::model

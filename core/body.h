// A rule's monitor body in the core model (docs/app-json.md#bodies): what the verifier encodes
// to reason about message data (docs/design.md#the-proof). Lowering writes it from the checked
// AST with names resolved and constants folded; app.json stores it as text (body_text.h), so
// `arbc verify app.json` proves what `arbc verify SPEC` proves without the compiler.
//
// Types are not stored: every node's type follows from the source port's type and the node's
// operands, exactly as sema typed them (an `int` literal is Int, a `float` literal Float).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace arbc::model {

struct BodyExpr {
  enum class Op {
    Message,  // the incoming message
    Int,      // number holds an integer literal (a folded int constant)
    Float,    // number holds a float literal (a folded float or duration constant)
    String,   // text
    Bool,     // boolean
    Local,    // text: a `let` or `var` of the body
    Param,    // text: the parameter of the enclosing lambda
    Field,    // args[0].text
    Index,    // args[0][args[1]], counting from 0
    Neg,      // -args[0]
    Not,      // not args[0]
    Binary,   // text is one of + - * / % < <= > >= == != and or; args[0], args[1]
    Record,   // { names[i]: args[i] }
    List,     // [ args... ]
    Lambda,   // text => args[0]
    Call,     // text(args...), text a builtin (len min_by max_by dist norm abs min max now vec3)
  };
  Op op = Op::Bool;
  std::string text;
  double number = 0;
  bool boolean = false;
  std::vector<std::string> names;  // Record
  std::vector<BodyExpr> args;
};

struct BodyStmt {
  enum class Kind {
    Let,       // let name = expr
    Var,       // var name = expr  (monitor state, initialised once)
    Assign,    // name = expr      (name is a var)
    Accept,    // accept expr
    Set,       // set name         (an event; the verifier reads effects from the connection)
    Unset,     // unset name
    If,        // if expr { then_body } else { else_body }
    Emit,      // emit expr
    Throttle,  // throttle (the period is the connection's `throttle`)
    Every,     // every { then_body }  (the period is the connection's `trig_interval`)
  };
  Kind kind = Kind::Accept;
  int line = 0;  // spec line, 0 if unknown
  std::string name;
  BodyExpr expr;
  std::vector<BodyStmt> then_body, else_body;
  // Set: the lifetime `for D` gives, in seconds; none: the event's declared lifetime, else
  // until unset. Not used by the proofs (they read effects from the connection); `arbc docs`
  // names it.
  std::optional<double> lifetime;
};

using Body = std::vector<BodyStmt>;

}  // namespace arbc::model

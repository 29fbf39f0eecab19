// A syntax tree of Lua 5.4 source, enough to follow the paths of a YARP port monitor script
// (docs/yarp.md#how-arbc-reads-a-monitor). Built by lua_parser.h; nothing here runs code.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace arbc::yarp {

struct LuaFunction;
struct LuaExpr;
using LuaExprPtr = std::unique_ptr<LuaExpr>;

struct LuaExpr {
  enum class Kind {
    Nil,
    True,
    False,
    Number,
    String,
    Vararg,    // literals
    Function,  // function ... end
    Table,     // { ... }: `items` holds keys and values
    Binary,    // items[0] text items[1]
    Unary,     // text items[0]
    Name,      // text
    Index,     // items[0][items[1]]; a.b has items[1] a String
    Call,      // items[0](items[1..])
    Method,    // items[0]:text(items[1..])
    Paren,     // (items[0])
  };
  Kind kind = Kind::Nil;
  int line = 0;
  std::string text;  // String: the decoded value; Name; Binary/Unary: the operator; Method
  double number = 0;
  std::vector<LuaExprPtr> items;
  std::shared_ptr<LuaFunction> function;  // Function
};

struct LuaStat;

struct LuaBlock {
  std::vector<LuaStat> stats;
};

struct LuaStat {
  enum class Kind {
    Local,   // local names = exprs
    Assign,  // targets = exprs
    Call,    // exprs[0] is the call
    Label,
    Goto,  // names[0]
    Break,
    Do,             // blocks[0]
    While,          // while exprs[0] do blocks[0]
    Repeat,         // repeat blocks[0] until exprs[0]
    If,             // exprs[i] then blocks[i]; blocks has one more when there is an else
    NumericFor,     // for names[0] = exprs[0], exprs[1] [, exprs[2]] do blocks[0]
    GenericFor,     // for names in exprs do blocks[0]
    Function,       // function targets[0] body (a.b.c or a.b:c; a method gets `self`)
    LocalFunction,  // local function names[0] body
    Return,         // return exprs
  };
  Kind kind = Kind::Break;
  int line = 0;
  std::vector<std::string> names;
  std::vector<LuaExprPtr> targets;
  std::vector<LuaExprPtr> exprs;
  std::vector<LuaBlock> blocks;
  std::shared_ptr<LuaFunction> function;  // Function, LocalFunction
};

struct LuaFunction {
  std::vector<std::string> params;
  bool vararg = false;
  LuaBlock body;
  int line = 0;      // of `function`
  int end_line = 0;  // of its `end`
};

}  // namespace arbc::yarp

// Where each name of a checked spec is declared and used: the table behind go to definition,
// find references, rename, hover and completion. Built from the AST after sema (every name
// there is already resolved), so it knows no more and no less than `arbc check`.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "compiler/frontend/ast.h"

namespace arbc::lsp {

using Loc = model::SourceLocation;

enum class SymbolKind { App, Type, Const, Module, Port, Event, Rule, Local };

const char* symbol_kind_name(SymbolKind k);  // "event", "rule", ...

struct Symbol {
  SymbolKind kind = SymbolKind::Event;
  std::string name;  // as written: "e_taken", "cmd", "obj"
  // Unique: "event:e_taken", "port:PickAndPlace.cmd", "local:12:5:obj"; a rule's name is
  // unique only in its port: "rule:PickAndPlace.cmd:take".
  std::string key;
  Loc def;  // the declaring name
  // Ports: the module; rules: the arbitrated port; locals: the key of the rule whose body
  // declares them, or "connect M.q -> N.p".
  std::string container;
  TypePtr type;  // ports, consts, locals: the value's type (may be null)
  // A local bound by `let`/`var`, a lambda's parameter or the incoming message.
  const ast::Stmt* stmt = nullptr;
  const ast::Rule* rule = nullptr;           // Rule symbols
  const ast::EventSymbol* event = nullptr;   // Event symbols
  const ast::ConstDecl* constant = nullptr;  // Const symbols
  const ast::ModuleDecl* module = nullptr;   // Module and Port symbols
  const ast::TypeDecl* type_decl = nullptr;  // Type symbols
};

// One place a symbol's name is written; `loc` covers exactly the name.
struct Occurrence {
  Loc loc;
  size_t symbol = 0;
  bool definition = false;
  // `events from M.p { e }`: the event's name is also the module's flag, so a rename must
  // keep the flag (`e2 = "e"`).
  bool implicit_flag = false;
};

class SymbolIndex {
 public:
  std::vector<Symbol> symbols;
  std::vector<Occurrence> occurrences;
  // Every typed expression, for hover on anything that is not a declared name.
  std::vector<const ast::Expr*> expressions;
  // Per event: the rules and connections whose bodies `set` / `unset` it.
  std::map<std::string, std::vector<std::string>> set_by, unset_by;
  // Declared type names by structural type, to print `Object` rather than its fields.
  std::map<const Type*, std::string> type_names;

  // The symbol with `key`, or null.
  const Symbol* find(const std::string& key) const;
  // The occurrence under 1-based (line, code-point column), or null.
  const Occurrence* occurrence_at(int line, int column) const;
  // The smallest typed expression under (line, column), or null.
  const ast::Expr* expression_at(int line, int column) const;
  // Every occurrence of symbol `index`, the definition first.
  std::vector<const Occurrence*> occurrences_of(size_t index) const;

  size_t add_symbol(Symbol s);  // keeps the first of equal keys; returns its index
  void add_occurrence(const std::string& key, Loc loc, bool definition = false,
                      bool implicit_flag = false);
  std::string file;  // occurrences in other files are not added; empty: all are

 private:
  std::map<std::string, size_t> by_key_;
};

// Builds the index of a spec that went through sema (errors allowed: unresolved names are
// left out). With `file`, only occurrences written in that file are kept: a tests file's
// spec is its app's with the tests added, and the app's names are written in the app's spec
// (their symbols keep their definitions there).
std::unique_ptr<SymbolIndex> build_index(const ast::Spec& spec, const std::string& file = "");

// A location covering only `name` at the start of `loc` (declarations whose loc is wider).
Loc name_loc(const Loc& loc, const std::string& name);

}  // namespace arbc::lsp

#include "lsp/symbol_index.h"

#include "lsp/positions.h"

namespace arbc::lsp {

const char* symbol_kind_name(SymbolKind k) {
  switch (k) {
    case SymbolKind::App:
      return "app";
    case SymbolKind::Type:
      return "type";
    case SymbolKind::Const:
      return "const";
    case SymbolKind::Module:
      return "module";
    case SymbolKind::Port:
      return "port";
    case SymbolKind::Event:
      return "event";
    case SymbolKind::Rule:
      return "rule";
    case SymbolKind::Local:
      return "local";
  }
  return "?";
}

Loc name_loc(const Loc& loc, const std::string& name) {
  Loc l = loc;
  int code_points = 0;
  for (unsigned char c : name) code_points += (c & 0xC0) != 0x80;
  l.end_line = l.line;
  l.end_column = l.column + code_points;
  return l;
}

const Symbol* SymbolIndex::find(const std::string& key) const {
  auto it = by_key_.find(key);
  return it == by_key_.end() ? nullptr : &symbols[it->second];
}

size_t SymbolIndex::add_symbol(Symbol s) {
  auto [it, added] = by_key_.emplace(s.key, symbols.size());
  if (added) symbols.push_back(std::move(s));
  return it->second;
}

void SymbolIndex::add_occurrence(const std::string& key, Loc loc, bool definition,
                                 bool implicit_flag) {
  auto it = by_key_.find(key);
  if (it == by_key_.end() || loc.line <= 0) return;
  if (!file.empty() && !loc.file.empty() && loc.file != file) return;
  occurrences.push_back({std::move(loc), it->second, definition, implicit_flag});
}

const Occurrence* SymbolIndex::occurrence_at(int line, int column) const {
  for (const Occurrence& o : occurrences)
    if (contains(o.loc, line, column)) return &o;
  return nullptr;
}

const ast::Expr* SymbolIndex::expression_at(int line, int column) const {
  const ast::Expr* best = nullptr;
  auto width = [](const Loc& l) {
    return (static_cast<long>(l.end_line) - l.line) * 100000 + (l.end_column - l.column);
  };
  for (const ast::Expr* e : expressions)
    if (contains(e->loc, line, column) && (!best || width(e->loc) < width(best->loc))) best = e;
  return best;
}

std::vector<const Occurrence*> SymbolIndex::occurrences_of(size_t index) const {
  std::vector<const Occurrence*> out;
  for (const Occurrence& o : occurrences)
    if (o.symbol == index && o.definition) out.push_back(&o);
  for (const Occurrence& o : occurrences)
    if (o.symbol == index && !o.definition) out.push_back(&o);
  return out;
}

}  // namespace arbc::lsp

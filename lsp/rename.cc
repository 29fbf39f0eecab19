// Rename of events, rules, constants and modules across the file and the app's tests files
// (`tests for`). The other names are refused with the reason, in prepareRename already: a
// client that gets a bare null says only "nothing to rename". Port and type names, and the
// app's, are also names outside the spec (traces, inputs files and DDS topics name ports,
// transports name types on the wire, the build directory is the app's), which a rename in the
// spec would not reach. So are modules' (a plugin registers its modules by name): a module is
// renamed in the spec all the same, since its name is written in every `Module.port`, and the
// rename's warning names what is left to change by hand.
#include <cctype>

#include "compiler/frontend/grammar_info.h"
#include "lsp/features.h"
#include "lsp/lookup.h"

namespace arbc::lsp {

namespace {

// Why `s` cannot be renamed here, or "" when it can.
std::string refusal(const Symbol& s) {
  switch (s.kind) {
    case SymbolKind::Event:
    case SymbolKind::Rule:
    case SymbolKind::Const:
    case SymbolKind::Module:
      return "";
    case SymbolKind::Port:
      return "port '" + s.container + "." + s.name +
             "' is not renamed here: its module's plugin, traces, inputs files and DDS topics "
             "use that name too; rename it in the spec and in those by hand";
    case SymbolKind::Type:
      return "type '" + s.name +
             "' is not renamed here: transports name it on the wire (app.json's types, "
             "deployment files); rename it in the spec and in those by hand";
    case SymbolKind::App:
      return "the app's name is not renamed here: it is also the name of the directory "
             "`arbc build` writes; change `app " +
             s.name + "` by hand";
    case SymbolKind::Local:
      return "'" + s.name +
             "' is a local name: only events, rules, constants and modules can be renamed; "
             "change it by hand";
  }
  return "only events, rules, constants and modules can be renamed";
}

bool is_identifier(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_'))
    return false;
  for (unsigned char c : name)
    if (!std::isalnum(c) && c != '_') return false;
  for (const std::string& k : frontend::grammar_keywords())
    if (k == name) return false;
  return true;
}

// Another declared name spelt `name`, or null. Names of different kinds can meet (an event
// and a constant both read as a name in an expression, `after X` takes a rule or an event, a
// local hides a constant), so any other symbol counts; a port's name is always written
// after its module's (`M.p`), so ports do not.
const Symbol* taken_by(const SymbolIndex& index, const Symbol& renamed, const std::string& name) {
  for (const Symbol& s : index.symbols)
    if (s.name == name && &s != &renamed && s.kind != SymbolKind::Port) return &s;
  return nullptr;
}

// Whether the index is of the text the client has: edits from an older text would land on the
// wrong characters.
bool index_is_current(const Document& doc) {
  return doc.analysis && doc.analysis->index && doc.analysis->index_text == doc.text;
}

// Why the name under the cursor cannot be renamed, or "" when it can (`l.symbol` is set).
std::string cannot_rename(const Document& doc, const Lookup& l) {
  if (!index_is_current(doc))
    return "the text does not parse now: fix the syntax error first, then rename";
  if (std::string why = refusal(*l.symbol); !why.empty()) return why;
  if (in_app_spec(doc, l.symbol->def))
    return "'" + l.symbol->name + "' is declared in " + l.symbol->def.file +
           ": rename it there (its tests files are renamed with it)";
  return "";
}

// The edits of renaming `symbol` (by key) to `name` in one document's index.
nlohmann::json edits_in(const Document& doc, const SymbolIndex& index, size_t symbol,
                        const std::string& old_name, const std::string& name) {
  nlohmann::json edits = nlohmann::json::array();
  for (const Occurrence* o : index.occurrences_of(symbol)) {
    // `events from M.p { e }`: the module still sends flag "e".
    std::string text = o->implicit_flag ? name + " = \"" + old_name + "\"" : name;
    edits.push_back({{"range", index_range(doc, o->loc)}, {"newText", text}});
  }
  return edits;
}

// What a module's rename leaves to do outside the spec.
std::string module_warning(const std::string& old_name, const std::string& name) {
  return "module '" + old_name + "' is now '" + name +
         "' in the spec; its plugin still registers it as '" + old_name +
         "' (ARBC_REGISTER_MODULE), and inputs files, traces and DDS deployment files name it "
         "too: rename it there";
}

}  // namespace

std::optional<nlohmann::json> prepare_rename(const Document& doc, Position p, std::string* err) {
  Lookup l = look_up(doc, p);
  if (!l.symbol) return nlohmann::json(nullptr);  // no name here: nothing to rename
  *err = cannot_rename(doc, l);
  if (!err->empty()) return std::nullopt;
  return nlohmann::json{{"range", index_range(doc, l.occurrence->loc)},
                        {"placeholder", l.symbol->name}};
}

std::optional<nlohmann::json> rename(const Document& doc, Position p, const std::string& name,
                                     const std::vector<Document>& tests_files, std::string* err,
                                     std::string* warning) {
  Lookup l = look_up(doc, p);
  if (!index_is_current(doc)) {
    *err = "the text does not parse now: fix the syntax error first, then rename";
    return std::nullopt;
  }
  if (!l.symbol) {
    *err =
        "there is no name to rename here: put the cursor on an event, a rule, a constant or a "
        "module";
    return std::nullopt;
  }
  *err = cannot_rename(doc, l);
  if (!err->empty()) return std::nullopt;
  if (!is_identifier(name)) {
    *err = "'" + name + "' is not a name (letters, digits and '_', not a keyword)";
    return std::nullopt;
  }
  if (const Symbol* other =
          name != l.symbol->name ? taken_by(*l.index, *l.symbol, name) : nullptr) {
    std::string kind =
        other->kind == SymbolKind::Local ? "local name" : symbol_kind_name(other->kind);
    *err = "there is already " + kind + " '" + name + "'";
    return std::nullopt;
  }
  nlohmann::json changes = nlohmann::json::object();
  changes[doc.uri] = edits_in(doc, *l.index, l.occurrence->symbol, l.symbol->name, name);
  // The app's tests files name its events, rules, constants and modules too; a tests file
  // whose text does not parse now is left alone (its edits would land on the wrong places).
  for (const Document& t : tests_files) {
    if (!index_is_current(t) || t.uri == doc.uri) continue;
    const Symbol* there = t.analysis->index->find(l.symbol->key);
    if (!there) continue;
    size_t symbol = static_cast<size_t>(there - t.analysis->index->symbols.data());
    nlohmann::json edits = edits_in(t, *t.analysis->index, symbol, l.symbol->name, name);
    if (!edits.empty()) changes[t.uri] = std::move(edits);
  }
  if (l.symbol->kind == SymbolKind::Module && name != l.symbol->name)
    *warning = module_warning(l.symbol->name, name);
  return nlohmann::json{{"changes", changes}};
}

}  // namespace arbc::lsp

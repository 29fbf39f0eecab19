#include "compiler/frontend/ast_builder.h"

#include <cctype>
#include <cstdlib>

#include "compiler/frontend/ast_builder_class.h"

namespace arbc::frontend {

using namespace ast;

void Builder::error(const Loc& where, std::string message, DiagId id) {
  Diagnostic d;
  d.loc = where;
  d.message = std::move(message);
  d.id = id.text();
  out_.push_back(std::move(d));
}

// STRING : '"' (~["\\\r\n] | '\\' ~[\r\n])* '"' ;   escapes: \" \\ \n \t \r
std::string Builder::decode_string(antlr4::tree::TerminalNode* node) {
  std::string raw = tx(node);
  std::string out;
  for (size_t i = 1; i + 1 < raw.size(); ++i) {
    if (raw[i] != '\\') {
      out += raw[i];
      continue;
    }
    char c = raw[++i];
    switch (c) {
      case '"':
        out += '"';
        break;
      case '\\':
        out += '\\';
        break;
      case 'n':
        out += '\n';
        break;
      case 't':
        out += '\t';
        break;
      case 'r':
        out += '\r';
        break;
      default: {
        Loc where = loc(node);
        where.column += static_cast<int>(i) - 1;
        where.end_column = where.column + 2;
        error(where,
              std::string("unknown escape sequence '\\") + c +
                  "' in a string: use \\\", \\\\, \\n, \\t or \\r",
              diag::BadEscape);
      }
    }
  }
  return out;
}

double Builder::seconds_of_duration(const std::string& text) {
  size_t unit = text.find_first_not_of("0123456789.");
  double value = std::strtod(text.substr(0, unit).c_str(), nullptr);
  std::string suffix = text.substr(unit);
  if (suffix == "ms") return value / 1000.0;
  if (suffix == "min") return value * 60.0;
  return value;
}

// The N of `list<T, N>`, `string<N>`, `T[N]`: a whole number from 1 to Type::kMaxSize; 0 after
// an error at its column.
int Builder::type_size(antlr4::Token* token) {
  std::string text = tx(token);
  bool whole = text.find_first_not_of("0123456789") == std::string::npos;
  int n = whole && text.size() <= 5 ? std::stoi(text) : 0;
  if (n >= 1 && n <= Type::kMaxSize) return n;
  bool too_big = whole && (text.size() > 5 || n > Type::kMaxSize);
  error(loc(token),
        "a size must be a whole number from 1 to " + std::to_string(Type::kMaxSize) + ", not " +
            text + (too_big ? " (for more elements, use list<T>, which has no bound)" : ""),
        diag::BadType);
  return 0;
}

// `list<T>`, `list<T, N>`, `string<N>` or a plain name; the `[N]` after it is type_expr's.
TypeExpr Builder::named_type(ArbcParser::NamedTypeContext* named, int depth) {
  TypeExpr t;
  t.loc = loc(named);
  std::string name = tx(named->ID());
  static const std::pair<const char*, TypeExpr::Kind> kScalars[] = {
      {"bool", TypeExpr::Kind::Bool},
      {"int", TypeExpr::Kind::Int},
      {"float", TypeExpr::Kind::Float},
      {"string", TypeExpr::Kind::String},
      {"vec3", TypeExpr::Kind::Vec3}};
  if (name == "list") {
    t.kind = TypeExpr::Kind::List;
    if (named->typeExpr()) {
      t.element = std::make_unique<TypeExpr>(type_expr(named->typeExpr(), depth + 1));
    } else {
      error(t.loc, "'list' needs an element type, e.g. list<string> or list<int, 8>",
            diag::BadType);
      t.element = std::make_unique<TypeExpr>();
      t.element->loc = t.loc;
    }
    if (named->bound) t.size = type_size(named->bound);
    return t;
  }
  t.kind = TypeExpr::Kind::Named;
  t.name = name;
  for (auto [scalar, kind] : kScalars)
    if (name == scalar) t.kind = kind;
  if (t.kind == TypeExpr::Kind::String && named->size && !named->bound) {
    t.size = type_size(named->size);
  } else if (named->typeExpr() || named->size || named->bound) {
    std::string what = named->typeExpr() ? "a type argument" : "a size";
    error(t.loc,
          "type '" + name + "' takes no " + what.substr(2) +
              "; only list<T>, list<T, N> and string<N> take one",
          diag::BadType);
  }
  return t;
}

// typeExpr : named arraySize? | record arraySize? ; a `[N]` makes it the element of a fixed list.
TypeExpr Builder::type_expr(ArbcParser::TypeExprContext* ctx, int depth) {
  TypeExpr t;
  t.loc = loc(ctx);
  if (depth > kMaxNesting) {
    error(t.loc, "type nested deeper than " + std::to_string(kMaxNesting) + " levels",
          diag::NestingTooDeep);
    t.kind = TypeExpr::Kind::Bool;
    return t;
  }
  ArbcParser::ArraySizeContext* array = nullptr;
  if (auto* named = as<ArbcParser::NamedTypeContext>(ctx)) {
    t = named_type(named, depth);
    array = named->arraySize();
  } else {
    auto* record = as<ArbcParser::RecordTypeContext>(ctx);
    t.kind = TypeExpr::Kind::Record;
    for (ArbcParser::FieldTypeContext* field : record->fieldType()) {
      t.fields.emplace_back(tx(field->ID()),
                            std::make_unique<TypeExpr>(type_expr(field->typeExpr(), depth + 1)));
      t.field_locs.push_back(loc(field->ID()));
    }
    array = record->arraySize();
  }
  if (!array) return t;
  TypeExpr fixed;
  fixed.kind = TypeExpr::Kind::List;
  fixed.loc = loc(ctx);
  fixed.size = type_size(array->NUMBER()->getSymbol());
  fixed.fixed = true;
  t.loc.end_line = loc(array).line;  // the element ends before its `[N]`
  t.loc.end_column = loc(array).column;
  fixed.element = std::make_unique<TypeExpr>(std::move(t));
  return fixed;
}

AstBuilder::AstBuilder(const std::string& file, std::string_view source,
                       std::vector<Diagnostic>& out)
    : builder_(std::make_unique<Builder>(file, source, out)), spec_(std::make_unique<Spec>()) {
  spec_->file = file;
}

AstBuilder::~AstBuilder() = default;

void AstBuilder::add_declaration(void* decl) {
  builder_->add_decl(*spec_, static_cast<ArbcParser::DeclContext*>(decl));
}

std::unique_ptr<Spec> AstBuilder::finish() { return std::move(spec_); }

}  // namespace arbc::frontend

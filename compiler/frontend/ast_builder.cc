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

// typeExpr : ID ('<' typeExpr '>')? | '{' (fieldType (',' fieldType)* ','?)? '}' ;
TypeExpr Builder::type_expr(ArbcParser::TypeExprContext* ctx, int depth) {
  TypeExpr t;
  t.loc = loc(ctx);
  if (depth > kMaxNesting) {
    error(t.loc, "type nested deeper than " + std::to_string(kMaxNesting) + " levels",
          diag::NestingTooDeep);
    t.kind = TypeExpr::Kind::Bool;
    return t;
  }
  if (auto* named = as<ArbcParser::NamedTypeContext>(ctx)) {
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
        error(t.loc, "'list' needs an element type, e.g. list<string>", diag::BadType);
        t.element = std::make_unique<TypeExpr>();
        t.element->loc = t.loc;
      }
      return t;
    }
    t.kind = TypeExpr::Kind::Named;
    t.name = name;
    for (auto [scalar, kind] : kScalars)
      if (name == scalar) t.kind = kind;
    if (named->typeExpr())
      error(loc(named->typeExpr()), "type '" + name + "' takes no type argument; only list<T> does",
            diag::BadType);
    return t;
  }
  auto* record = as<ArbcParser::RecordTypeContext>(ctx);
  t.kind = TypeExpr::Kind::Record;
  for (ArbcParser::FieldTypeContext* field : record->fieldType()) {
    t.fields.emplace_back(tx(field->ID()),
                          std::make_unique<TypeExpr>(type_expr(field->typeExpr(), depth + 1)));
    t.field_locs.push_back(loc(field->ID()));
  }
  return t;
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

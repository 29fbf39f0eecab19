#include "core/type.h"

#include <algorithm>
#include <cctype>

namespace arbc {

TypePtr Type::scalar(Kind kind) {
  auto t = std::make_shared<Type>();
  t->kind = kind;
  return t;
}

TypePtr Type::list(TypePtr element) {
  auto t = std::make_shared<Type>();
  t->kind = Kind::List;
  t->element = std::move(element);
  return t;
}

TypePtr Type::record(std::vector<Field> fields) {
  auto t = std::make_shared<Type>();
  t->kind = Kind::Record;
  t->fields = std::move(fields);
  return t;
}

bool Type::has_list() const {
  if (kind == Kind::List) return true;
  for (const Field& f : fields)
    if (f.type && f.type->has_list()) return true;
  return false;
}

const Field* Type::field(std::string_view name) const {
  for (const Field& f : fields)
    if (f.name == name) return &f;
  return nullptr;
}

std::string Type::to_string() const {
  switch (kind) {
    case Kind::Bool:
      return "bool";
    case Kind::Int:
      return "int";
    case Kind::Float:
      return "float";
    case Kind::String:
      return "string";
    case Kind::Vec3:
      return "vec3";
    case Kind::List:
      return "list<" + element->to_string() + ">";
    case Kind::Record: {
      std::string s = "{";
      for (size_t i = 0; i < fields.size(); ++i) {
        if (i) s += ", ";
        s += fields[i].name + ": " + fields[i].type->to_string();
      }
      return s + "}";
    }
  }
  return "?";
}

bool same_type(const Type& a, const Type& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == Type::Kind::List) return same_type(*a.element, *b.element);
  if (a.kind != Type::Kind::Record) return true;
  if (a.fields.size() != b.fields.size()) return false;
  for (const Field& fa : a.fields) {
    auto it = std::find_if(b.fields.begin(), b.fields.end(),
                           [&](const Field& fb) { return fb.name == fa.name; });
    if (it == b.fields.end() || !same_type(*fa.type, *it->type)) return false;
  }
  return true;
}

namespace {

// Recursive descent over: type := scalar | 'list' '<' type '>' | '{' (name ':' type),* '}'
class TypeParser {
 public:
  explicit TypeParser(std::string_view text) : text_(text) {}

  TypePtr parse_all(std::string* error) {
    TypePtr t = parse();
    skip_space();
    if (t && pos_ != text_.size()) fail("unexpected text after type");
    if (!t || !error_.empty()) {
      if (error) *error = error_.empty() ? "malformed type" : error_;
      return nullptr;
    }
    return t;
  }

 private:
  static constexpr int kMaxDepth = 64;  // nested types deeper than this are surely a mistake

  TypePtr parse() {
    if (++depth_ > kMaxDepth) return fail("type nested too deeply");
    skip_space();
    TypePtr result;
    if (eat('{')) {
      std::vector<Field> fields;
      skip_space();
      if (!eat('}')) {
        do {
          std::string name = identifier();
          if (name.empty()) return fail("expected a field name");
          skip_space();
          if (!eat(':')) return fail("expected ':' after field name");
          TypePtr ft = parse();
          if (!ft) return nullptr;
          fields.push_back({name, ft});
          skip_space();
        } while (eat(','));
        if (!eat('}')) return fail("expected '}'");
      }
      result = Type::record(std::move(fields));
    } else {
      std::string word = identifier();
      if (word == "bool")
        result = Type::scalar(Type::Kind::Bool);
      else if (word == "int")
        result = Type::scalar(Type::Kind::Int);
      else if (word == "float")
        result = Type::scalar(Type::Kind::Float);
      else if (word == "string")
        result = Type::scalar(Type::Kind::String);
      else if (word == "vec3")
        result = Type::scalar(Type::Kind::Vec3);
      else if (word == "list") {
        skip_space();
        if (!eat('<')) return fail("expected '<' after list");
        TypePtr el = parse();
        if (!el) return nullptr;
        skip_space();
        if (!eat('>')) return fail("expected '>'");
        result = Type::list(el);
      } else {
        return fail("unknown type '" + word + "'");
      }
    }
    --depth_;
    return result;
  }

  std::string identifier() {
    skip_space();
    size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    return std::string(text_.substr(start, pos_ - start));
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool eat(char c) {
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  TypePtr fail(std::string message) {
    if (error_.empty()) error_ = std::move(message);
    return nullptr;
  }

  std::string_view text_;
  size_t pos_ = 0;
  int depth_ = 0;
  std::string error_;
};

}  // namespace

TypePtr parse_type(std::string_view text, std::string* error) {
  return TypeParser(text).parse_all(error);
}

}  // namespace arbc

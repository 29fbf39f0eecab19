#include "core/type.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace arbc {

namespace {

struct NumberSpelling {
  const char* name;
  Type::Kind kind;
  int bits;
  bool is_unsigned;
};

constexpr NumberSpelling kNumbers[] = {
#define ARBC_NUMBER(name, kind, bits, is_unsigned) {name, Type::Kind::kind, bits, is_unsigned},
#include "core/number_types.def"
#undef ARBC_NUMBER
};

// The canonical text of a number type: `int` and `float` for the 64-bit ones (what every spec
// and app.json before issue 41 wrote), else the first spelling the table gives (`uint8`, not
// `byte`).
std::string number_text(const Type& t) {
  if (!t.narrow() && !t.is_unsigned) return t.kind == Type::Kind::Int ? "int" : "float";
  for (const NumberSpelling& n : kNumbers)
    if (n.kind == t.kind && n.bits == t.bits && n.is_unsigned == t.is_unsigned) return n.name;
  return "?";
}

}  // namespace

TypePtr Type::number(std::string_view name) {
  for (const NumberSpelling& n : kNumbers) {
    if (name != n.name) continue;
    auto t = std::make_shared<Type>();
    t->kind = n.kind;
    t->bits = n.bits;
    t->is_unsigned = n.is_unsigned;
    return t;
  }
  return nullptr;
}

const std::vector<std::string>& Type::number_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const NumberSpelling& n : kNumbers) v.push_back(n.name);
    return v;
  }();
  return names;
}

bool Type::narrow() const {
  return (kind == Kind::Int && (bits < 64 || is_unsigned)) || (kind == Kind::Float && bits < 64);
}

int64_t Type::min_int() const {
  if (is_unsigned) return 0;
  return bits >= 64 ? INT64_MIN : -(int64_t{1} << (bits - 1));
}

int64_t Type::max_int() const {
  if (bits >= 64) return INT64_MAX;  // uint64's greatest is not an int64: range_text says it
  return is_unsigned ? (int64_t{1} << bits) - 1 : (int64_t{1} << (bits - 1)) - 1;
}

bool Type::holds(int64_t v) const { return v >= min_int() && v <= max_int(); }

bool Type::holds(double v) const {
  if (bits >= 64 || !std::isfinite(v)) return true;
  if (std::fabs(v) > std::numeric_limits<float>::max()) return false;  // the cast would be UB
  return static_cast<double>(static_cast<float>(v)) == v;
}

std::string Type::range_text() const {
  if (is_unsigned && bits >= 64) return "0 to 18446744073709551615";
  return std::to_string(min_int()) + " to " + std::to_string(max_int());
}

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

TypePtr Type::sized_list(TypePtr element, int bound, bool fixed) {
  auto t = std::make_shared<Type>();
  t->kind = Kind::List;
  t->element = std::move(element);
  t->size = bound;
  t->fixed = fixed;
  return t;
}

TypePtr Type::bounded_string(int bound) {
  auto t = std::make_shared<Type>();
  t->kind = Kind::String;
  t->size = bound;
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
    case Kind::Float:
      return number_text(*this);
    case Kind::String:
      return size > 0 ? "string<" + std::to_string(size) + ">" : "string";
    case Kind::Vec3:
      return "vec3";
    case Kind::List:
      if (fixed) return element->to_string() + "[" + std::to_string(size) + "]";
      if (size > 0) return "list<" + element->to_string() + ", " + std::to_string(size) + ">";
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

bool is_uint64(const Type& t) { return t.kind == Type::Kind::Int && t.bits == 64 && t.is_unsigned; }

TypePtr promoted(const TypePtr& t) {
  static const TypePtr kInt = Type::number("int64"), kFloat = Type::number("float64");
  if (!t || !t->narrow() || is_uint64(*t)) return t;
  return t->kind == Type::Kind::Int ? kInt : kFloat;
}

TypePtr arithmetic_type(const Type& a, const Type& b) {
  static const TypePtr kInt = Type::number("int64"), kUint64 = Type::number("uint64"),
                       kFloat = Type::number("float64");
  if (a.kind == Type::Kind::Float || b.kind == Type::Kind::Float) return kFloat;
  return is_uint64(a) || is_uint64(b) ? kUint64 : kInt;
}

bool same_type(const Type& a, const Type& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == Type::Kind::Int || a.kind == Type::Kind::Float)
    return a.bits == b.bits && a.is_unsigned == b.is_unsigned;
  if (a.size != b.size || a.fixed != b.fixed) return false;
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

// Recursive descent over: type := base ('[' N ']')* ; base := scalar (number types by any
// spelling) | 'string' ('<' N '>')? | 'list' '<' type (',' N)? '>' | '{' (name ':' type),* '}'
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
      else if (TypePtr number = Type::number(word))
        result = number;
      else if (word == "string") {
        skip_space();
        if (!eat('<')) {
          result = Type::scalar(Type::Kind::String);
        } else {
          int n = bound();
          if (n == 0) return nullptr;
          skip_space();
          if (!eat('>')) return fail("expected '>'");
          result = Type::bounded_string(n);
        }
      } else if (word == "vec3")
        result = Type::scalar(Type::Kind::Vec3);
      else if (word == "list") {
        skip_space();
        if (!eat('<')) return fail("expected '<' after list");
        TypePtr el = parse();
        if (!el) return nullptr;
        skip_space();
        int n = 0;
        if (eat(',') && (n = bound()) == 0) return nullptr;
        skip_space();
        if (!eat('>')) return fail("expected '>'");
        result = Type::sized_list(el, n, false);
      } else {
        return fail("unknown type '" + word + "'");
      }
    }
    for (skip_space(); eat('['); skip_space()) {
      int n = bound();
      if (n == 0) return nullptr;
      skip_space();
      if (!eat(']')) return fail("expected ']'");
      result = Type::sized_list(result, n, true);
    }
    --depth_;
    return result;
  }

  // N of string<N>, list<T, N>, T[N]: 1 to Type::kMaxSize; 0 after a failure.
  int bound() {
    skip_space();
    size_t start = pos_;
    long long n = 0;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_])) &&
           n <= Type::kMaxSize)
      n = n * 10 + (text_[pos_++] - '0');
    if (pos_ == start || n < 1 || n > Type::kMaxSize) {
      fail("expected a size from 1 to " + std::to_string(Type::kMaxSize));
      return 0;
    }
    return static_cast<int>(n);
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

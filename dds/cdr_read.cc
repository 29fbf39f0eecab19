#include "dds/cdr_read.h"

#include <bit>
#include <cstring>

#include "dds/float32_bits.h"

namespace arbc::dds {

namespace {

// The body after the encapsulation: a cursor that aligns each primitive to its size.
class Body {
 public:
  Body(const uint8_t* p, size_t n, bool swap) : p_(p), n_(n), swap_(swap) {}

  template <typename T>
  bool get(T* v) {
    size_t align = sizeof(T) < 8 ? sizeof(T) : 8;
    size_t at = (pos_ + align - 1) / align * align;
    if (at + sizeof(T) > n_) return false;
    uint8_t bytes[sizeof(T)];
    std::memcpy(bytes, p_ + at, sizeof(T));
    if (swap_) {
      for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    }
    std::memcpy(v, bytes, sizeof(T));
    pos_ = at + sizeof(T);
    return true;
  }
  bool string(std::string* s) {
    uint32_t length = 0;
    if (!get(&length) || length > n_ - pos_) return false;
    // The length counts the NUL that ends the characters (0: an empty string without one).
    size_t chars = length > 0 && p_[pos_ + length - 1] == 0 ? length - 1 : length;
    s->assign(reinterpret_cast<const char*>(p_ + pos_), chars);
    pos_ += length;
    return true;
  }
  // A sequence's length, at most the bytes left (each element takes one at least): a corrupt
  // length does not allocate gigabytes.
  bool length(uint32_t* n) { return get(n) && *n <= n_ - pos_; }
  size_t used() const { return pos_; }

 private:
  const uint8_t* p_;
  size_t n_;
  size_t pos_ = 0;
  bool swap_;
};

bool read(Body& b, const Type& t, Value* out);

bool read_number(Body& b, const Type& t, Value* out) {
  auto keep = [out](bool ok, auto x) {
    if (ok) *out = Value(x);
    return ok;
  };
  // Each read comes before the keep that takes its value: C++ leaves the order of a call's
  // arguments unspecified (wire_values.cc says how GCC read x before the getter ran).
  if (t.kind == Type::Kind::Float) {
    if (t.bits == 32) {
      float f = 0;
      bool ok = b.get(&f);
      return keep(ok, widen(f));  // a signalling NaN stays one
    }
    double d = 0;
    bool ok = b.get(&d);
    return keep(ok, d);
  }
  switch (t.bits) {
    case 8: {
      uint8_t x = 0;
      bool ok = b.get(&x);
      return keep(ok, t.is_unsigned ? int64_t{x} : int64_t{static_cast<int8_t>(x)});
    }
    case 16: {
      uint16_t x = 0;
      bool ok = b.get(&x);
      return keep(ok, t.is_unsigned ? int64_t{x} : int64_t{static_cast<int16_t>(x)});
    }
    case 32: {
      uint32_t x = 0;
      bool ok = b.get(&x);
      return keep(ok, t.is_unsigned ? int64_t{x} : int64_t{static_cast<int32_t>(x)});
    }
    default: {
      uint64_t x = 0;  // a uint64 is kept as its bits (core/type.h)
      bool ok = b.get(&x);
      return keep(ok, static_cast<int64_t>(x));
    }
  }
}

bool read_list(Body& b, const Type& t, Value* out) {
  uint32_t n = static_cast<uint32_t>(t.size);
  if (!t.fixed && !b.length(&n)) return false;
  if (t.size > 0 && n > static_cast<uint32_t>(t.size)) return false;  // list<T, N>: the bound
  ValueList items(n);
  for (Value& item : items) {
    if (!read(b, *t.element, &item)) return false;
  }
  *out = Value(std::move(items));
  return true;
}

bool read(Body& b, const Type& t, Value* out) {
  switch (t.kind) {
    case Type::Kind::Bool: {
      uint8_t x = 0;
      if (!b.get(&x) || x > 1) return false;
      *out = Value(x == 1);
      return true;
    }
    case Type::Kind::Int:
    case Type::Kind::Float:
      return read_number(b, t, out);
    case Type::Kind::String: {
      std::string s;
      if (!b.string(&s) || (t.size > 0 && s.size() > static_cast<size_t>(t.size))) return false;
      *out = Value(std::move(s));
      return true;
    }
    case Type::Kind::Vec3: {
      double x = 0, y = 0, z = 0;
      if (!b.get(&x) || !b.get(&y) || !b.get(&z)) return false;
      *out = Value::vec3(x, y, z);
      return true;
    }
    case Type::Kind::List:
      return read_list(b, t, out);
    case Type::Kind::Record: {
      ValueRecord fields;
      for (const Field& f : t.fields) {
        Value v;
        if (!read(b, *f.type, &v)) return false;
        fields.emplace(f.name, std::move(v));
      }
      *out = Value(std::move(fields));
      return true;
    }
  }
  return false;
}

}  // namespace

CdrRead cdr_read(const Type& type, const uint8_t* payload, uint32_t length, Value* out) {
  CdrRead r;
  // The encapsulation: 0x0000 plain CDR big endian, 0x0001 little endian, then two bytes of
  // options (a writer's padding count).
  if (length < 4 || payload[0] != 0 || payload[1] > 1) {
    r.why = "not plain CDR (its encapsulation is not CDR_BE or CDR_LE)";
    return r;
  }
  bool little = payload[1] == 1;
  Body b(payload + 4, length - 4, little != (std::endian::native == std::endian::little));
  // A port whose type is no struct travels as a struct whose one member is its value: the same
  // bytes as the value alone.
  r.ok = read(b, type, out);
  if (!r.ok) r.why = "the bytes end early or hold no value of the type";
  r.used = static_cast<uint32_t>(b.used()) + 4;
  return r;
}

}  // namespace arbc::dds

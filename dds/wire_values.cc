#include "dds/wire_values.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "dds/float32_bits.h"

namespace arbc::dds {

namespace ft = eprosima::fastrtps::types;

namespace {

bool ok(const ft::ReturnCode_t& rc) { return rc == ft::ReturnCode_t::RETCODE_OK; }

bool put(ft::DynamicData* parent, ft::MemberId id, const Type& t, const Value& v);

// A number of type t into member `id`, at its width (wire_types.cc). The value is in t's range:
// the runtime refuses a message that is not (core/value.h conforms), and a uint64 is held as its
// bits, which the cast keeps.
bool put_number(ft::DynamicData* d, ft::MemberId id, const Type& t, const Value& v) {
  if (t.kind == Type::Kind::Float)
    return t.bits == 32 ? ok(d->set_float32_value(narrow(v.as_float()), id))
                        : ok(d->set_float64_value(v.as_float(), id));
  int64_t i = v.as_int();
  switch (t.bits) {
    case 8:
      return ok(d->set_byte_value(static_cast<ft::octet>(static_cast<uint8_t>(i)), id));
    case 16:
      return t.is_unsigned ? ok(d->set_uint16_value(static_cast<uint16_t>(i), id))
                           : ok(d->set_int16_value(static_cast<int16_t>(i), id));
    case 32:
      return t.is_unsigned ? ok(d->set_uint32_value(static_cast<uint32_t>(i), id))
                           : ok(d->set_int32_value(static_cast<int32_t>(i), id));
    default:
      return t.is_unsigned ? ok(d->set_uint64_value(static_cast<uint64_t>(i), id))
                           : ok(d->set_int64_value(i, id));
  }
}

// A number of type t appended to a sequence, at its width (as put_number).
bool insert_number(ft::DynamicData* seq, const Type& t, const Value& v) {
  ft::MemberId id = 0;
  if (t.kind == Type::Kind::Float)
    return t.bits == 32 ? ok(seq->insert_float32_value(narrow(v.as_float()), id))
                        : ok(seq->insert_float64_value(v.as_float(), id));
  int64_t i = v.as_int();
  switch (t.bits) {
    case 8:
      return ok(seq->insert_byte_value(static_cast<ft::octet>(static_cast<uint8_t>(i)), id));
    case 16:
      return t.is_unsigned ? ok(seq->insert_uint16_value(static_cast<uint16_t>(i), id))
                           : ok(seq->insert_int16_value(static_cast<int16_t>(i), id));
    case 32:
      return t.is_unsigned ? ok(seq->insert_uint32_value(static_cast<uint32_t>(i), id))
                           : ok(seq->insert_int32_value(static_cast<int32_t>(i), id));
    default:
      return t.is_unsigned ? ok(seq->insert_uint64_value(static_cast<uint64_t>(i), id))
                           : ok(seq->insert_int64_value(i, id));
  }
}

// A number of type t from member `id`: an int8 gets its sign back from the octet, a uint64 is
// kept as its bits, a float32 widens exactly. (Fast-DDS overloads each getter, so no table of
// member pointers: one call per width.)
// x is a reference: the getter that fills it is another argument of the same call, and C++
// leaves the order of arguments unspecified (GCC copied x, still 0, before the getter ran).
template <typename T>
bool keep(bool read, const T& x, Value* out) {
  if (!read) return false;
  if constexpr (std::is_floating_point_v<T>)
    *out = Value(static_cast<double>(x));
  else
    *out = Value(static_cast<int64_t>(x));
  return true;
}

bool get_number(ft::DynamicData* d, ft::MemberId id, const Type& t, Value* out) {
  if (t.kind == Type::Kind::Float) {
    if (t.bits == 32) {
      float f = 0;
      bool read = ok(d->get_float32_value(f, id));
      return keep(read, widen(f), out);
    }
    double x = 0;
    return keep(ok(d->get_float64_value(x, id)), x, out);
  }
  if (t.bits == 8) {
    ft::octet b = 0;
    bool read = ok(d->get_byte_value(b, id));
    return t.is_unsigned ? keep(read, b, out) : keep(read, static_cast<int8_t>(b), out);
  }
  if (t.bits == 16 && t.is_unsigned) {
    uint16_t x = 0;
    return keep(ok(d->get_uint16_value(x, id)), x, out);
  }
  if (t.bits == 16) {
    int16_t x = 0;
    return keep(ok(d->get_int16_value(x, id)), x, out);
  }
  if (t.bits == 32 && t.is_unsigned) {
    uint32_t x = 0;
    return keep(ok(d->get_uint32_value(x, id)), x, out);
  }
  if (t.bits == 32) {
    int32_t x = 0;
    return keep(ok(d->get_int32_value(x, id)), x, out);
  }
  if (t.is_unsigned) {
    uint64_t x = 0;
    return keep(ok(d->get_uint64_value(x, id)), x, out);
  }
  int64_t x = 0;
  return keep(ok(d->get_int64_value(x, id)), x, out);
}

// Fills a struct (a record's fields in declaration order, or vec3's x, y, z).
bool fill_struct(ft::DynamicData* s, const Type& t, const Value& v) {
  if (t.kind == Type::Kind::Vec3) {
    const Eigen::Vector3d& p = v.as_vec3();
    return ok(s->set_float64_value(p.x(), 0)) && ok(s->set_float64_value(p.y(), 1)) &&
           ok(s->set_float64_value(p.z(), 2));
  }
  for (size_t i = 0; i < t.fields.size(); ++i) {
    if (!put(s, static_cast<ft::MemberId>(i), *t.fields[i].type, v[t.fields[i].name])) return false;
  }
  return true;
}

// A fixed list (T[N]: a struct of N members, wire_types.cc): element i is member i.
bool fill_array(ft::DynamicData* array, const Type& t, const Value& v) {
  const ValueList& items = v.as_list();
  if (items.size() != static_cast<size_t>(t.size)) return false;  // conforms() said so earlier
  for (size_t i = 0; i < items.size(); ++i)
    if (!put(array, static_cast<ft::MemberId>(i), *t.element, items[i])) return false;
  return true;
}

bool fill_sequence(ft::DynamicData* seq, const Type& element, const Value& v) {
  if (!ok(seq->clear_data())) return false;
  for (const Value& item : v.as_list()) {
    ft::MemberId id = 0;
    bool done = false;
    switch (element.kind) {
      case Type::Kind::Bool:
        done = ok(seq->insert_bool_value(item.as_bool(), id));
        break;
      case Type::Kind::Int:
      case Type::Kind::Float:
        done = insert_number(seq, element, item);
        break;
      case Type::Kind::String:
        done = ok(seq->insert_string_value(item.as_string(), id));
        break;
      default:
        done = ok(seq->insert_sequence_data(id)) && put(seq, id, element, item);
    }
    if (!done) return false;
  }
  return true;
}

// Writes v into member `id` of parent (a struct's member or a sequence's element).
bool put(ft::DynamicData* parent, ft::MemberId id, const Type& t, const Value& v) {
  switch (t.kind) {
    case Type::Kind::Bool:
      return ok(parent->set_bool_value(v.as_bool(), id));
    case Type::Kind::Int:
    case Type::Kind::Float:
      return put_number(parent, id, t, v);
    case Type::Kind::String:
      return ok(parent->set_string_value(v.as_string(), id));
    default:
      break;
  }
  ft::DynamicData* child = parent->loan_value(id);
  if (!child) return false;
  bool done = t.kind != Type::Kind::List ? fill_struct(child, t, v)
              : t.fixed                  ? fill_array(child, t, v)
                                         : fill_sequence(child, *t.element, v);
  parent->return_loaned_value(child);
  return done;
}

bool get(ft::DynamicData* parent, ft::MemberId id, const Type& t, Value* out);

bool read_struct(ft::DynamicData* s, const Type& t, Value* out) {
  if (t.kind == Type::Kind::Vec3) {
    double x = 0, y = 0, z = 0;
    if (!ok(s->get_float64_value(x, 0)) || !ok(s->get_float64_value(y, 1)) ||
        !ok(s->get_float64_value(z, 2)))
      return false;
    *out = Value::vec3(x, y, z);
    return true;
  }
  ValueRecord fields;
  for (size_t i = 0; i < t.fields.size(); ++i) {
    Value field;
    if (!get(s, static_cast<ft::MemberId>(i), *t.fields[i].type, &field)) return false;
    fields.emplace(t.fields[i].name, std::move(field));
  }
  *out = Value(std::move(fields));
  return true;
}

// A list from a sequence, or from a fixed list's struct (t.fixed: its N members).
// A bounded sequence longer than its bound is no value of its type: the proof assumed the bound.
bool read_sequence(ft::DynamicData* seq, const Type& t, Value* out) {
  const Type& element = *t.element;
  ValueList items;
  uint32_t n = t.fixed ? static_cast<uint32_t>(t.size) : seq->get_item_count();
  if (t.size > 0 && n > static_cast<uint32_t>(t.size)) return false;
  items.reserve(n);
  for (uint32_t i = 0; i < n; ++i) {
    Value item;
    if (!get(seq, i, element, &item)) return false;
    items.push_back(std::move(item));
  }
  *out = Value(std::move(items));
  return true;
}

// Reads member `id` of parent as a value of type t.
bool get(ft::DynamicData* parent, ft::MemberId id, const Type& t, Value* out) {
  switch (t.kind) {
    case Type::Kind::Bool: {
      bool b = false;
      if (!ok(parent->get_bool_value(b, id))) return false;
      *out = Value(b);
      return true;
    }
    case Type::Kind::Int:
    case Type::Kind::Float:
      return get_number(parent, id, t, out);
    case Type::Kind::String: {
      std::string s;
      if (!ok(parent->get_string_value(s, id))) return false;
      if (t.size > 0 && s.size() > static_cast<size_t>(t.size)) return false;  // string<N>
      *out = Value(std::move(s));
      return true;
    }
    default:
      break;
  }
  ft::DynamicData* child = parent->loan_value(id);
  if (!child) return false;
  bool done =
      t.kind == Type::Kind::List ? read_sequence(child, t, out) : read_struct(child, t, out);
  parent->return_loaned_value(child);
  return done;
}

}  // namespace

bool to_wire(const WireType& w, const Value& v, ft::DynamicData* data, std::string* error) {
  bool done = w.wrapped ? put(data, 0, *w.type, v) : fill_struct(data, *w.type, v);
  if (!done) *error = "Fast-DDS refused a value of " + w.name + ": " + v.to_json();
  return done;
}

bool from_wire(const WireType& w, ft::DynamicData* data, Value* out, std::string* error) {
  bool done = w.wrapped ? get(data, 0, *w.type, out) : read_struct(data, *w.type, out);
  if (!done) *error = "a sample of " + w.name + " does not have its structure";
  return done;
}

}  // namespace arbc::dds

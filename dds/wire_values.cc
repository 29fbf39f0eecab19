#include "dds/wire_values.h"

namespace arbc::dds {

namespace ft = eprosima::fastrtps::types;

namespace {

bool ok(const ft::ReturnCode_t& rc) { return rc == ft::ReturnCode_t::RETCODE_OK; }

bool put(ft::DynamicData* parent, ft::MemberId id, const Type& t, const Value& v);

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
        done = ok(seq->insert_int64_value(item.as_int(), id));
        break;
      case Type::Kind::Float:
        done = ok(seq->insert_float64_value(item.as_float(), id));
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
      return ok(parent->set_int64_value(v.as_int(), id));
    case Type::Kind::Float:
      return ok(parent->set_float64_value(v.as_float(), id));
    case Type::Kind::String:
      return ok(parent->set_string_value(v.as_string(), id));
    default:
      break;
  }
  ft::DynamicData* child = parent->loan_value(id);
  if (!child) return false;
  bool done =
      t.kind == Type::Kind::List ? fill_sequence(child, *t.element, v) : fill_struct(child, t, v);
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

bool read_sequence(ft::DynamicData* seq, const Type& element, Value* out) {
  ValueList items;
  uint32_t n = seq->get_item_count();
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
    case Type::Kind::Int: {
      int64_t i = 0;
      if (!ok(parent->get_int64_value(i, id))) return false;
      *out = Value(i);
      return true;
    }
    case Type::Kind::Float: {
      double d = 0;
      if (!ok(parent->get_float64_value(d, id))) return false;
      *out = Value(d);
      return true;
    }
    case Type::Kind::String: {
      std::string s;
      if (!ok(parent->get_string_value(s, id))) return false;
      *out = Value(std::move(s));
      return true;
    }
    default:
      break;
  }
  ft::DynamicData* child = parent->loan_value(id);
  if (!child) return false;
  bool done = t.kind == Type::Kind::List ? read_sequence(child, *t.element, out)
                                         : read_struct(child, t, out);
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

#include "tests/yarp_real/bottle_layout.h"

#include <cstdint>

namespace arbc::yarp_test {

namespace {

void write_contents(::yarp::os::Bottle& b, const nlohmann::json& v, const Type& t);

// One element of `b`.
void write_item(::yarp::os::Bottle& b, const nlohmann::json& v, const Type& t) {
  switch (t.kind) {
    case Type::Kind::Float:
      b.addFloat64(v.get<double>());
      return;
    case Type::Kind::Int: {
      int64_t x = v.get<int64_t>();
      if (x >= INT32_MIN && x <= INT32_MAX) {
        b.addInt32(static_cast<int32_t>(x));
      } else {
        b.addInt64(x);
      }
      return;
    }
    case Type::Kind::Bool:
      b.addInt32(v.get<bool>() ? 1 : 0);
      return;
    case Type::Kind::String:
      b.addString(v.get<std::string>());
      return;
    default:
      write_contents(b.addList(), v, t);
  }
}

void write_contents(::yarp::os::Bottle& b, const nlohmann::json& v, const Type& t) {
  switch (t.kind) {
    case Type::Kind::Vec3:
      for (const char* axis : {"x", "y", "z"}) b.addFloat64(v.at(axis).get<double>());
      return;
    case Type::Kind::List:
      for (const nlohmann::json& e : v) write_item(b, e, *t.element);
      return;
    case Type::Kind::Record:
      for (const Field& f : t.fields) {
        ::yarp::os::Bottle& pair = b.addList();
        pair.addString(f.name);
        write_item(pair, v.at(f.name), *f.type);
      }
      return;
    default:
      write_item(b, v, t);
  }
}

}  // namespace

void write_value(::yarp::os::Bottle& b, const nlohmann::json& value, const Type& t) {
  b.clear();
  write_contents(b, value, t);
}

}  // namespace arbc::yarp_test

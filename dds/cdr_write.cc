#include "dds/cdr_write.h"

#include <bit>
#include <cstring>

#include "dds/float32_bits.h"

namespace arbc::dds {

namespace {

constexpr size_t kEncapsulation = 4;

// Appends primitives aligned to their size from the start of the body (after the
// encapsulation).
class Sink {
 public:
  explicit Sink(std::vector<uint8_t>* out) : out_(*out) {}

  template <typename T>
  void put(T x) {
    size_t align = sizeof(T) < 8 ? sizeof(T) : 8;
    size_t body = out_.size() - kEncapsulation;
    out_.resize(out_.size() + (align - body % align) % align, 0);
    size_t at = out_.size();
    out_.resize(at + sizeof(T));
    std::memcpy(out_.data() + at, &x, sizeof(T));
  }
  void bytes(const std::string& s) {
    put(static_cast<uint32_t>(s.size() + 1));
    out_.insert(out_.end(), s.begin(), s.end());
    out_.push_back(0);
  }

 private:
  std::vector<uint8_t>& out_;
};

struct Writer {
  Sink sink;
  std::string* error;

  bool fail(std::string why) {
    *error = std::move(why);
    return false;
  }

  // At its width; a uint64 is held as its bits, which the cast keeps (core/type.h).
  bool number(const Type& t, const Value& v) {
    if (t.kind == Type::Kind::Float) {
      if (!v.is_number()) return fail("a float field holds " + v.to_json());
      if (t.bits == 32)
        sink.put(narrow(v.as_float()));  // a signalling NaN stays one (float32_bits.h)
      else
        sink.put(v.as_float());
      return true;
    }
    if (!v.is_int()) return fail("an integer field holds " + v.to_json());
    int64_t i = v.as_int();
    switch (t.bits) {
      case 8:
        sink.put(static_cast<uint8_t>(i));
        break;
      case 16:
        sink.put(static_cast<uint16_t>(i));
        break;
      case 32:
        sink.put(static_cast<uint32_t>(i));
        break;
      default:
        sink.put(static_cast<uint64_t>(i));
    }
    return true;
  }

  bool list(const Type& t, const Value& v) {
    if (!v.is_list()) return fail("a list field holds " + v.to_json());
    const ValueList& items = v.as_list();
    if (t.fixed && items.size() != static_cast<size_t>(t.size))
      return fail("a " + std::to_string(t.size) + "-element array holds " +
                  std::to_string(items.size()));
    if (!t.fixed && t.size > 0 && items.size() > static_cast<size_t>(t.size))
      return fail("a list bounded to " + std::to_string(t.size) + " holds " +
                  std::to_string(items.size()));
    if (!t.fixed) sink.put(static_cast<uint32_t>(items.size()));
    for (const Value& item : items)
      if (!write(*t.element, item)) return false;
    return true;
  }

  bool record(const Type& t, const Value& v) {
    if (!v.is_record()) return fail("a record field holds " + v.to_json());
    const ValueRecord& fields = v.as_record();
    for (const Field& f : t.fields) {
      auto it = fields.find(f.name);
      if (it == fields.end()) return fail("field '" + f.name + "' is missing");
      if (!write(*f.type, it->second)) return false;
    }
    return true;
  }

  bool write(const Type& t, const Value& v) {
    switch (t.kind) {
      case Type::Kind::Bool:
        if (!v.is_bool()) return fail("a bool field holds " + v.to_json());
        sink.put(static_cast<uint8_t>(v.as_bool() ? 1 : 0));
        return true;
      case Type::Kind::Int:
      case Type::Kind::Float:
        return number(t, v);
      case Type::Kind::String: {
        if (!v.is_string()) return fail("a string field holds " + v.to_json());
        const std::string& s = v.as_string();
        if (s.find('\0') != std::string::npos)
          return fail("a string holds a NUL byte, which CDR cannot carry");
        sink.bytes(s);
        return true;
      }
      case Type::Kind::Vec3: {
        if (!v.is_vec3()) return fail("a vec3 field holds " + v.to_json());
        const Eigen::Vector3d& p = v.as_vec3();
        sink.put(p.x());
        sink.put(p.y());
        sink.put(p.z());
        return true;
      }
      case Type::Kind::List:
        return list(t, v);
      case Type::Kind::Record:
        return record(t, v);
    }
    return fail("a value of no known type");
  }
};

}  // namespace

bool cdr_write(const Type& type, const Value& v, std::vector<uint8_t>* out, std::string* error) {
  bool little = std::endian::native == std::endian::little;
  out->assign({0, static_cast<uint8_t>(little ? 1 : 0), 0, 0});
  Writer w{Sink(out), error};
  return w.write(type, v);
}

}  // namespace arbc::dds

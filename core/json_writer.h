// A streaming JSON writer with the layout of nlohmann's dump(2): two-space indents, one member
// or element per line, empty containers as `{}` and `[]`. app.json of a 10,000-rule spec is
// written through it: building an nlohmann::ordered_json tree first copied every object's
// members each time the object grew (ordered_map keys are const, so they cannot move), which
// made serialising the slowest part of `arbc build`.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace arbc {

class JsonWriter {
 public:
  void begin_object();
  void end_object();
  void begin_array();
  void end_array();
  // Inside an object, each value is preceded by its key.
  void key(std::string_view name);

  void value(std::string_view s);
  void value(const char* s) { value(std::string_view(s)); }
  void value(const std::string& s) { value(std::string_view(s)); }
  void value(bool b);
  void value(int i) { value(static_cast<int64_t>(i)); }
  void value(int64_t i);
  void value(double d);
  // A number already written as JSON text ("0.000000001": exact where a double is not).
  void number_text(std::string_view literal);
  void null();
  void value(const std::vector<std::string>& strings);

  // key(name) then value(v): one object member.
  template <class T>
  void member(std::string_view name, const T& v) {
    key(name);
    value(v);
  }

  // The text written so far; complete once every container is closed.
  const std::string& text() const { return out_; }
  std::string take() { return std::move(out_); }

 private:
  void open(char bracket);
  void close(char bracket);
  // Writes the separator and indentation that precede a value (none after a key).
  void before_value();
  void newline_and_indent();

  struct Level {
    bool empty = true;
  };
  std::string out_;
  std::vector<Level> levels_;
  bool after_key_ = false;
};

}  // namespace arbc

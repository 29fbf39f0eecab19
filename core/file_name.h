// The path of a source file as locations carry it (model::SourceLocation::file).
//
// A spec's syntax tree has a location in every node, and each used to hold its own copy of the
// path: for a 10,000-rule spec that was a tenth of the memory `arbc check` touched and of its
// time (docs/benchmarks.md). A FileName is one pointer to a path kept once per process (paths
// are interned and never freed: a process sees few distinct files), so copying a location
// copies no string, and two names are equal exactly when their pointers are.
#pragma once

#include <compare>
#include <ostream>
#include <string>
#include <string_view>

namespace arbc::model {

class FileName {
 public:
  FileName() = default;
  // Implicit, so that `loc.file = path;` reads as it did when the field was a string.
  FileName(std::string_view path);  // NOLINT(google-explicit-constructor)
  FileName(const std::string& path) : FileName(std::string_view(path)) {}  // NOLINT
  FileName(const char* path) : FileName(std::string_view(path)) {}         // NOLINT

  const std::string& str() const { return path_ ? *path_ : empty_path(); }
  operator const std::string&() const { return str(); }  // NOLINT(google-explicit-constructor)
  bool empty() const { return str().empty(); }

  friend bool operator==(const FileName& a, const FileName& b) { return a.path_ == b.path_; }
  friend bool operator==(const FileName& a, const std::string& b) { return a.str() == b; }
  friend bool operator==(const FileName& a, const char* b) { return a.str() == b; }
  friend std::strong_ordering operator<=>(const FileName& a, const FileName& b) {
    return a.str() <=> b.str();
  }
  friend std::string operator+(const FileName& a, std::string_view b) {
    return a.str() + std::string(b);
  }
  friend std::string operator+(std::string_view a, const FileName& b) {
    return std::string(a) + b.str();
  }
  friend std::ostream& operator<<(std::ostream& out, const FileName& f) { return out << f.str(); }

 private:
  static const std::string& empty_path();
  const std::string* path_ = nullptr;  // interned; null for no file
};

}  // namespace arbc::model

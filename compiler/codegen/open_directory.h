// A directory held open, so that each file operation in it names the file relative to it.
//
// Why: a build of a large app writes 10,000 monitors into one directory, and a rebuild reads
// each previous monitor, links it and later removes the old build: five system calls a file
// that each resolved the file's whole path from the root, plus two stat calls the same work
// did not need (docs/benchmarks.md). Relative to an open directory the kernel resolves one
// component.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>

namespace arbc::codegen {

class OpenDirectory {
 public:
  OpenDirectory() = default;
  // Not valid() when `path` cannot be opened as a directory.
  explicit OpenDirectory(const std::filesystem::path& path);
  ~OpenDirectory();
  OpenDirectory(OpenDirectory&& other) noexcept;
  OpenDirectory& operator=(OpenDirectory&& other) noexcept;

  bool valid() const { return fd_ >= 0; }

  // True when `name` is a regular file (or a link to one) holding exactly `content`.
  bool holds(const std::string& name, const std::string& content) const;
  // Creates or truncates `name` and writes `content`; false on any failure.
  bool write(const std::string& name, const std::string& content) const;
  // Links `from`'s `name` here under the same name (a hard link: the same file).
  bool link_from(const OpenDirectory& from, const std::string& name) const;

 private:
  int fd_ = -1;
};

// Removes `path` and everything under it, without following symbolic links, as
// std::filesystem::remove_all does but naming each entry relative to its open directory. A
// missing `path` is no error.
void remove_tree(const std::filesystem::path& path, std::error_code& ec);

}  // namespace arbc::codegen

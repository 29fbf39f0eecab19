#include "compiler/codegen/open_directory.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace arbc::codegen {

namespace {

constexpr int kDirectoryFlags = O_RDONLY | O_DIRECTORY | O_CLOEXEC;

// Removes everything inside the open directory `fd` (which it then closes).
bool empty_directory(int fd, std::error_code& ec) {
  DIR* dir = fdopendir(fd);
  if (!dir) {
    ec.assign(errno, std::generic_category());
    ::close(fd);
    return false;
  }
  bool ok = true;
  while (dirent* entry = readdir(dir)) {
    const char* name = entry->d_name;
    if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
    bool is_dir = entry->d_type == DT_DIR;
    if (entry->d_type == DT_UNKNOWN) {  // some file systems do not say
      struct stat st {};
      is_dir = fstatat(dirfd(dir), name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISDIR(st.st_mode);
    }
    if (is_dir) {
      int sub = openat(dirfd(dir), name, kDirectoryFlags | O_NOFOLLOW);
      if (sub < 0 || !empty_directory(sub, ec)) {
        if (sub < 0) ec.assign(errno, std::generic_category());
        ok = false;
        break;
      }
    }
    if (unlinkat(dirfd(dir), name, is_dir ? AT_REMOVEDIR : 0) != 0) {
      ec.assign(errno, std::generic_category());
      ok = false;
      break;
    }
  }
  closedir(dir);
  return ok;
}

}  // namespace

OpenDirectory::OpenDirectory(const std::filesystem::path& path)
    : fd_(::open(path.c_str(), kDirectoryFlags)) {}

OpenDirectory::~OpenDirectory() {
  if (fd_ >= 0) ::close(fd_);
}

OpenDirectory::OpenDirectory(OpenDirectory&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

OpenDirectory& OpenDirectory::operator=(OpenDirectory&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

bool OpenDirectory::holds(const std::string& name, const std::string& content) const {
  if (fd_ < 0) return false;
  // O_NONBLOCK: a FIFO left in the old build must not block the build (it is not a regular
  // file, so it never matches).
  int fd = openat(fd_, name.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return false;
  struct stat st {};
  bool same = fstat(fd, &st) == 0 && S_ISREG(st.st_mode) &&
              static_cast<size_t>(st.st_size) == content.size();
  if (same) {
    std::string existing(content.size(), '\0');
    size_t got = 0;
    while (got < existing.size()) {
      ssize_t n = ::read(fd, existing.data() + got, existing.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<size_t>(n);
    }
    same = got == existing.size() && existing == content;
  }
  ::close(fd);
  return same;
}

bool OpenDirectory::write(const std::string& name, const std::string& content) const {
  if (fd_ < 0) return false;
  int fd = openat(fd_, name.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) return false;
  size_t done = 0;
  while (done < content.size()) {
    ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<size_t>(n);
  }
  bool closed = ::close(fd) == 0;
  return done == content.size() && closed;
}

bool OpenDirectory::link_from(const OpenDirectory& from, const std::string& name) const {
  return fd_ >= 0 && from.fd_ >= 0 && linkat(from.fd_, name.c_str(), fd_, name.c_str(), 0) == 0;
}

void remove_tree(const std::filesystem::path& path, std::error_code& ec) {
  ec.clear();
  struct stat st {};
  if (lstat(path.c_str(), &st) != 0) {
    if (errno != ENOENT) ec.assign(errno, std::generic_category());
    return;
  }
  if (S_ISDIR(st.st_mode)) {
    int fd = ::open(path.c_str(), kDirectoryFlags | O_NOFOLLOW);
    if (fd < 0) {
      ec.assign(errno, std::generic_category());
      return;
    }
    if (!empty_directory(fd, ec)) return;
  }
  if (::remove(path.c_str()) != 0) ec.assign(errno, std::generic_category());
}

}  // namespace arbc::codegen

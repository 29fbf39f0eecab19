#include "cli/report/report_file.h"

#include <cerrno>
#include <cstring>

namespace arbc::report {

ReportFile::~ReportFile() {
  if (file_) std::fclose(file_);
}

std::string ReportFile::open(const std::string& path) {
  path_ = path;
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) return "cannot write report file " + path + ": " + std::strerror(errno);
  return {};
}

std::string ReportFile::write(const std::string& text) {
  if (!file_) return "cannot write report file " + path_ + ": it is not open";
  bool written = std::fwrite(text.data(), 1, text.size(), file_) == text.size();
  int write_errno = errno;
  bool closed = std::fclose(file_) == 0;
  int close_errno = errno;
  file_ = nullptr;
  if (!written) return "cannot write report file " + path_ + ": " + std::strerror(write_errno);
  if (!closed) return "cannot write report file " + path_ + ": " + std::strerror(close_errno);
  return {};
}

}  // namespace arbc::report

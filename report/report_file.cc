#include "report/report_file.h"

#include <cerrno>
#include <cstring>

namespace arbc::report {

ReportFile::~ReportFile() {
  if (file_) std::fclose(file_);
}

bool ReportFile::open(const std::string& path, std::string* err) {
  path_ = path;
  file_ = std::fopen(path.c_str(), "w");
  if (file_) return true;
  *err = "cannot write report file " + path + ": " + std::strerror(errno);
  return false;
}

bool ReportFile::write(const std::string& text, std::string* err) {
  if (!file_) {
    *err = "cannot write report file " + path_ + ": it is not open";
    return false;
  }
  bool written = std::fwrite(text.data(), 1, text.size(), file_) == text.size();
  int write_errno = errno;
  bool closed = std::fclose(file_) == 0;
  int close_errno = errno;
  file_ = nullptr;
  if (written && closed) return true;
  *err = "cannot write report file " + path_ + ": " +
         std::strerror(written ? close_errno : write_errno);
  return false;
}

}  // namespace arbc::report

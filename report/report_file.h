// The --report file: opened before the run, so a bad path is bad input reported at once
// (exit 2) rather than after a long run, and written when the run has ended.
#pragma once

#include <cstdio>
#include <string>

namespace arbc::report {

class ReportFile {
 public:
  ReportFile() = default;
  ReportFile(const ReportFile&) = delete;
  ReportFile& operator=(const ReportFile&) = delete;
  ~ReportFile();

  // Creates (or truncates) path; false and *err ("cannot write report file PATH: REASON") when
  // it cannot.
  bool open(const std::string& path, std::string* err);
  // Writes text and closes the file; false and *err when that fails (a full disk, say).
  bool write(const std::string& text, std::string* err);

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
};

}  // namespace arbc::report

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

  // Creates (or truncates) path. Returns "" or "cannot write report file PATH: REASON".
  std::string open(const std::string& path);
  // Writes text and closes the file. Returns "" or what failed (a full disk, say).
  std::string write(const std::string& text);

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
};

}  // namespace arbc::report

#include "compiler/codegen/write_artifacts.h"

#include <fcntl.h>

#include <cstdio>  // renameat2
#include <exception>
#include <filesystem>
#include <thread>

#include "compiler/codegen/open_directory.h"

namespace arbc::codegen {

namespace fs = std::filesystem;

namespace {

// Below this many files a second thread costs more than it saves.
constexpr size_t kFilesPerThread = 512;

// 'path', for messages. (Built by appending: GCC 12 warns falsely about "'" + string.)
std::string quoted(const fs::path& path) {
  std::string s = "'";
  s += path.string();
  s += '\'';
  return s;
}

// Puts the staging directory in the target's place in one step. renameat2 exchanges the two
// atomically, so a program loading the app sees the old build or the new one, never neither;
// where the file system cannot exchange, the old build is removed first.
bool swap_in(const fs::path& staging, const fs::path& target, bool target_exists,
             std::string* err) {
  std::error_code ec;
  if (target_exists &&
      renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
    remove_tree(staging, ec);  // now the old build
    return true;
  }
  remove_tree(target, ec);
  if (ec) {
    *err = "cannot replace " + quoted(target) + ": " + ec.message();
    return false;
  }
  fs::rename(staging, target, ec);
  if (ec) {
    *err = "cannot move the build into " + quoted(target) + ": " + ec.message();
    return false;
  }
  return true;
}

// Puts files [begin, end) into `staging`, each linked from `previous` (the previous build, or
// empty) when it holds the same bytes. The index of the first file that could not be written,
// or `end`.
size_t stage_files(const fs::path& staging, const fs::path& previous_build,
                   const std::vector<OutputFile>& files, size_t begin, size_t end) {
  fs::path made;
  OpenDirectory staged, previous;  // `made`, and its place in the previous build
  for (size_t i = begin; i < end; ++i) {
    fs::path path = staging / files[i].path;
    if (path.parent_path() != made) {
      made = path.parent_path();
      staged = OpenDirectory(made);
      previous = previous_build.empty()
                     ? OpenDirectory()
                     : OpenDirectory((previous_build / files[i].path).parent_path());
    }
    // A file the previous build already wrote with the same bytes is linked, not rewritten:
    // rebuilding 10,000 monitors then costs no new inodes or data blocks, and unchanged
    // monitors keep their modification times (an rsync to the robot ships only changes).
    std::string name = path.filename().string();
    if (previous.holds(name, files[i].content) && staged.link_from(previous, name)) continue;
    if (!staged.write(name, files[i].content)) return i;
  }
  return end;
}

// stage_files for all of `files`, a large build's in two halves on two threads: the kernel's
// work for each file (open, read and compare the previous one, link or write) is most of the
// write phase, and only the directory updates of the two halves wait for each other. The first
// failure in file order, as one thread would find it.
size_t stage_on_two_threads(const fs::path& staging, const fs::path& previous_build,
                            const std::vector<OutputFile>& files) {
  size_t n = files.size();
  if (n < 2 * kFilesPerThread || std::thread::hardware_concurrency() < 2)
    return stage_files(staging, previous_build, files, 0, n);
  size_t second_failed = n;
  std::exception_ptr failure;
  std::thread second([&] {
    try {
      second_failed = stage_files(staging, previous_build, files, n / 2, n);
    } catch (...) {
      failure = std::current_exception();
    }
  });
  size_t first_failed;
  try {
    first_failed = stage_files(staging, previous_build, files, 0, n / 2);
  } catch (...) {
    second.join();
    throw;
  }
  second.join();
  if (failure) std::rethrow_exception(failure);
  return first_failed < n / 2 ? first_failed : second_failed;
}

}  // namespace

bool write_artifacts(const std::string& out_dir, const std::string& app_name,
                     const std::vector<OutputFile>& files, std::string* err) {
  std::error_code ec;
  fs::path target = fs::path(out_dir) / app_name;
  fs::path staging = fs::path(out_dir) / ("." + app_name + ".arbc-tmp");
  bool target_exists = fs::exists(target, ec);
  if (target_exists) {
    if (!fs::is_directory(target, ec)) {
      *err = quoted(target) + " exists and is not a directory; remove it or choose -o";
      return false;
    }
    // An arbc build has app.json (embedded target) or ports.json (yarp target).
    if (!fs::is_empty(target, ec) && !fs::exists(target / "app.json", ec) &&
        !fs::exists(target / "ports.json", ec)) {
      *err = "refusing to replace " + quoted(target) +
             ": it is not empty and has no app.json or ports.json (not an arbc build); choose "
             "another -o";
      return false;
    }
  }
  remove_tree(staging, ec);
  if (!fs::create_directories(staging, ec) && ec) {
    *err = "cannot create " + quoted(staging) + ": " + ec.message();
    return false;
  }
  // Every directory first, so that the two threads below only add files.
  fs::path made;  // the last directory created: monitors come in a row
  for (const OutputFile& f : files) {
    fs::path dir = (staging / f.path).parent_path();
    if (dir != made) fs::create_directories(dir, ec);
    made = std::move(dir);
  }
  size_t failed = stage_on_two_threads(staging, target_exists ? target : fs::path(), files);
  if (failed < files.size()) {
    remove_tree(staging, ec);
    *err = "cannot write " + quoted(target / files[failed].path);
    return false;
  }
  return swap_in(staging, target, target_exists, err);
}

}  // namespace arbc::codegen

#include "compiler/codegen/write_artifacts.h"

#include <fcntl.h>

#include <cstdio>  // renameat2
#include <filesystem>

#include "compiler/codegen/open_directory.h"

namespace arbc::codegen {

namespace fs = std::filesystem;

namespace {

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
  fs::path made;                   // the last directory created: monitors come in a row
  OpenDirectory staged, previous;  // `made`, and its place in the previous build
  for (const OutputFile& f : files) {
    fs::path path = staging / f.path;
    if (path.parent_path() != made) {
      made = path.parent_path();
      fs::create_directories(made, ec);
      staged = OpenDirectory(made);
      previous = target_exists ? OpenDirectory((target / f.path).parent_path()) : OpenDirectory();
    }
    // A file the previous build already wrote with the same bytes is linked, not rewritten:
    // rebuilding 10,000 monitors then costs no new inodes or data blocks, and unchanged
    // monitors keep their modification times (an rsync to the robot ships only changes).
    std::string name = path.filename().string();
    if (previous.holds(name, f.content) && staged.link_from(previous, name)) continue;
    if (!staged.write(name, f.content)) {
      remove_tree(staging, ec);
      *err = "cannot write " + quoted(target / f.path);
      return false;
    }
  }
  return swap_in(staging, target, target_exists, err);
}

}  // namespace arbc::codegen

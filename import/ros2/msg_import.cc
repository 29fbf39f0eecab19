#include "import/ros2/msg_import.h"

#include <algorithm>
#include <filesystem>

#include "compiler/frontend/frontend.h"
#include "core/check_ids.h"

namespace arbc::ros2_import {

namespace fs = std::filesystem;

namespace {

struct Found {
  std::string root;                                       // the folder above the packages
  std::vector<std::pair<std::string, std::string>> msgs;  // (package, name), sorted
};

void add_package(const fs::path& package, Found& found) {
  std::vector<std::pair<std::string, std::string>> msgs;
  for (const fs::directory_entry& e : fs::directory_iterator(package / "msg"))
    if (e.path().extension() == ".msg")
      msgs.push_back({package.filename().string(), e.path().stem().string()});
  std::sort(msgs.begin(), msgs.end());
  found.msgs.insert(found.msgs.end(), msgs.begin(), msgs.end());
}

// The messages `input` names; an error message when it names none.
std::string find_messages(const std::string& input, Found& found) {
  std::error_code ec;
  fs::path p = fs::absolute(input, ec);
  if (fs::is_regular_file(p, ec)) {
    if (p.extension() != ".msg" || p.parent_path().filename() != "msg")
      return "is not a PKG/msg/NAME.msg file: give a .msg file in its package's msg/ folder, or "
             "a folder of packages";
    found.root = p.parent_path().parent_path().parent_path().string();
    found.msgs.push_back({p.parent_path().parent_path().filename().string(), p.stem().string()});
    return "";
  }
  if (!fs::is_directory(p, ec)) return "no such file or folder";
  p = p.lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // a trailing slash
  if (fs::is_directory(p / "msg", ec)) {
    found.root = p.parent_path().string();
    add_package(p, found);
  } else {
    found.root = p.string();
    std::vector<fs::path> packages;
    for (const fs::directory_entry& e : fs::directory_iterator(p, ec))
      if (fs::is_directory(e.path() / "msg", ec)) packages.push_back(e.path());
    std::sort(packages.begin(), packages.end());
    for (const fs::path& package : packages) add_package(package, found);
  }
  if (found.msgs.empty())
    return "holds no PKG/msg/NAME.msg file: give a .msg file, a package folder (with msg/) or a "
           "folder of packages";
  return "";
}

}  // namespace

MsgImport import_ros2_messages(const std::string& input) {
  MsgImport out;
  Found found;
  if (std::string why = find_messages(input, found); !why.empty()) {
    Diagnostic d;
    d.loc.file = input;
    d.message = input + " " + why;
    d.id = diag::Ros2Message.text();
    out.diagnostics.push_back(std::move(d));
    return out;
  }
  std::vector<std::string> messages;
  for (const auto& [package, name] : found.msgs) messages.push_back(package + "/msg/" + name);
  std::string types = frontend::ros2_types_text(messages, {found.root}, input, &out.diagnostics);
  out.ok = out.diagnostics.empty();
  out.spec = "// ROS 2 message types written by `arbc import ros2-msg` from " +
             fs::path(input).lexically_normal().filename().string() +
             ": each message's fields in its order,\n// at its widths "
             "(docs/language.md#ros-2-messages). `use ros2 PKG/msg/NAME;` declares the same\n"
             "// types without this file.\n" +
             types;
  return out;
}

}  // namespace arbc::ros2_import

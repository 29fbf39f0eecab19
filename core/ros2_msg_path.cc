#include "core/ros2_msg_path.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace arbc::ros2 {

namespace {

void add_split(std::vector<std::string>& out, const char* list, const char* suffix) {
  if (!list) return;
  std::stringstream s(list);
  std::string item;
  while (std::getline(s, item, ':'))
    if (!item.empty()) out.push_back(item + suffix);
}

}  // namespace

std::vector<std::string> message_path(const std::vector<std::string>& msg_path_options) {
  std::vector<std::string> out = msg_path_options;
  add_split(out, std::getenv("ARBC_MSG_PATH"), "");
  add_split(out, std::getenv("AMENT_PREFIX_PATH"), "/share");
  return out;
}

MsgLibrary::MsgLibrary(std::vector<std::string> path, std::map<std::string, std::string> builtin)
    : path_(std::move(path)), builtin_(std::move(builtin)) {}

const MsgDefinition* MsgLibrary::find(const std::string& full, MsgError* err) {
  *err = MsgError{};
  return load(full, err);
}

const MsgDefinition* MsgLibrary::load(const std::string& written, MsgError* err) {
  auto names = split_message_name(written);
  if (!names) return nullptr;
  const auto& [package, name] = *names;
  const std::string full = package + "/msg/" + name;
  if (auto it = loaded_.find(full); it != loaded_.end()) return it->second.get();
  std::string file, text;
  for (const std::string& dir : path_) {
    std::filesystem::path p = std::filesystem::path(dir) / package / "msg" / (name + ".msg");
    std::ifstream in(p, std::ios::binary);
    if (!in || std::filesystem::is_directory(p)) continue;
    std::stringstream s;
    s << in.rdbuf();
    file = p.string();
    text = s.str();
    break;
  }
  if (file.empty()) {
    auto b = builtin_.find(full);
    if (b == builtin_.end()) return nullptr;
    text = b->second;
  }
  std::optional<MsgDefinition> def = parse_msg(text, package, name, file, err);
  if (!def) return nullptr;
  loading_.insert(full);
  for (const MsgField& f : def->fields) {
    if (f.type.primitive) continue;
    if (loading_.count(f.type.name)) {
      *err = {file, f.line, f.column,
              full + " uses itself through " + f.type.name + " (field '" + f.name +
                  "'): a message cannot contain itself"};
      loading_.erase(full);
      return nullptr;
    }
    if (!load(f.type.name, err)) {
      if (err->message.empty())
        *err = {file, f.line, f.column,
                "field '" + f.name + "' is a " + f.type.name +
                    ", which no .msg file on the message path defines; give the folder that "
                    "holds " +
                    f.type.name.substr(0, f.type.name.find('/')) +
                    "/msg/ with --msg-path or ARBC_MSG_PATH"};
      loading_.erase(full);
      return nullptr;
    }
  }
  loading_.erase(full);
  auto [it, _] = loaded_.emplace(full, std::make_unique<MsgDefinition>(std::move(*def)));
  return it->second.get();
}

}  // namespace arbc::ros2

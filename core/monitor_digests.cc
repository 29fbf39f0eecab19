#include "core/monitor_digests.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/sha256.h"

namespace arbc::model {

bool monitor_matches_digest(const Connection& c, const std::string& path, std::string_view bytes,
                            std::string* err) {
  if (c.monitor_sha256.empty()) return true;
  std::string actual = sha256_hex(bytes);
  if (actual == c.monitor_sha256) return true;
  *err = path + ": this monitor of connection '" + c.name +
         "' is not the one `arbc build` wrote (its SHA-256 is " + actual + ", app.json records " +
         c.monitor_sha256 +
         "); monitors are generated: change the spec and rebuild the app with `arbc build`";
  return false;
}

bool read_claims_script(const App& app, const std::string& dir, std::string* text,
                        std::string* err) {
  text->clear();
  if (app.claims_script.empty()) return true;
  std::string path = (std::filesystem::path(dir) / app.claims_script).string();
  std::ifstream in(path, std::ios::binary);
  if (!in || !std::filesystem::is_regular_file(path)) {
    *err = path +
           ": app.json names this claims script, but it cannot be read (rebuild the app "
           "with `arbc build`)";
    return false;
  }
  std::ostringstream bytes;
  bytes << in.rdbuf();
  *text = bytes.str();
  std::string actual = sha256_hex(*text);
  if (app.claims_script_sha256.empty() || actual == app.claims_script_sha256) return true;
  *err = path + ": this claims script is not the one `arbc build` wrote (its SHA-256 is " + actual +
         ", app.json records " + app.claims_script_sha256 +
         "); it is generated: change the spec and rebuild the app with `arbc build`";
  return false;
}

std::vector<std::string> check_monitor_files(const App& app, const std::string& dir) {
  std::vector<std::string> errors;
  std::string claims, claims_error;
  if (!read_claims_script(app, dir, &claims, &claims_error)) errors.push_back(claims_error);
  for (const Connection& c : app.connections) {
    if (c.monitor.empty()) continue;
    std::string path = (std::filesystem::path(dir) / c.monitor).string();
    std::ifstream in(path, std::ios::binary);
    if (!in || !std::filesystem::is_regular_file(path)) {
      errors.push_back(path + ": connection '" + c.name +
                       "' names this monitor, but it cannot be read (rebuild the app with "
                       "`arbc build`)");
      continue;
    }
    std::ostringstream bytes;
    bytes << in.rdbuf();
    std::string err;
    if (!monitor_matches_digest(c, path, bytes.str(), &err)) errors.push_back(err);
  }
  return errors;
}

}  // namespace arbc::model

// How a file of the build machine is named inside an artifact that arbc writes for other tools
// and other machines (app.json, monitors, the YARP application, docs, SARIF, JUnit).
//
// A path the user gave relative to the working directory is kept as given: a built app.json
// then names its spec as `arbc check` does, and `arbc verify out/APP/app.json` run from the same
// folder finds it to quote its lines. An absolute path would carry the build machine's folders
// into files that are copied, committed and diffed, so it is made relative to the working
// directory when it lies under it, and otherwise reduced to the file's name
// (docs/app-json.md#paths-in-artifacts).
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace arbc {

// `path` as an artifact names it; `working_directory` is the absolute folder relative paths
// are read from (the process's, by the overload below).
std::string artifact_path(std::string_view path, std::string_view working_directory);
std::string artifact_path(std::string_view path);

// artifact_path for the many locations of one artifact: the working directory is read once,
// and each distinct path is mapped once.
class ArtifactPaths {
 public:
  ArtifactPaths();
  const std::string& operator()(const std::string& path);

 private:
  std::string working_directory_;  // empty when it cannot be read: absolute paths keep a name
  std::map<std::string, std::string, std::less<>> mapped_;
};

}  // namespace arbc

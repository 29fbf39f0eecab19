// The tests files of an app spec (`tests for "app.spec";`, docs/testing.md) on disk, for a
// rename in the app to reach them: a tests file names the app's events, rules, constants and
// modules, and a rename that left them would break every one of its tests.
#pragma once

#include <string>
#include <vector>

namespace arbc::lsp {

// Whether `text`, the text of the spec at `path`, starts a tests file of the app at `app_path`
// (its `tests for` path is relative to its own folder).
bool is_tests_file_of(const std::string& path, const std::string& text,
                      const std::string& app_path);

// The `.spec` files in the app's folder and up to two folders below it (hidden ones skipped:
// editors' and tests' scratch files) that are its tests files, with their texts; `app_path`
// absolute. At most a few hundred files are looked at, so a rename stays quick in a big tree.
std::vector<std::pair<std::string, std::string>> tests_files_on_disk(const std::string& app_path);

}  // namespace arbc::lsp

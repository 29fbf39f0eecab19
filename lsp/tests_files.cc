#include "lsp/tests_files.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "compiler/frontend/frontend.h"

namespace arbc::lsp {

namespace fs = std::filesystem;

namespace {

constexpr int kDepth = 2;          // folders below the app's
constexpr size_t kMaxFiles = 500;  // .spec files looked at

std::string normal(const fs::path& p) { return p.lexically_normal().string(); }

}  // namespace

bool is_tests_file_of(const std::string& path, const std::string& text,
                      const std::string& app_path) {
  // Comments and blank lines may come first; `tests for` is the first declaration.
  static const std::regex kTestsFor(
      R"re(^(?:\s|//[^\n]*\n|/\*[\s\S]*?\*/)*tests\s+for\s+"([^"]*)")re");
  std::string head = text.substr(0, 4096);  // the declaration is near the start
  std::smatch m;
  if (!std::regex_search(head, m, kTestsFor)) return false;
  fs::path app = m[1].str();
  if (app.is_relative()) app = fs::path(path).parent_path() / app;
  return normal(app) == normal(app_path);
}

std::vector<std::pair<std::string, std::string>> tests_files_on_disk(const std::string& app_path) {
  std::vector<std::pair<std::string, std::string>> out;
  std::error_code ec;
  fs::path root = fs::path(app_path).parent_path();
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
  size_t looked_at = 0;
  for (; !ec && it != end && looked_at < kMaxFiles; it.increment(ec)) {
    const fs::path& p = it->path();
    bool hidden = p.filename().string().starts_with(".");
    if (it->is_directory(ec)) {
      if (hidden || it.depth() >= kDepth) it.disable_recursion_pending();
      continue;
    }
    if (hidden || p.extension() != ".spec" || normal(p) == normal(app_path)) continue;
    if (!it->is_regular_file(ec) || it->file_size(ec) > frontend::kMaxSpecBytes) continue;
    ++looked_at;
    std::ifstream in(p, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (is_tests_file_of(p.string(), text.str(), app_path))
      out.emplace_back(p.string(), text.str());
  }
  return out;
}

}  // namespace arbc::lsp

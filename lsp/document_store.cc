#include "lsp/document_store.h"

#include <filesystem>

#include "lsp/text_edits.h"
#include "lsp/uri.h"

namespace arbc::lsp {

void DocumentStore::open(const std::string& uri, std::string text, int version) {
  Document d;
  d.uri = uri;
  d.path = uri_to_path(uri);
  std::filesystem::path parent = std::filesystem::path(d.path).parent_path();
  d.script_dir = parent.empty() ? "." : parent.string();
  d.version = version;
  d.text = std::move(text);
  std::lock_guard lock(mutex_);
  docs_[uri] = std::move(d);
}

bool DocumentStore::change(const std::string& uri, const nlohmann::json& changes, int version,
                           std::string* err) {
  std::lock_guard lock(mutex_);
  auto it = docs_.find(uri);
  if (it == docs_.end()) {
    *err = "a change to a document that is not open: " + uri;
    return false;
  }
  if (!changes.is_array()) {
    *err = "didChange without contentChanges";
    return false;
  }
  it->second.version = version;
  for (const nlohmann::json& c : changes)
    if (!apply_change(it->second.text, c, err)) return false;
  return true;
}

void DocumentStore::close(const std::string& uri) {
  std::lock_guard lock(mutex_);
  docs_.erase(uri);
}

std::optional<Document> DocumentStore::get(const std::string& uri) const {
  std::lock_guard lock(mutex_);
  auto it = docs_.find(uri);
  if (it == docs_.end()) return std::nullopt;
  return it->second;
}

std::vector<Document> DocumentStore::all() const {
  std::lock_guard lock(mutex_);
  std::vector<Document> out;
  for (const auto& [uri, d] : docs_) out.push_back(d);
  return out;
}

void DocumentStore::set_analysis(const std::string& uri, std::shared_ptr<const Analysis> a) {
  {
    std::lock_guard lock(mutex_);
    auto it = docs_.find(uri);
    if (it == docs_.end()) return;
    if (it->second.analysis && it->second.analysis->version > a->version) return;
    it->second.analysis = std::move(a);
  }
  analysed_.notify_all();
}

void DocumentStore::set_verification(const std::string& uri, Verification v) {
  std::lock_guard lock(mutex_);
  auto it = docs_.find(uri);
  if (it != docs_.end()) it->second.verification = std::move(v);
}

std::optional<Document> DocumentStore::wait_current(
    const std::string& uri, std::chrono::steady_clock::time_point deadline) const {
  std::unique_lock lock(mutex_);
  analysed_.wait_until(lock, deadline, [&] {
    auto it = docs_.find(uri);
    return it == docs_.end() ||
           (it->second.analysis && it->second.analysis->version >= it->second.version);
  });
  auto it = docs_.find(uri);
  if (it == docs_.end()) return std::nullopt;
  return it->second;
}

}  // namespace arbc::lsp

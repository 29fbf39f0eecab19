// The open documents: their text (kept in sync incrementally), the latest analysis and the
// latest verification. Shared by the request thread and the workers, so every access locks.
#pragma once

#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.h"
#include "lsp/analysis.h"

namespace arbc::lsp {

// What `arbc verify` found for one version of a document.
struct Verification {
  int version = -1;
  std::vector<Diagnostic> diagnostics;
  std::string summary;  // "proved: 4 ports, 6 rules", "refuted: ...", or why it did not run
};

struct Document {
  std::string uri;
  std::string path;        // file name in diagnostics (the URI's path)
  std::string script_dir;  // where `script` files are looked for: the file's folder
  int version = 0;
  std::string text;
  std::shared_ptr<const Analysis> analysis;  // null until the first analysis
  Verification verification;
};

class DocumentStore {
 public:
  void open(const std::string& uri, std::string text, int version);
  // Applies contentChanges; false (and `err`) if the document is not open or a change is
  // malformed (the changes before it stay applied: the client will resend the text).
  bool change(const std::string& uri, const nlohmann::json& changes, int version, std::string* err);
  void close(const std::string& uri);

  std::optional<Document> get(const std::string& uri) const;  // a copy
  std::vector<Document> all() const;                          // copies, by URI
  // Stores an analysis unless a newer one is there already; wakes wait_current().
  void set_analysis(const std::string& uri, std::shared_ptr<const Analysis> a);
  void set_verification(const std::string& uri, Verification v);
  // The document once its analysis is of its current version, or at `deadline` whatever it
  // has (requests answer from the freshest analysis without waiting on a slow one).
  std::optional<Document> wait_current(const std::string& uri,
                                       std::chrono::steady_clock::time_point deadline) const;

 private:
  mutable std::mutex mutex_;
  mutable std::condition_variable analysed_;
  std::map<std::string, Document> docs_;
};

}  // namespace arbc::lsp

// What the server's workers do: check a document and publish its diagnostics; prove it and
// publish the proof's findings beside them.
#include <chrono>

#include "compiler/frontend/frontend.h"
#include "core/check_ids.h"
#include "lsp/lsp_diagnostics.h"
#include "lsp/server.h"
#include "lsp/verification.h"

namespace arbc::lsp {

namespace {

// A text over the front end's limit gets the diagnostic `arbc check` gives such a file.
std::shared_ptr<const Analysis> too_large(const Document& d) {
  auto a = std::make_shared<Analysis>();
  a->version = d.version;
  a->text = d.text;
  Diagnostic diag;
  diag.loc.file = d.path;
  diag.id = diag::Io.text();
  diag.message = "the file is larger than " + std::to_string(frontend::kMaxSpecBytes >> 20) +
                 " MiB; a spec this large is surely not hand-written text";
  a->diagnostics.push_back(std::move(diag));
  return a;
}

}  // namespace

void Server::check_document(const std::string& uri) {
  std::optional<Document> d = store_.get(uri);
  if (!d) return;
  std::shared_ptr<const Analysis> a;
  if (d->text.size() > frontend::kMaxSpecBytes) {
    a = too_large(*d);
  } else {
    a = gate_.run(d->path, [&] {
      return analyze(d->text, d->version, d->path, d->script_dir, d->analysis.get());
    });
  }
  store_.set_analysis(uri, a);
  publish(uri);
}

void Server::verify_document(const std::string& uri) {
  std::optional<Document> d = store_.get(uri);
  if (!d || d->text.size() > frontend::kMaxSpecBytes) return;
  Verification v = verify_text(d->text, d->version, d->path, d->script_dir, gate_,
                               options_.verify_timeout_seconds, options_.make_replayers);
  log_info(uri + " (version " + std::to_string(v.version) + "): " + v.summary);
  store_.set_verification(uri, std::move(v));
  publish(uri);
}

void Server::publish(const std::string& uri) {
  std::lock_guard lock(publish_mutex_);  // so that an older set never overwrites a newer one
  std::optional<Document> d = store_.get(uri);
  if (!d || !d->analysis) return;
  const Analysis& a = *d->analysis;
  nlohmann::json list = nlohmann::json::array();
  for (const Diagnostic& diag : a.diagnostics) list.push_back(diagnostic_json(diag, a.text, uri));
  // The proof's findings hold for the text that was proved: shown until the text changes.
  if (d->verification.version == a.version && a.text == d->text)
    for (const Diagnostic& diag : d->verification.diagnostics)
      list.push_back(diagnostic_json(diag, a.text, uri));
  send({{"jsonrpc", "2.0"},
        {"method", "textDocument/publishDiagnostics"},
        {"params", {{"uri", uri}, {"version", a.version}, {"diagnostics", list}}}});
}

}  // namespace arbc::lsp

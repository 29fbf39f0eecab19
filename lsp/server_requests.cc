// Server::request and Server::notification: the methods the server handles, each handed to
// its feature (features.h) with a snapshot of the document.
#include <filesystem>
#include <set>

#include "lsp/features.h"
#include "lsp/server.h"
#include "lsp/tests_files.h"
#include "lsp/uri.h"

namespace arbc::lsp {

nlohmann::json Server::initialize_result() const {
  nlohmann::json caps = {
      {"textDocumentSync",
       {{"openClose", true}, {"change", 2 /* incremental */}, {"save", {{"includeText", false}}}}},
      {"hoverProvider", true},
      {"definitionProvider", true},
      {"referencesProvider", true},
      {"documentHighlightProvider", true},
      {"documentSymbolProvider", true},
      {"completionProvider", {{"triggerCharacters", {"."}}}},
      {"codeActionProvider", {{"codeActionKinds", {"quickfix"}}}},
      {"renameProvider", {{"prepareProvider", true}}},
  };
  return {{"capabilities", caps},
          {"serverInfo", {{"name", "arbc"}, {"version", options_.version}}}};
}

void Server::watch_client(const nlohmann::json& initialize_params) {
  auto pid = initialize_params.find("processId");
  if (!options_.on_client_gone || pid == initialize_params.end() || !pid->is_number_integer())
    return;
  int id = pid->get<int>();
  client_watch_ = std::make_unique<ClientWatch>(id, options_.client_poll, [this, id] {
    log("the client's process " + std::to_string(id) + " is gone; exiting");
    options_.on_client_gone();
  });
}

std::optional<Document> Server::document(const nlohmann::json& params) {
  std::string uri = params.at("textDocument").at("uri").get<std::string>();
  return store_.wait_current(uri, std::chrono::steady_clock::now() + options_.request_wait);
}

std::vector<Document> Server::tests_files_of(const Document& app) {
  std::vector<Document> out;
  std::set<std::string> open;
  std::string app_path = std::filesystem::path(app.path).lexically_normal().string();
  auto names_app = [&](const Document& d) {
    return d.analysis && d.analysis->app_file == app_path;
  };
  for (Document& d : store_.all()) {
    open.insert(std::filesystem::path(d.path).lexically_normal().string());
    if (names_app(d)) out.push_back(std::move(d));
  }
  for (auto& file : tests_files_on_disk(app_path)) {
    // Named, not bound: clang 14 cannot capture a structured binding in a lambda.
    const std::string& path = file.first;
    std::string& text = file.second;
    if (open.count(path)) continue;  // the editor's text, not the disk's
    Document d;
    d.uri = path_to_uri(path);
    d.path = path;
    d.script_dir = std::filesystem::path(path).parent_path().string();
    d.text = std::move(text);
    d.analysis = gate_.run(path, [&] { return analyze(d.text, 0, path, d.script_dir, nullptr); });
    if (names_app(d)) out.push_back(std::move(d));
  }
  return out;
}

std::optional<nlohmann::json> Server::rename_request(const Document& doc,
                                                     const nlohmann::json& params,
                                                     RequestError* err) {
  Position p = parse_position(params.value("position", nlohmann::json::object()));
  std::string why, warning;
  // Only an app spec has tests files; a tests file's own names are declared in its app.
  std::vector<Document> tests_files;
  if (doc.analysis && doc.analysis->app_file.empty()) tests_files = tests_files_of(doc);
  auto edit = rename(doc, p, params.at("newName").get<std::string>(), tests_files, &why, &warning);
  if (!edit) *err = {kRequestFailed, why};
  if (edit && !warning.empty())
    send({{"jsonrpc", "2.0"},
          {"method", "window/showMessage"},
          {"params", {{"type", 2 /* Warning */}, {"message", warning}}}});
  return edit;
}

std::optional<nlohmann::json> Server::request(const std::string& method,
                                              const nlohmann::json& params, RequestError* err) {
  if (method == "initialize") {
    initialized_ = true;
    watch_client(params);
    return initialize_result();
  }
  if (!initialized_) {
    *err = {kServerNotInitialized, "the server is not initialized"};
    return std::nullopt;
  }
  if (shutdown_) {
    *err = {kInvalidRequest, "the server is shutting down"};
    return std::nullopt;
  }
  if (method == "shutdown") {
    shutdown_ = true;
    return nlohmann::json(nullptr);
  }
  if (method == "arbc/status")  // ours: what the tests and benchmarks look at
    return nlohmann::json{{"parserCacheResets", gate_.resets()}};
  static const std::set<std::string> kDocumentMethods = {
      "textDocument/hover",          "textDocument/definition",
      "textDocument/references",     "textDocument/documentHighlight",
      "textDocument/documentSymbol", "textDocument/completion",
      "textDocument/codeAction",     "textDocument/prepareRename",
      "textDocument/rename"};
  if (!kDocumentMethods.count(method)) {
    *err = {kMethodNotFound, "unknown method " + method};
    return std::nullopt;
  }
  std::optional<Document> doc = document(params);
  if (!doc) {
    *err = {kInvalidParams, "the document is not open"};
    return std::nullopt;
  }
  Position p = parse_position(params.value("position", nlohmann::json::object()));
  if (method == "textDocument/hover") return hover(*doc, p);
  if (method == "textDocument/definition") return definition(*doc, p);
  if (method == "textDocument/references")
    return references(
        *doc, p,
        params.value("context", nlohmann::json::object()).value("includeDeclaration", true));
  if (method == "textDocument/documentHighlight") return highlights(*doc, p);
  if (method == "textDocument/documentSymbol") return document_symbols(*doc);
  if (method == "textDocument/completion") return completion(*doc, p);
  if (method == "textDocument/codeAction") return code_actions(*doc, params.at("range"));
  if (method == "textDocument/prepareRename") {
    std::string why;
    auto range = prepare_rename(*doc, p, &why);
    if (!range) *err = {kRequestFailed, why};
    return range;
  }
  if (method == "textDocument/rename") return rename_request(*doc, params, err);
  *err = {kMethodNotFound, "unknown method " + method};
  return std::nullopt;
}

void Server::notification(const std::string& method, const nlohmann::json& params) {
  if (method == "textDocument/didOpen") {
    const nlohmann::json& td = params.at("textDocument");
    std::string uri = td.at("uri");
    store_.open(uri, td.at("text").get<std::string>(), td.value("version", 0));
    check_worker_.schedule(uri);
    if (options_.verify) verify_worker_.schedule(uri);
  } else if (method == "textDocument/didChange") {
    std::string uri = params.at("textDocument").at("uri");
    std::string err;
    if (!store_.change(uri, params.at("contentChanges"),
                       params.at("textDocument").value("version", 0), &err))
      log(err);
    check_worker_.schedule(uri);
  } else if (method == "textDocument/didSave") {
    if (options_.verify) verify_worker_.schedule(params.at("textDocument").at("uri"));
  } else if (method == "textDocument/didClose") {
    std::string uri = params.at("textDocument").at("uri");
    store_.close(uri);
    check_worker_.cancel(uri);
    verify_worker_.cancel(uri);
    send({{"jsonrpc", "2.0"},
          {"method", "textDocument/publishDiagnostics"},
          {"params", {{"uri", uri}, {"diagnostics", nlohmann::json::array()}}}});
  }
  // Anything else (initialized, $/cancelRequest, $/setTrace, configuration) needs nothing.
}

}  // namespace arbc::lsp

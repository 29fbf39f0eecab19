// `arbc lsp`: a Language Server Protocol server on a pair of streams (docs/editors.md).
//
// Threads: the caller's thread reads messages and answers requests from the latest analysis;
// a check worker analyses a document once typing pauses (check_delay) and publishes its
// diagnostics; a verify worker proves a document after it is opened or saved. Parses are
// serialised by one ParserGate. Nothing a client sends can end the server but `exit` or the
// end of its input: malformed messages get JSON-RPC errors, bad documents diagnostics.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <istream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "lsp/client_watch.h"
#include "lsp/debounced_worker.h"
#include "lsp/document_store.h"
#include "lsp/framing.h"
#include "lsp/parser_gate.h"
#include "lsp/verification.h"

namespace arbc::lsp {

struct ServerOptions {
  std::string version = "0";                     // serverInfo.version
  std::chrono::milliseconds check_delay{30};     // quiet time before checking
  std::chrono::milliseconds verify_delay{200};   // quiet time before proving
  std::chrono::milliseconds request_wait{1000};  // how long a request waits for an analysis
  double verify_timeout_seconds = 30;            // the solver's budget per proof
  MakeReplayers make_replayers;                  // replays counterexamples; empty: none
  bool verify = true;                            // prove on open and save
  // Called (on a watch thread) once the process named by initialize's processId is gone;
  // `arbc lsp` exits there. Null: the client's process is not watched.
  std::function<void()> on_client_gone;
  std::chrono::milliseconds client_poll{1000};  // how often the client's process is looked at
};

class Server {
 public:
  Server(std::istream& in, std::ostream& out, std::ostream& log, ServerOptions options);
  ~Server();
  // Serves until `exit` or the end of the input. The exit code: 0 after shutdown, else 1.
  int run();

 private:
  void dispatch(const nlohmann::json& message);
  // nullopt and `err` when the request fails (an unknown method, a document not open, ...).
  std::optional<nlohmann::json> request(const std::string& method, const nlohmann::json& params,
                                        struct RequestError* err);
  void notification(const std::string& method, const nlohmann::json& params);
  nlohmann::json initialize_result() const;
  void watch_client(const nlohmann::json& initialize_params);
  std::optional<Document> document(const nlohmann::json& params);
  // The tests files of the app spec `app`, analysed: the open ones and the others on disk.
  std::vector<Document> tests_files_of(const Document& app);
  std::optional<nlohmann::json> rename_request(const Document& doc, const nlohmann::json& params,
                                               RequestError* err);
  void check_document(const std::string& uri);   // on the check worker
  void verify_document(const std::string& uri);  // on the verify worker
  void publish(const std::string& uri);
  void send(const nlohmann::json& message);
  void log(const std::string& line);       // something went wrong: stderr
  void log_info(const std::string& line);  // what the server did: the client's log

  std::istream& in_;
  MessageWriter writer_;
  std::ostream& log_;
  std::mutex log_mutex_, publish_mutex_;
  ServerOptions options_;
  DocumentStore store_;
  ParserGate gate_;
  bool initialized_ = false;
  bool shutdown_ = false;
  DebouncedWorker check_worker_;
  DebouncedWorker verify_worker_;
  std::unique_ptr<ClientWatch> client_watch_;
};

// JSON-RPC error codes (LSP).
inline constexpr int kParseError = -32700;
inline constexpr int kInvalidRequest = -32600;
inline constexpr int kMethodNotFound = -32601;
inline constexpr int kInvalidParams = -32602;
inline constexpr int kInternalError = -32603;
inline constexpr int kServerNotInitialized = -32002;
inline constexpr int kRequestFailed = -32803;

// Why a request failed: the JSON-RPC error it is answered with.
struct RequestError {
  int code;
  std::string message;
};

}  // namespace arbc::lsp

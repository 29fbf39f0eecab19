#include "lsp/server.h"

namespace arbc::lsp {

Server::Server(std::istream& in, std::ostream& out, std::ostream& log, ServerOptions options)
    : in_(in),
      writer_(out),
      log_(log),
      options_(std::move(options)),
      check_worker_(options_.check_delay, [this](const std::string& uri) { check_document(uri); }),
      verify_worker_(options_.verify_delay,
                     [this](const std::string& uri) { verify_document(uri); }) {
  // A stream tied to `out` flushes it before its own input or output: std::cin and std::cerr
  // are tied to std::cout. That flush would run outside the writer's lock (reading the next
  // message on this thread, logging on any) while a worker writes a message: a data race
  // seen as a header whose body was lost under random edits (tests/lsp/random_edits.py).
  in_.tie(nullptr);
  log_.tie(nullptr);
}

Server::~Server() {
  client_watch_.reset();
  check_worker_.stop();
  verify_worker_.stop();
}

int Server::run() {
  for (;;) {
    if (writer_.broken()) {  // the client closed its end of our output: it is gone
      log("the client stopped reading the server's output; exiting");
      return 1;
    }
    std::string err;
    std::optional<std::string> body = read_message(in_, &err);
    if (!err.empty()) log(err);
    if (!body) return shutdown_ ? 0 : 1;
    if (body->empty()) continue;
    nlohmann::json message = nlohmann::json::parse(*body, nullptr, /*allow_exceptions=*/false);
    if (message.is_discarded() || !message.is_object()) {
      send({{"jsonrpc", "2.0"},
            {"id", nullptr},
            {"error", {{"code", kParseError}, {"message", "the message is not a JSON object"}}}});
      continue;
    }
    auto method = message.find("method");  // any JSON value: dispatch() answers a bad one
    if (method != message.end() && *method == "exit") return shutdown_ ? 0 : 1;
    dispatch(message);
  }
}

void Server::dispatch(const nlohmann::json& message) {
  auto method_it = message.find("method");
  auto id = message.find("id");
  if (method_it == message.end() || !method_it->is_string()) {
    if (id == message.end()) return;  // a response to us (we send no requests): ignore
    send({{"jsonrpc", "2.0"},
          {"id", *id},
          {"error", {{"code", kInvalidRequest}, {"message", "a request needs a method"}}}});
    return;
  }
  const std::string method = *method_it;
  nlohmann::json params = message.value("params", nlohmann::json::object());
  if (id == message.end()) {
    try {
      notification(method, params);
    } catch (const nlohmann::json::exception& e) {  // malformed params: drop it, say why
      log("ignored " + method + ": " + e.what());
    }
    return;
  }
  RequestError err{kInternalError, ""};
  std::optional<nlohmann::json> result;
  try {
    result = request(method, params, &err);
  } catch (const nlohmann::json::exception& e) {
    err = {kInvalidParams, std::string("malformed parameters: ") + e.what()};
  }
  if (result)
    send({{"jsonrpc", "2.0"}, {"id", *id}, {"result", *result}});
  else
    send({{"jsonrpc", "2.0"},
          {"id", *id},
          {"error", {{"code", err.code}, {"message", err.message}}}});
}

void Server::send(const nlohmann::json& message) {
  writer_.write(message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

// Routine news goes to the client as window/logMessage (type 4, "Log"), not to stderr:
// Neovim records every line a server writes on stderr as an [ERROR] in its lsp.log, so a
// proof that went well would look like a failure there. stderr keeps what went wrong.
void Server::log_info(const std::string& line) {
  send({{"jsonrpc", "2.0"},
        {"method", "window/logMessage"},
        {"params", {{"type", 4}, {"message", "arbc lsp: " + line}}}});
}

void Server::log(const std::string& line) {
  std::lock_guard lock(log_mutex_);
  log_ << "arbc lsp: " << line << "\n";
  log_.flush();
}

}  // namespace arbc::lsp

#include "lsp/framing.h"

#include <cctype>
#include <charconv>

namespace arbc::lsp {

namespace {

// Reads header lines up to the empty line. False at the end of the stream.
bool read_headers(std::istream& in, std::optional<size_t>* length, bool* any_line) {
  std::string line;
  while (std::getline(in, line)) {
    *any_line = true;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) return true;
    size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string name = line.substr(0, colon);
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (name != "content-length") continue;
    size_t start = line.find_first_not_of(' ', colon + 1);
    if (start == std::string::npos) continue;
    size_t value = 0;
    auto [end, ec] = std::from_chars(line.data() + start, line.data() + line.size(), value);
    if (ec == std::errc() && end == line.data() + line.size()) *length = value;
  }
  return false;
}

}  // namespace

std::optional<std::string> read_message(std::istream& in, std::string* err) {
  std::optional<size_t> length;
  bool any_line = false;
  if (!read_headers(in, &length, &any_line)) {
    if (any_line) *err = "the input ended inside a message header";
    return std::nullopt;
  }
  if (!length) {
    *err = "a message header has no valid Content-Length; the header was skipped";
    return std::string();
  }
  if (*length > kMaxMessageBytes) {
    in.ignore(static_cast<std::streamsize>(*length));
    *err = "a message of " + std::to_string(*length) + " bytes is larger than " +
           std::to_string(kMaxMessageBytes >> 20) + " MiB; it was skipped";
    return std::string();
  }
  std::string body(*length, '\0');
  in.read(body.data(), static_cast<std::streamsize>(*length));
  if (static_cast<size_t>(in.gcount()) != *length) {
    *err = "the input ended inside a message body";
    return std::nullopt;
  }
  return body;
}

void MessageWriter::write(const std::string& body) {
  std::lock_guard lock(mutex_);
  if (broken_) return;
  out_ << "Content-Length: " << body.size() << "\r\n\r\n" << body;
  out_.flush();
  if (!out_) broken_ = true;
}

}  // namespace arbc::lsp

// file:// URIs (RFC 8089, as LSP clients send them) to paths and back.
#pragma once

#include <string>

namespace arbc::lsp {

// The path of a `file://` URI, percent-decoded; any other URI (e.g. `untitled:1`) is returned
// as it is, so that it still names the document in diagnostics.
std::string uri_to_path(const std::string& uri);

// `file://` + the absolute path, percent-encoded where a URI needs it.
std::string path_to_uri(const std::string& path);

}  // namespace arbc::lsp

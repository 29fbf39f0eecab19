#include "import/yarp/app_xml.h"

#include <tinyxml2.h>

#include <fstream>
#include <sstream>

#include "core/check_ids.h"
#include "import/yarp/xml_mismatch.h"

namespace arbc::yarp {
namespace {

constexpr const char* kXmlId = diag::YarpXml.text();
constexpr size_t kMaxXmlBytes = 64u << 20;

Diagnostic error_at(model::SourceLocation loc, std::string message, Severity s = Severity::Error) {
  Diagnostic d;
  d.severity = s;
  d.loc = std::move(loc);
  d.message = std::move(message);
  d.id = kXmlId;
  return d;
}

std::string trimmed_text(const tinyxml2::XMLElement* e) {
  const char* t = e ? e->GetText() : nullptr;
  std::string s = t ? t : "";
  size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

const tinyxml2::XMLElement* child(const tinyxml2::XMLElement* e, const char* a,
                                  const char* b = nullptr) {
  const tinyxml2::XMLElement* c = e->FirstChildElement(a);
  return c || !b ? c : e->FirstChildElement(b);
}

// tinyxml2's error, in words.
std::string xml_error_text(const tinyxml2::XMLDocument& doc) {
  switch (doc.ErrorID()) {
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
      return "an element is not closed, or closed with another tag";
    case tinyxml2::XML_ERROR_PARSING_ELEMENT:
      return "a malformed element";
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
      return "a malformed attribute";
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT:
      return "the document is empty";
    case tinyxml2::XML_ERROR_PARSING_TEXT:
      return "malformed text (an unescaped '<' or '&'?)";
    default:
      return std::string("malformed XML (") + doc.ErrorName() + ")";
  }
}

bool read_file(const std::string& path, std::string& text, std::string* err) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *err = "cannot read the file";
    return false;
  }
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  if (text.size() > kMaxXmlBytes) {
    *err = "the file is larger than 64 MiB";
    return false;
  }
  return true;
}

}  // namespace

model::SourceLocation locate(const std::string& file, const std::string& text, int line,
                             const std::string& needle) {
  model::SourceLocation loc{file, line, 1, line, 0};
  size_t start = 0;
  for (int l = 1; l < line && start != std::string::npos; ++l) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos || line < 1) return loc;
  size_t end = text.find('\n', start);
  std::string_view this_line(text.data() + start,
                             (end == std::string::npos ? text.size() : end) - start);
  size_t at = needle.empty() ? std::string_view::npos : this_line.find(needle);
  if (at == std::string_view::npos) {
    size_t first = this_line.find_first_not_of(" \t");
    loc.column = first == std::string_view::npos ? 1 : static_cast<int>(first) + 1;
    return loc;
  }
  loc.column = static_cast<int>(at) + 1;
  loc.end_column = loc.column + static_cast<int>(needle.size());
  return loc;
}

namespace {

void read_connection(const tinyxml2::XMLElement* c, XmlApplication& app,
                     std::vector<Diagnostic>& diags) {
  XmlConnection conn;
  conn.loc = locate(app.file, app.text, c->GetLineNum(), "<connection");
  const tinyxml2::XMLElement* from = child(c, "from", "output");
  const tinyxml2::XMLElement* to = child(c, "to", "input");
  conn.from = trimmed_text(from);
  conn.to = trimmed_text(to);
  if (conn.from.empty() || conn.to.empty()) {
    diags.push_back(error_at(conn.loc, "a <connection> needs both <from> and <to> port names"));
    return;
  }
  conn.from_loc = locate(app.file, app.text, from->GetLineNum(), conn.from);
  conn.to_loc = locate(app.file, app.text, to->GetLineNum(), conn.to);
  conn.id_loc = conn.loc;
  if (const char* id = c->Attribute("id")) {
    conn.id = id;
    for (const char* quote : {"\"", "'"}) {
      model::SourceLocation at =
          locate(app.file, app.text, c->GetLineNum(), std::string("id=") + quote + id + quote);
      if (at.end_column > 0) {
        conn.id_loc = at;
        break;
      }
    }
  }
  conn.protocol_loc = conn.loc;
  if (const tinyxml2::XMLElement* p = child(c, "protocol", "carrier")) {
    conn.protocol = trimmed_text(p);
    conn.protocol_loc = locate(app.file, app.text, p->GetLineNum(), conn.protocol);
  }
  app.connections.push_back(std::move(conn));
}

void read_children(const tinyxml2::XMLElement* root, XmlApplication& app,
                   std::vector<Diagnostic>& diags) {
  for (const tinyxml2::XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    std::string tag = e->Name();
    if (tag == "module") {
      XmlModule m;
      m.name = trimmed_text(child(e, "name"));
      m.node = trimmed_text(child(e, "node"));
      m.loc = locate(app.file, app.text, e->GetLineNum(), "<module");
      app.modules.push_back(std::move(m));
    } else if (tag == "connection") {
      read_connection(e, app, diags);
    } else if (tag == "arbitrator") {
      diags.push_back(error_at(locate(app.file, app.text, e->GetLineNum(), "<arbitrator"),
                               "<arbitrator> (yarpmanager's builder rules) is not read: the "
                               "running application selects by its monitors' constraints",
                               Severity::Warning));
    } else if (tag == "application") {
      diags.push_back(error_at(locate(app.file, app.text, e->GetLineNum(), "<application"),
                               "an embedded <application> is not read: verify it on its own",
                               Severity::Warning));
    }
  }
}

}  // namespace

std::optional<XmlApplication> read_application_xml(const std::string& path,
                                                   std::vector<Diagnostic>& diags) {
  XmlApplication app;
  app.file = path;
  std::string err;
  if (!read_file(path, app.text, &err)) {
    diags.push_back(error_at({path, 0, 0, 0, 0}, err + "; give a yarpmanager application XML"));
    return std::nullopt;
  }
  tinyxml2::XMLDocument doc;
  if (doc.Parse(app.text.data(), app.text.size()) != tinyxml2::XML_SUCCESS) {
    std::optional<XmlMismatch> m;
    if (doc.ErrorID() == tinyxml2::XML_ERROR_MISMATCHED_ELEMENT) m = find_xml_mismatch(app.text);
    if (m) {
      // tinyxml2 points at where the element opens; the typo is at the closing tag.
      std::string what = m->found.empty()  ? m->open + " is never closed"
                         : m->open.empty() ? m->found + " closes no open element"
                                           : m->found + " does not close " + m->open + " (line " +
                                                 std::to_string(m->open_line) + ")";
      model::SourceLocation loc{path, m->line, m->column, m->line, 0};
      loc.end_column = m->column + static_cast<int>((m->found.empty() ? m->open : m->found).size());
      diags.push_back(error_at(loc, "the XML does not parse: " + what));
      return std::nullopt;
    }
    std::string what = xml_error_text(doc);
    diags.push_back(error_at(locate(path, app.text, doc.ErrorLineNum(), ""),
                             "the XML does not parse: " + what));
    return std::nullopt;
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "application") {
    diags.push_back(error_at(locate(path, app.text, root ? root->GetLineNum() : 1, ""),
                             "the root element is not <application>: not a yarpmanager "
                             "application"));
    return std::nullopt;
  }
  app.name = trimmed_text(child(root, "name"));
  app.description = trimmed_text(child(root, "description"));
  size_t errors_before = diags.size();
  read_children(root, app, diags);
  for (size_t i = errors_before; i < diags.size(); ++i) {
    if (diags[i].severity == Severity::Error) return std::nullopt;
  }
  if (app.name.empty()) {
    diags.push_back(error_at(locate(path, app.text, root->GetLineNum(), "<application"),
                             "the <application> has no <name>"));
    return std::nullopt;
  }
  return app;
}

}  // namespace arbc::yarp

// Reads a yarpmanager application XML (the format of YARP's libYARP_manager xmlapploader.cpp):
//
//   <application>
//     <name>ball_line</name> <description>...</description>
//     <module> <name>ballTracker</name> <node>localhost</node> ... </module>
//     <connection id="..." persist="true">
//       <from>/ballTracker/out</from> <to>/motor/in</to>       (or <output> / <input>)
//       <protocol>tcp+recv.portmonitor+type.lua+file.ball</protocol>
//     </connection>
//   </application>
//
// Every connection keeps its place in the file, so findings point at the XML.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/diagnostic.h"

namespace arbc::yarp {

struct XmlConnection {
  std::string id;                          // the id attribute, if any
  std::string from, to;                    // YARP port names
  std::string protocol;                    // the carrier string; empty: YARP's default (tcp)
  model::SourceLocation loc;               // the <connection> element
  model::SourceLocation id_loc;            // its id attribute (id="..."), or loc
  model::SourceLocation protocol_loc;      // its <protocol>, or loc when absent
  model::SourceLocation from_loc, to_loc;  // the port names in <from> and <to>
};

struct XmlModule {
  std::string name;
  std::string node;
  model::SourceLocation loc;
};

struct XmlApplication {
  std::string file;  // as given
  std::string text;  // the file's content, to quote lines under diagnostics
  std::string name, description;
  std::vector<XmlModule> modules;
  std::vector<XmlConnection> connections;
};

// Reads `path`. Malformed XML, a root other than <application>, a connection without both
// ends: errors (id yarp-xml) appended to `diags`, and nullopt. Parts arbc does not use
// (<arbitrator>, embedded <application>) are warnings.
std::optional<XmlApplication> read_application_xml(const std::string& path,
                                                   std::vector<Diagnostic>& diags);

// The place of the first `needle` on `line` of `text` (column and end column), or the line's
// start when it is not there.
model::SourceLocation locate(const std::string& file, const std::string& text, int line,
                             const std::string& needle);

}  // namespace arbc::yarp

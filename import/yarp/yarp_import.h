// A yarpmanager application and its Lua monitors as arbc's core model
// (docs/yarp.md#verifying-an-existing-application):
//   - each <connection> is a model connection (source and destination are YARP port names);
//   - a destination port with two or more connections, or any constraint, is arbitrated; a
//     connection whose accept never returns true there is a feed (it only sets events);
//   - a rule's constraint is what YARP's evaluator selects on (yarp_evaluator.h);
//   - sets / unsets, must-set / must-unset and derived exclusive groups come from the scripts
//     (script_facts.h), restricted by YARP's rule that a monitor unsets only its own events;
//   - YARP-specific hazards are diagnostics with ids yarp-* (hazards.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/check_ids.h"
#include "core/diagnostic.h"
#include "import/yarp/app_xml.h"
#include "import/yarp/carrier.h"
#include "import/yarp/monitor_analysis.h"
#include "import/yarp/yarp_evaluator.h"

namespace arbc::yarp {

struct ImportedConnection {
  XmlConnection xml;
  Carrier carrier;
  std::optional<MonitorAnalysis> monitor;  // a receiving-side Lua monitor that was found
  ConstraintMeaning meaning;               // of the monitor's constraint ("" when none)
  bool analysed = false;  // the monitor's events and constraint are known (else opaque, true)
};

struct YarpImportOptions {
  std::vector<std::string> search_paths;  // --yarp-path
};

struct YarpImport {
  bool ok = false;  // false: bad input (exit 2), `diagnostics` says why
  XmlApplication xml;
  model::App app;
  std::vector<ImportedConnection> connections;  // parallel to app.connections
  std::vector<Diagnostic> diagnostics;          // problems with the input, and the hazards (yarp-*)
  // Parallel to diagnostics: the destination port a diagnostic is about ("" for the app).
  std::vector<std::string> diagnostic_ports;
};

YarpImport import_yarp(const std::string& xml_path, const YarpImportOptions& options);

// Each diagnostic id this importer reports, with its meaning (registered in core/check_ids.cc).
inline constexpr const char* kIdXml = diag::YarpXml.text();
inline constexpr const char* kIdCarrier = diag::YarpCarrier.text();
inline constexpr const char* kIdMonitorMissing = diag::YarpMonitorMissing.text();
inline constexpr const char* kIdScriptError = diag::YarpScriptError.text();
inline constexpr const char* kIdRequire = diag::YarpRequire.text();
inline constexpr const char* kIdOpaque = diag::YarpOpaque.text();
inline constexpr const char* kIdConstraintSyntax = diag::YarpConstraintSyntax.text();
inline constexpr const char* kIdSubstring = diag::YarpSubstringEvent.text();
inline constexpr const char* kIdKeyword = diag::YarpKeywordEvent.text();
inline constexpr const char* kIdTrigInterval = diag::YarpTrigInterval.text();
inline constexpr const char* kIdForever = diag::YarpEventForever.text();
inline constexpr const char* kIdShared = diag::YarpSharedEvent.text();
inline constexpr const char* kIdDuplicateId = diag::YarpDuplicateId.text();
inline constexpr const char* kIdSpecName = diag::YarpSpecName.text();
inline constexpr const char* kIdPortName = diag::YarpPortName.text();

}  // namespace arbc::yarp

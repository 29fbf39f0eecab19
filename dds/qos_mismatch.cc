#include "dds/qos_mismatch.h"

#include "core/json_diagnostic.h"

namespace arbc::dds {

namespace {

// What this process's endpoint has and what the remote one must have for DDS to refuse the
// match: a reader asks for at most what a writer offers.
struct Sides {
  std::string ours, theirs, key, word;  // word: the setting that makes ours match theirs
};

Sides sides_of(const QosMismatch& m) {
  if (m.policy == QosPolicy::Reliability) {
    // Only a reliable reader and a best-effort writer fail to match.
    return m.reader ? Sides{"requests reliable", "offers best effort", "reliability", "best_effort"}
                    : Sides{"offers best effort", "requests reliable", "reliability", "reliable"};
  }
  // Only a transient-local reader and a volatile writer fail to match.
  return m.reader ? Sides{"requests transient local", "offers volatile", "durability", "volatile"}
                  : Sides{"offers volatile", "requests transient local", "durability",
                          "transient_local"};
}

// "FILE:LINE:COL" of the port's entry in "qos": {"ports": ...}, else of "qos", else the file.
std::string place_in(const Deployment& d, const std::string& port) {
  for (const std::vector<std::string>& path :
       {std::vector<std::string>{"qos", "ports", port}, {"qos", "ports"}, {"qos"}}) {
    Diagnostic at = json_diagnostic(d.path, d.text, path, JsonPart::Key, "");
    if (at.loc.line > 0)
      return d.path + ":" + std::to_string(at.loc.line) + ":" + std::to_string(at.loc.column);
  }
  return d.path;
}

}  // namespace

std::string qos_mismatch_text(const Deployment& d, const QosMismatch& m) {
  const std::string remote = m.reader ? "publisher" : "subscriber";
  std::string line = "DDS: QoS mismatch on topic " + m.topic + " (" + m.port + "): ";
  if (m.policy == QosPolicy::Other) {
    return line + "a remote " + remote + "'s " + m.policy_name +
           " QoS is incompatible with this process's (DDS's default for it), so nothing flows "
           "between them; arbc sets only reliability and durability "
           "(docs/distributed.md#quality-of-service): give the program DDS's default " +
           m.policy_name;
  }
  Sides s = sides_of(m);
  std::string setting = "\"" + m.port + "\": {\"" + s.key + "\": \"" + s.word + "\"}";
  std::string where = d.path.empty() ? "a deployment file (--deploy)" : place_in(d, m.port);
  line += "a remote " + remote + " " + s.theirs + " " + s.key + ", this process's " +
          (m.reader ? "reader " : "writer ") + s.ours + ", so nothing flows between them; " +
          "if that is the program's QoS, write " + setting + " in \"qos\": {\"ports\": ...} of " +
          where;
  if (!m.reader && s.word == "transient_local")
    line += " (the subscriber then also gets the last messages written before it joined)";
  return line + " (docs/distributed.md#quality-of-service)";
}

}  // namespace arbc::dds

// `arbc status [--domain N] [--topic T] [--wait D]`: what every DDS mediator on a domain says
// of its arbitrated ports now (docs/distributed.md#live-status), read from /diagnostics as any
// ROS 2 tool reads it: a line per port, the selected rule, why each other rule is not selected,
// the counters. Exit 0 when some mediator was heard, 3 when none was within the wait, 2 on bad
// input.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/dds_plugin.h"
#include "cli/duration_option.h"
#include "cli/parse_error.h"
#include "cli/run_transport.h"
#include "core/duration_literal.h"
#include "dds/status_types.h"

namespace arbc::cli {

int status_command(std::span<char*> args) {
  CLI::App cli{"Show what the DDS mediators on a domain say of their arbitrated ports",
               "arbc status"};
  std::optional<int> domain_flag;
  std::string topic = "/diagnostics";
  double wait = 2.5;
  cli.add_option("--domain", domain_flag, "the DDS domain (default: ROS_DOMAIN_ID, else 0)");
  cli.add_option("--topic", topic,
                 "the mediators' diagnostic_msgs/msg/DiagnosticArray topic (default "
                 "/diagnostics; a deployment's \"status\" \"diagnostics\" renames it)");
  cli.add_option("--wait", wait,
                 "how long to listen, in wall seconds or with a unit (default 2.5s: a mediator "
                 "writes its diagnostics once a second)")
      ->transform(seconds_option(false))
      ->type_name("DURATION");
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(cli, e);
  }
  int domain = 0;
  std::string error;
  if (topic.empty() || topic == "/") error = "--topic needs a topic name, such as /diagnostics";
  if (wait > 3600) error = "--wait must be at most 1h";
  if (!error.empty() || !choose_domain(domain_flag, std::nullopt, &domain, &error)) {
    std::fprintf(stderr, "arbc status: error: %s\n", error.c_str());
    return kExitBadInput;
  }
  std::vector<Value> statuses;
  std::string note;
  bool read = read_dds_status(domain, topic, wait, &statuses, &note, &error);
  if (!note.empty()) std::fprintf(stderr, "arbc status: %s\n", note.c_str());
  if (!read) {
    std::fprintf(stderr, "arbc status: error: %s\n", error.c_str());
    return kExitRuntimeFailure;
  }
  if (statuses.empty()) {
    std::fprintf(stderr,
                 "arbc status: no arbc mediator's status on %s in domain %d within %s (is a "
                 "mediator running there, with its status on? `arbc run --transport dds` "
                 "writes it unless --no-status-topics or the deployment says \"status\": false)\n",
                 topic.c_str(), domain, duration_literal(wait).c_str());
    return kExitRuntimeFailure;
  }
  for (const Value& s : statuses) std::printf("%s\n", dds::status_line(s).c_str());
  return kExitOk;
}

}  // namespace arbc::cli

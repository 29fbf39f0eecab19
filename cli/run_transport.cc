#include "cli/run_transport.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "cli/commands.h"
#include "cli/dds_plugin.h"
#include "cli/duration_option.h"
#include "cli/msg_path_option.h"
#include "core/diagnostic.h"
#include "core/suggest.h"
#include "dds/deployment.h"

namespace arbc::cli {

namespace {

void print_error(const std::string& line) {
  std::fprintf(stderr, "arbc run: error: %s\n", line.c_str());
}

// "all", "none" or a comma-separated list of the app's modules.
bool parse_module_set(const std::string& text, const char* flag, const model::App& app,
                      ModuleSet* out) {
  if (text == "all") {
    *out = ModuleSet::everything();
    return true;
  }
  *out = ModuleSet::none();
  if (text == "none") return true;
  size_t start = 0;
  while (start <= text.size()) {
    size_t comma = text.find(',', start);
    std::string name = text.substr(start, comma == std::string::npos ? comma : comma - start);
    if (!app.find_module(name)) {
      std::string known;
      std::vector<std::string> names;
      for (const model::Module& m : app.modules) {
        known += (known.empty() ? "" : ", ") + m.name;
        names.push_back(m.name);
      }
      auto meant = closest_name(name, names);
      print_error(std::string(flag) + " '" + text + "': '" + name + "' is not a module of app " +
                  app.name + (meant ? "; did you mean '" + *meant + "'?" : "") +
                  " (its modules: " + known + "; or write all, none)");
      return false;
    }
    out->names.insert(name);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return true;
}

std::string describe_set(const ModuleSet& s) {
  if (s.all) return "all";
  if (s.names.empty()) return "none";
  std::string out;
  for (const std::string& n : s.names) out += (out.empty() ? "" : ",") + n;
  return out;
}

// The domain (choose_domain), or false after saying why not.
bool pick_domain(const TransportFlags& flags, const dds::Deployment& d, int* domain) {
  std::string error;
  if (choose_domain(flags.domain, d.domain, domain, &error)) return true;
  print_error(error);
  return false;
}

// ARBC_DDS_NO_PEER_AFTER=S: the first report of topics without a peer S wall seconds in
// instead of 10 (the later ones keep their proportions, dds/no_peer_reports.h). For tests,
// which would otherwise wait minutes to see the reports repeat.
bool pick_no_peer_after(double* seconds) {
  const char* text = std::getenv("ARBC_DDS_NO_PEER_AFTER");
  if (!text || !*text) return true;
  char* end = nullptr;
  double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value > 0 && value <= 3600)) {
    print_error(std::string("ARBC_DDS_NO_PEER_AFTER='") + text +
                "' is not a number of seconds above 0 and at most 3600 (the time of the first "
                "report of topics without a peer; unset it for 10 s)");
    return false;
  }
  *seconds = value;
  return true;
}

bool apply_dds(const TransportFlags& flags, const model::App& app, RunOptions* options) {
  dds::DdsOptions dds;
  std::string error;
  if (!flags.deploy.empty()) {
    std::vector<Diagnostic> problems;
    bool read = dds::read_deployment(flags.deploy, &dds.deployment, &problems);
    if (!read || !dds::check_deployment(dds.deployment, app, &problems)) {
      // As a compiler reports a spec: file:line:col: error: ..., the line quoted.
      SourceCache sources;
      for (const Diagnostic& d : problems) std::fputs(render(d, &sources).c_str(), stderr);
      return false;
    }
  }
  if (!pick_domain(flags, dds.deployment, &dds.domain)) return false;
  if (!pick_no_peer_after(&dds.unmatched_after)) return false;
  // --host none alone (--mediate follows --host): a process that would run for its whole
  // duration and do nothing, most often a mediator whose --mediate was forgotten.
  const ModuleSet& mediated = options->mediate ? *options->mediate : options->host;
  if (options->host.empty() && mediated.empty()) {
    print_error(
        "this process hosts no module and mediates none, so it would do nothing; "
        "give --mediate all (or the modules whose connections run here) for a mediator, "
        "or --host the modules it runs");
    return false;
  }
  dds.wait_peers = flags.wait_peers.value_or(0);
  dds.use_sim_time = flags.use_sim_time;
  dds.status = !flags.no_status_topics;
  options->realtime = true;
  options->unknown_until_fed = true;
  options->report_silent_lapses = true;
  options->report_bulk_drops = true;
  options->time_scale = flags.time_scale.value_or(1);
  dds.time_scale = options->time_scale;
  options->transport = load_dds_transport(app, std::move(dds), &error);
  if (!options->transport) {
    print_error(error);
    return false;
  }
  return true;
}

}  // namespace

bool choose_domain(std::optional<int> flag, std::optional<int> file, int* domain,
                   std::string* error) {
  std::string source;
  if (flag) {
    *domain = *flag;
    source = "--domain " + std::to_string(*domain);
  } else if (file) {
    *domain = *file;  // the file's reader checked its range
  } else if (const char* ros = std::getenv("ROS_DOMAIN_ID"); ros && *ros) {
    std::string_view text(ros);
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *domain);
    source = "ROS_DOMAIN_ID='" + std::string(text) + "'";
    if (ec != std::errc() || end != text.data() + text.size()) *domain = -1;
  } else {
    *domain = 0;
  }
  if (*domain >= 0 && *domain <= 232) return true;
  *error = source + " is not a DDS domain, a whole number from 0 to 232" +
           (flag ? "" : " (give --domain N, or unset ROS_DOMAIN_ID for domain 0)");
  return false;
}

void add_transport_options(CLI::App& cli, TransportFlags* flags) {
  cli.add_option("--transport", flags->transport,
                 "inproc (default: the whole app in this process) or dds (ports to other "
                 "processes over DDS topics)")
      ->check(CLI::IsMember({"inproc", "dds"}));
  cli.add_option("--host", flags->host,
                 "dds: the modules this process runs: M1,M2, all (default) or none");
  cli.add_option("--mediate", flags->mediate,
                 "dds: the modules whose incoming connections run here (default: the hosted)");
  cli.add_option(
      "--deploy", flags->deploy,
      "dds: a deployment file (domain, ros2, topics, types, qos, status; docs/distributed.md)");
  add_msg_path_option(cli,
                      &flags->msg_path);  // also what the deployment's types are checked against
  cli.add_option("--domain", flags->domain,
                 "dds: the DDS domain (default: the deployment's, else "
                 "ROS_DOMAIN_ID, else 0)");
  cli.add_option("--wait-peers", flags->wait_peers,
                 "dds: wait up to S wall seconds (or a time with its unit: 2min) for a peer on "
                 "every connected topic before starting (default 0: start at once)")
      ->transform(seconds_option(true))
      ->type_name("DURATION");
  cli.add_flag("--use-sim-time", flags->use_sim_time,
               "dds: age() measures stamps against ROS 2 simulated time, the last sample of "
               "/clock (rosgraph_msgs/msg/Clock), as a node with use_sim_time does");
  cli.add_flag("--no-status-topics", flags->no_status_topics,
               "dds: write no live status (each arbitrated port's latched status topic and "
               "/diagnostics; docs/distributed.md#live-status)");
  cli.add_option("--time-scale", flags->time_scale,
                 "wall-clock runs: time runs K times as fast as the wall clock (default 1)");
}

int apply_transport(const TransportFlags& flags, const model::App& app, RunOptions* options) {
  bool dds = flags.transport == "dds";
  if (!dds) {
    const char* needs = !flags.host.empty()      ? "--host"
                        : !flags.mediate.empty() ? "--mediate"
                        : !flags.deploy.empty()  ? "--deploy"
                        : flags.domain           ? "--domain"
                        : flags.wait_peers       ? "--wait-peers"
                        : flags.use_sim_time     ? "--use-sim-time"
                        : flags.no_status_topics ? "--no-status-topics"
                                                 : nullptr;
    if (needs) {
      print_error(std::string(needs) +
                  " needs --transport dds (the in-process transport runs "
                  "every module here)");
      return kExitBadInput;
    }
  }
  if (flags.wait_peers && !(*flags.wait_peers >= 0 && *flags.wait_peers <= 3600)) {
    print_error("--wait-peers must be from 0 to 3600 seconds (1h)");
    return kExitBadInput;
  }
  if (flags.time_scale && !(*flags.time_scale > 0 && *flags.time_scale <= 1000)) {
    print_error("--time-scale must be a number above 0 and at most 1000");
    return kExitBadInput;
  }
  if (flags.time_scale && !dds && !options->realtime) {
    print_error("--time-scale applies to runs on the wall clock (--transport dds or --realtime)");
    return kExitBadInput;
  }
  if (!dds) {
    options->time_scale = flags.time_scale.value_or(1);
    return kExitOk;
  }
  if (!flags.host.empty() && !parse_module_set(flags.host, "--host", app, &options->host))
    return kExitBadInput;
  if (!flags.mediate.empty()) {
    ModuleSet mediate;
    if (!parse_module_set(flags.mediate, "--mediate", app, &mediate)) return kExitBadInput;
    options->mediate = mediate;
  }
  return apply_dds(flags, app, options) ? kExitOk : kExitBadInput;
}

std::string describe_transport(const TransportFlags& flags, const RunOptions& options) {
  if (flags.transport != "dds") return {};
  char scale[32];
  std::snprintf(scale, sizeof scale, "%g", options.time_scale);
  return std::string("dds, time scale ") + scale + ", hosts " + describe_set(options.host) +
         ", mediates " + describe_set(options.mediate ? *options.mediate : options.host);
}

}  // namespace arbc::cli

#include "tests/yarp_real/replay_trace.h"

#include <cmath>
#include <fstream>
#include <tuple>

namespace arbc::yarp_test {

namespace {

// The instants at which an event entry of each port really ends: its expiry, unless the same
// owner sets or unsets it again before then (less than `tolerance` before: then the refresh
// itself races the expiry, and the expiry counts).
std::map<std::string, std::vector<double>> real_expiries(const std::vector<nlohmann::json>& events,
                                                         double tolerance) {
  using Key = std::tuple<std::string, std::string, std::string>;
  std::map<Key, std::vector<const nlohmann::json*>> by_key;
  for (const nlohmann::json& e : events) {
    if (e.value("op", "") == "expire") continue;
    by_key[{e.value("port", ""), e.value("event", ""), e.value("owner", "")}].push_back(&e);
  }
  std::map<std::string, std::vector<double>> out;
  for (const auto& [key, ops] : by_key) {
    for (size_t i = 0; i < ops.size(); ++i) {
      const nlohmann::json& op = *ops[i];
      if (op.value("op", "") != "set" || !op.contains("expiry")) continue;
      double expiry = op["expiry"].get<double>();
      bool refreshed = i + 1 < ops.size() && (*ops[i + 1])["t"].get<double>() < expiry - tolerance;
      if (!refreshed) out[std::get<0>(key)].push_back(expiry);
    }
  }
  return out;
}

// The instants at which an event of each port changes presence for one owner: a set of an
// entry that is not live, an unset of one that is. Messages of other connections around such
// an instant are decided in an order the replay only approximates.
std::map<std::string, std::vector<double>> changes(const std::vector<nlohmann::json>& events) {
  using Key = std::tuple<std::string, std::string, std::string>;
  std::map<Key, double> live_until;  // absent from the map: no entry
  std::map<std::string, std::vector<double>> out;
  for (const nlohmann::json& e : events) {
    std::string op = e.value("op", "");
    if (op == "expire") continue;
    Key key{e.value("port", ""), e.value("event", ""), e.value("owner", "")};
    double t = e["t"].get<double>();
    auto it = live_until.find(key);
    bool live = it != live_until.end() && t < it->second;
    if (op == "set") {
      if (!live) out[std::get<0>(key)].push_back(t);
      live_until[key] = e.contains("expiry") ? e["expiry"].get<double>() : 1e300;
    } else if (op == "unset") {
      if (live) out[std::get<0>(key)].push_back(t);
      live_until.erase(key);
    }
  }
  return out;
}

bool near_any(double t, const std::vector<double>& instants, double tolerance) {
  for (double x : instants)
    if (std::fabs(x - t) <= tolerance) return true;
  return false;
}

}  // namespace

bool read_recorded_run(const std::string& path,
                       const std::map<std::string, std::string>& destination,
                       const std::map<std::string, double>& throttle, double window,
                       double tolerance, RecordedRun* out, std::string* err) {
  std::ifstream in(path);
  if (!in) {
    *err = path + ": cannot read the trace";
    return false;
  }
  std::vector<nlohmann::json> events;
  std::map<std::string, std::vector<double>> throttle_ends;  // connection -> last delivery + period
  std::string line;
  while (std::getline(in, line)) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded()) {
      *err = path + ": a line that is not JSON: " + line;
      return false;
    }
    double t = j["t"].get<double>();
    std::string type = j["type"].get<std::string>();
    out->end = std::max(out->end, t);
    if (type == "event") events.push_back(j);
    if (t >= window) continue;
    if (type == "publish") out->publishes.push_back({t, j["port"], j["value"]});
    bool deliver = type == "deliver";
    std::string reason = j.value("reason", "");
    if (!deliver && !(type == "drop" && (reason == "not-selected" || reason == "throttled")))
      continue;
    std::string c = j["connection"].get<std::string>();
    auto d = destination.find(c);
    if (d == destination.end()) continue;
    out->decisions.push_back({t, c, d->second, deliver, deliver ? j["value"] : nlohmann::json()});
    if (deliver && throttle.count(c)) throttle_ends[c].push_back(t + throttle.at(c));
  }
  std::map<std::string, std::vector<double>> expiries = real_expiries(events, tolerance);
  std::map<std::string, std::vector<double>> changed = changes(events);
  for (Decision& d : out->decisions) {
    d.sensitive = near_any(d.t, expiries[d.port], tolerance) ||
                  near_any(d.t, changed[d.port], tolerance) ||
                  near_any(d.t, throttle_ends[d.connection], tolerance);
  }
  return true;
}

PortComparison compare_deliveries(const std::vector<std::string>& a,
                                  const std::vector<bool>& sensitive,
                                  const std::vector<std::string>& y) {
  PortComparison r;
  r.arbc = a.size();
  r.yarp = y.size();
  // lcs[i][j]: the longest common subsequence of a[i..] and y[j..].
  std::vector<std::vector<uint32_t>> lcs(a.size() + 1, std::vector<uint32_t>(y.size() + 1, 0));
  for (size_t i = a.size(); i-- > 0;)
    for (size_t j = y.size(); j-- > 0;)
      lcs[i][j] = a[i] == y[j] ? lcs[i + 1][j + 1] + 1 : std::max(lcs[i + 1][j], lcs[i][j + 1]);
  size_t i = 0, j = 0;
  while (i < a.size() || j < y.size()) {
    if (i < a.size() && j < y.size() && a[i] == y[j]) {
      ++r.matched, ++i, ++j;
    } else if (j == y.size() || (i < a.size() && lcs[i + 1][j] >= lcs[i][j + 1])) {
      if (sensitive[i]) {
        ++r.missing_sensitive;
      } else {
        r.missing.push_back(a[i]);
      }
      ++i;
    } else {
      r.extra.push_back(y[j++]);
    }
  }
  return r;
}

}  // namespace arbc::yarp_test

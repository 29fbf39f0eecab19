// The files `arbc verify --counterexamples DIR` writes (docs/cli.md): each counterexample as a
// tests file that replays it, or, when it cannot be replayed, a .txt that says why. The names
// are functions of their own so that their rules have tests (cli/counterexample_files_test.cc).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "verify/report_format.h"

namespace arbc::cli {

// The stem of a counterexample over time: APP.RULE for a spacing (APP.RULE.after_OTHER after
// another rule), APP.RULE.KIND for the others, APP.M_p.KIND for one that names no rule (a
// stability, a response answered by any rule of the port). Unique in `used`, where it is added:
// a second property of the same rule and kind gets 2, 3, ... appended, never overwriting the
// first's file.
std::string temporal_stem(const std::string& app, const model::TemporalProperty& p,
                          std::set<std::string>& used);

// The stem of a counterexample to a claim about single decisions: APP.WHERE.RULE[.RULE].CHECK,
// WHERE the port ("M.p" written M_p) or the resource's name. Unique in `used` as above.
std::string finding_stem(const std::string& app, const std::string& where, const verify::Finding& f,
                         std::set<std::string>& used);

// Writes every counterexample the reports hold into `dir` (made if missing), each test's
// `tests for` naming its spec relative to `dir`. False, after saying why on stderr, when a file
// cannot be written.
bool write_counterexamples(const std::vector<verify::InputReport>& reports, const std::string& dir);

}  // namespace arbc::cli

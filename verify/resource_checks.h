// `resource` checks (docs/checks.md#resource): for every pair of rules into two different
// ports of a resource, no message (same source) or pair of messages (different sources) makes
// both deliver a command that uses the resource. Event containers are per port, so the two
// ports' event states are independent: each rule only has to be selectable (not dead).
#pragma once

#include <z3++.h>

#include <vector>

#include "verify/data_query.h"
#include "verify/port_scope.h"
#include "verify/report.h"
#include "verify/verify.h"

namespace arbc::verify {

void run_resource_checks(const model::App& app, const std::vector<PortScope>& scopes,
                         const VerifyOptions& options, z3::context& ctx, Clock::time_point deadline,
                         DataQuery& data, VerifyReport& report);

}  // namespace arbc::verify

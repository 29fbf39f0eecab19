// `resource` checks (docs/checks.md#resource): for every pair of rules into two different
// ports of a resource, no two messages (of one source or two) make both deliver a command that
// uses the resource, one decision after the other in one event state: the second decides in the
// state the first's delivery left, which differs only by the delivery events that delivery
// feeds into the second's port (verify/delivery_effects.h). Each port's container holds its own
// facts (verify/joint_scope.h, core/event_facts.h).
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

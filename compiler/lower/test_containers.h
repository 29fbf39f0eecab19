// Which event container each `expect CONSTRAINT [in M.p] at D;` reads (docs/testing.md). Every
// arbitrated port owns a container, and the same event name in two ports is two facts
// (core/event_facts.h): the proof and the runtime checks read an event in its port's container,
// so a test's event state names one too. The bare form is kept where it means one thing: the
// event lives in one container of the test's app (or in several that hold one fact).
#pragma once

#include <vector>

#include "core/app_model.h"
#include "core/diagnostic.h"
#include "core/test_case.h"

namespace arbc::lower {

// Fills Expectation::containers of every State expectation of `tests`, and reports (error
// `test-container`) a bare form over an event that lives in several containers, naming them
// and the `in M.p` to write, or in none the test runs, which no event state could show.
void resolve_test_containers(const model::App& app, std::vector<model::TestCase>& tests,
                             std::vector<Diagnostic>& diagnostics);

}  // namespace arbc::lower

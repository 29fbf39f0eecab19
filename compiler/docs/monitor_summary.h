// One line saying what a connection's monitor does, for the docs' connections table.
#pragma once

#include <string>

#include "core/app_model.h"

namespace arbc::docs {

std::string monitor_summary(const model::Connection& c);

}  // namespace arbc::docs

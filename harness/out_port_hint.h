// Why a "Module.port" named on the command line or in an inputs file is not an out-port of the
// app, and what to write instead: `--inputs` lines and `--stub-rate` name the ports a stand-in
// publishes on, and a newcomer's slip (a typo, an in-port, a module without its port) should get
// the name to write rather than a bare refusal.
#pragma once

#include <string>

#include "core/app_model.h"

namespace arbc::harness {

// For a `port` that is not an out-port of `app`: "'Joystick.cmnd' is not an out-port of app
// base; did you mean 'Joystick.cmd'?", or, for an in-port, which out-ports there are.
std::string not_an_out_port(const model::App& app, const std::string& port);

}  // namespace arbc::harness

// `--msg-path DIR` on every command that reads a spec: where `use ros2` (and `run`'s deployment
// check) look for PKG/msg/NAME.msg files before ARBC_MSG_PATH and AMENT_PREFIX_PATH
// (core/ros2_msg_path.h).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace arbc::cli {

// Adds the option, repeatable, storing the folders in `dirs`; once the command line is parsed,
// puts them before ARBC_MSG_PATH in this process's environment. The environment, not an
// argument: every stage that reads a spec (the front end under check, verify, build, run, test,
// docs, the LSP's analyses, `arbc test`'s replays) then finds the same files without each
// call threading a path through, and processes arbc starts inherit it.
CLI::Option* add_msg_path_option(CLI::App& app, std::vector<std::string>* dirs);

}  // namespace arbc::cli

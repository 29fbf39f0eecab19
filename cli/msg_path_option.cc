#include "cli/msg_path_option.h"

#include <cstdlib>

namespace arbc::cli {

CLI::Option* add_msg_path_option(CLI::App& app, std::vector<std::string>* dirs) {
  return app
      .add_option_function<std::vector<std::string>>(
          "--msg-path",
          [dirs](const std::vector<std::string>& given) {
            *dirs = given;
            std::string path;
            for (const std::string& dir : given) path += (path.empty() ? "" : ":") + dir;
            if (const char* old = std::getenv("ARBC_MSG_PATH"); old && *old)
              path += std::string(":") + old;
            setenv("ARBC_MSG_PATH", path.c_str(), 1);
          },
          "a folder of PKG/msg/NAME.msg files for `use ros2` (repeatable; searched before "
          "ARBC_MSG_PATH and AMENT_PREFIX_PATH/share)")
      ->type_name("DIR");
}

}  // namespace arbc::cli

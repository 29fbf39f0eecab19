#include "import/yarp/yarp_directory.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace arbc::yarp {

YarpDirectory yarp_directory(const std::string& path) {
  namespace fs = std::filesystem;
  YarpDirectory out;
  std::error_code ec;
  fs::path dir(path);
  if (!fs::is_directory(dir, ec) || fs::exists(dir / "app.json", ec)) return out;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    if (e.path().extension() == ".xml" && e.is_regular_file(ec))
      out.xmls.push_back(e.path().string());
  }
  std::sort(out.xmls.begin(), out.xmls.end());
  // ports.json names the app, and so the application XML the build wrote beside it.
  std::ifstream in(dir / "ports.json", std::ios::binary);
  if (!in) return out;
  nlohmann::json ports = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!ports.is_object() || !ports.contains("app") || !ports["app"].is_string()) return out;
  fs::path xml = dir / (ports["app"].get<std::string>() + ".xml");
  if (fs::is_regular_file(xml, ec)) out.build_xml = xml.string();
  return out;
}

}  // namespace arbc::yarp

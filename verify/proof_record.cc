#include "verify/proof_record.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/sha256.h"
#include "verify/executable_id.h"

namespace arbc::verify {

std::string proof_record(const std::string& app_json, const std::string& summary) {
  std::string id = executable_build_id();
  if (id.empty()) return "";
  nlohmann::ordered_json record;
  record["proved_by"] = "arbc build";
  record["arbc"] = ARBC_VERSION;
  record["arbc_build_id"] = id;
  record["app_json_sha256"] = sha256_hex(app_json);
  record["summary"] = summary;
  return record.dump(2) + "\n";
}

std::optional<std::string> recorded_proof(const std::string& dir, const std::string& app_json) {
  std::string id = executable_build_id();
  if (id.empty()) return std::nullopt;
  std::ifstream in(std::filesystem::path(dir) / kProofRecordFile, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  nlohmann::json record = nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
  if (!record.is_object()) return std::nullopt;
  auto field = [&](const char* key) -> std::string {
    auto it = record.find(key);
    return it != record.end() && it->is_string() ? it->get<std::string>() : "";
  };
  if (field("arbc_build_id") != id || field("app_json_sha256") != sha256_hex(app_json)) {
    return std::nullopt;
  }
  std::string summary = field("summary");
  if (summary.empty()) return std::nullopt;
  return summary;
}

}  // namespace arbc::verify

#include "baker/cli/report_sidecar.h"

#include <fstream>

#include <fmt/format.h>

#include "data_formats/atomic_file.h"
#include "data_formats/error.h"

namespace skybake {

std::filesystem::path reportSidecarPath(const std::filesystem::path& bake_file) {
  std::filesystem::path p = bake_file;
  return p.replace_extension(".report.json");
}

nlohmann::ordered_json readReportSidecar(const std::filesystem::path& bake_file) {
  std::ifstream in(reportSidecarPath(bake_file));
  if (!in) return nlohmann::ordered_json::object();
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(in, nullptr, false);
  return j.is_object() ? j : nlohmann::ordered_json::object();
}

void writeReportSidecar(const std::filesystem::path& bake_file, const nlohmann::ordered_json& report) {
  writeFileContentsAtomically(reportSidecarPath(bake_file), report.dump(2) + "\n");
}

}  // namespace skybake

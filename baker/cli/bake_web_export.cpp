#include "baker/cli/bake_web_export.h"

#include <filesystem>

#include "baker/cli/report_sidecar.h"
#include "data_formats/bake_file/bake_file.h"
#include "data_formats/config/config.h"

namespace skybake::cli {

BakeWebExport webExportOfBakeFile(const std::string& bake_path, WebTableEncoding encoding) {
  const BakeFile header = readBakeFileHeader(bake_path);
  const std::string name = parseConfig(header.config_toml, bake_path + " [skybake:config]").name;
  BakeWebExport out{Sky::load(bake_path), {}};
  const nlohmann::ordered_json facts = bakeFacts(out.sky, std::filesystem::path(bake_path).filename().string(),
                                                 header.format_version, name, readReportSidecar(bake_path));
  out.files = webExport(out.sky, facts, encoding);
  return out;
}

}  // namespace skybake::cli

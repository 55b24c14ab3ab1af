// skybake export FILE.exr --format web -o DIR: a bake as files a WebGL2 or
// three.js program loads (baker/export/web_export.h; data_formats/FORMAT.md,
// "Web export").
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "baker/cli/bake_web_export.h"
#include "baker/cli/commands.h"
#include "baker/cli/option_checks.h"
#include "data_formats/atomic_file.h"
#include "data_formats/error.h"
#include "runtime/tables/gpu_tables.h"

namespace skybake::cli {
namespace {

struct ExportOptions {
  std::string bake_path;
  std::string format = "web";
  std::string output_dir;
};

// Whether `dir` holds a web export already (its manifest says so): the
// only non-empty folder an export replaces files in.
bool holdsWebExport(const std::filesystem::path& dir) {
  std::ifstream in(dir / kWebManifestName);
  const nlohmann::json manifest = nlohmann::json::parse(in, nullptr, false);
  return manifest.is_object() && manifest.value("format", "") == kWebExportFormat;
}

// The output folder: new, empty, or an earlier web export (whose files are
// replaced); anything else is refused before the bake is read.
void requireExportFolder(const std::filesystem::path& dir) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(dir, error);
  if (!std::filesystem::exists(status)) return;
  if (!std::filesystem::is_directory(status)) {
    refuseOptionValue("-o", dir.string(), "exists and is not a folder; the web export is a folder of files");
  }
  if (!std::filesystem::is_empty(dir, error) && !holdsWebExport(dir)) {
    refuseOptionValue("-o", dir.string(),
                      "holds files that are not a skybake web export; choose a new or empty folder (an earlier "
                      "export there is replaced)");
  }
}

void runExport(const ExportOptions& o) {
  const std::filesystem::path dir = o.output_dir;
  requireExportFolder(dir);
  const BakeWebExport web = webExportOfBakeFile(o.bake_path);
  const std::vector<WebFile>& files = web.files;
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throwBadInput(fmt::format("{}: cannot create the folder: {}", dir.string(), error.message()));
  uint64_t total = 0;
  for (const WebFile& file : files) {
    requireWritableOutput(dir / file.name, {o.bake_path});
    writeFileContentsAtomically(dir / file.name, file.bytes);
    total += file.bytes.size();
  }
  constexpr double kMiB = 1024.0 * 1024.0;
  const uint64_t upload = gpuUploadBytes(web.sky.contents(), GpuTablePrecision::Half).total();
  fmt::print(
      "skybake: exported {} for the web into {}/: {} files, {:.1f} MiB ({:.0f} % of its {:.1f} MiB half-float "
      "GPU upload; the tables gzip-compressed)\n",
      o.bake_path, dir.string(), files.size(), total / kMiB, 100.0 * total / upload, upload / kMiB);
}

}  // namespace

Command addExportCommand(CLI::App& app) {
  auto o = std::make_shared<ExportOptions>();
  CLI::App* cmd = app.add_subcommand("export", "Write a bake in another format (web: for WebGL2 and three.js).");
  cmd->add_option("file", o->bake_path, "Bake file (.exr).")->required();
  cmd->add_option("--format", o->format,
                  "web: the GPU textures (half-float 4D tables), gzip-compressed, the GLSL library and a JSON "
                  "manifest (data_formats/FORMAT.md, \"Web export\").")
      ->check(CLI::IsMember({"web"}))
      ->required();
  cmd->add_option("-o,--output", o->output_dir,
                  "Folder to write into: new, empty, or an earlier web export (its files are replaced).")
      ->required();
  return {cmd, [o] { runExport(*o); }};
}

}  // namespace skybake::cli

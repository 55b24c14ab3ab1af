// A bake file's web export with its facts (the config's name, the report
// sidecar's validated errors), as `skybake export` writes it and `skybake
// view` serves it.
#pragma once

#include <string>
#include <vector>

#include "baker/export/web_export.h"
#include "runtime/sky.h"

namespace skybake::cli {

struct BakeWebExport {
  Sky sky;
  std::vector<WebFile> files;
};

// Reads the bake (Error(BadInput) naming it when it cannot) and exports it.
BakeWebExport webExportOfBakeFile(const std::string& bake_path, WebTableEncoding encoding = WebTableEncoding::Gzip);

}  // namespace skybake::cli

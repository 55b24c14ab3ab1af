// A bake for WebGL2 and three.js programs (`skybake export --format web`;
// `skybake view` serves the same files): the textures the GLSL library
// reads (runtime/gl/sky_gpu_textures.h: the 4D tables as half floats, the
// 2D tables as floats), each gzip-compressed (or, for a server on the same
// machine, as they are); the GLSL library itself; and
// a JSON manifest of sizes, formats, the uniform block's values by name,
// the channels' meaning and their colour. data_formats/FORMAT.md ("Web
// export") is the format's description; runtime/glsl/web/skybake_web.js
// loads it into WebGL2.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/sky.h"

namespace skybake {

// The manifest's "format" and "version".
inline constexpr const char* kWebExportFormat = "skybake-web";
inline constexpr int kWebExportVersion = 1;
inline constexpr const char* kWebManifestName = "manifest.json";

// How the tables' files hold their bytes: gzip-compressed (for a web
// server: 61 % of the bytes for the default bake), or as they are (for
// `skybake view`, whose page on the same machine then neither waits for
// the compression nor spends its own time unpacking).
enum class WebTableEncoding { Gzip, None };

struct WebFile {
  std::string name;        // within the export's folder
  std::string media_type;  // what an HTTP server states for it
  std::string bytes;
};

// The export's files, the manifest last (written last, a reader never sees
// it name a file that is not there yet). `facts` goes into the manifest as
// it is (bakeFacts): what a viewer shows about the bake.
std::vector<WebFile> webExport(const Sky& sky, const nlohmann::ordered_json& facts,
                               WebTableEncoding encoding = WebTableEncoding::Gzip);

// What a viewer shows about a bake: its file and format version, the
// config's name, channels, sizes, orders, and, where `skybake validate`
// left them in the report sidecar, the validated errors (`sidecar`, the
// sidecar's JSON or an empty object).
nlohmann::ordered_json bakeFacts(const Sky& sky, const std::string& file_name, int format_version,
                                 const std::string& atmosphere_name, const nlohmann::ordered_json& sidecar);

}  // namespace skybake

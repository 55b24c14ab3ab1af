// The JSON sidecar next to a bake file (earth.exr -> earth.report.json): the
// bake report (also in the EXR header) plus what later commands add, such as
// `skybake validate`'s error figures.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace skybake {

std::filesystem::path reportSidecarPath(const std::filesystem::path& bake_file);

// Reads the sidecar; an absent or unreadable one reads as an empty object.
nlohmann::ordered_json readReportSidecar(const std::filesystem::path& bake_file);

// Writes `report` as the sidecar, atomically.
void writeReportSidecar(const std::filesystem::path& bake_file, const nlohmann::ordered_json& report);

}  // namespace skybake

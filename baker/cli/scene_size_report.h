// What `skybake bake` says about the sizes a narrowed scene's tables got:
// which the bake chose from the whole domain's and which the config gave,
// and the share of the whole bake's 4D texels they hold.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "data_formats/config/config.h"

namespace skybake {

struct SceneSizeChoice {
  std::string description;      // one line for the terminal
  nlohmann::ordered_json json;  // for the report sidecar's "scene_sizes"
};

// For a bake whose settled config (settledBakeConfig) narrows the domain;
// nullopt otherwise. `requested` is the config before settling: its
// resolution.scattering is the whole domain's.
std::optional<SceneSizeChoice> sceneSizeChoice(const BakeConfig& requested, const BakeConfig& settled);

}  // namespace skybake

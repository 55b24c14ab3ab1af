// A spectral bake's lane groups as ordinary bakes (FORMAT.md, "Spectral bakes").
#include <fmt/format.h>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/error.h"

namespace skybake {

BakeFile takeLaneGroup(BakeFile& spectral, size_t g) {
  BakeFile group;
  group.config_toml = spectral.config_toml;
  group.orders_computed = spectral.orders_computed;
  group.format_version = spectral.format_version;
  group.report_json = spectral.report_json;
  group.contents = spectral.contents;
  if (spectral.contents.lane_groups.empty()) {
    if (g != 0) throw Error(ErrorKind::Internal, fmt::format("lane group {} of a bake of one group", g));
    group.tables = std::move(spectral.tables);
    return group;
  }
  if (g >= spectral.contents.lane_groups.size() ||
      spectral.lane_group_tables.size() != spectral.contents.lane_groups.size()) {
    throw Error(ErrorKind::Internal,
                fmt::format("lane group {} of a spectral bake of {} groups", g, spectral.contents.lane_groups.size()));
  }
  group.contents.atmosphere = spectral.contents.lane_groups[g];
  group.contents.lane_groups.clear();
  // The irradiance rows are blended over one of the group's own channels, as
  // an ordinary bake of those wavelengths blends them.
  group.contents.domain.irradiance_depth_channel = irradianceDepthChannel(group.contents.atmosphere);
  group.tables = std::move(spectral.lane_group_tables[g]);
  // The part a group without Mie scattering holds zeros in: an ordinary bake
  // of those wavelengths has no such table.
  if (!bakeStoresSingleMie(group.contents.atmosphere)) group.tables.single_mie.texels = {};
  return group;
}

}  // namespace skybake

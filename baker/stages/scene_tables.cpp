#include "baker/stages/scene_tables.h"

#include "baker/stages/multiple_scattering_table.h"
#include "baker/stages/single_scattering_tables.h"

namespace skybake {

void narrowTablesToScene(const StageContext& scene, const TableSampler& whole, const Texture2D& optical_depth,
                         const MultipleScatteringPhase& stored_shape, Texture4D scene_density, BakeTables& tables) {
  computeSingleScatteringTables(scene, optical_depth, tables.single_rayleigh, tables.single_mie);
  tables.multiple_scattering = computeMultipleScatteringTable(scene, optical_depth, whole, tables.multiple_density,
                                                              stored_shape, kStoredRaySegments);
  tables.multiple_density = std::move(scene_density);
}

}  // namespace skybake

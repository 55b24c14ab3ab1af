// Error against the reference: evaluates a method (the bake, or a comparator)
// and the reference on a query set and reports relative errors per channel,
// per sun band, for sky rays, ground rays and rays to a point separately.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "baker/stages/progress.h"
#include "baker/validation/error_report.h"
#include "baker/validation/reference_cache.h"
#include "baker/validation/validation_queries.h"
#include "runtime/sky.h"

namespace skybake {

// More Monte Carlo paths per query than this would take days per query set
// (--reference-samples).
inline constexpr int kMaxReferencePaths = 100000000;

struct ReferenceSettings {
  int paths = 32768;  // Monte Carlo paths per query (see docs/QUERIES.md for the noise this gives)
  std::filesystem::path cache_directory = defaultReferenceCacheDirectory();  // empty: no cache
};

// Settings from the command-line options shared by validate and compare: an
// empty cache_dir means the default directory, no_cache disables caching.
ReferenceSettings referenceSettings(int paths, const std::string& cache_dir, bool no_cache);

struct ReferenceValues {
  std::vector<CachedReference> radiance;  // one per query of the set
  std::vector<CachedReference> irradiance;
  double seconds = 0.0;  // spent computing what the cache did not have
  int computed = 0;
  int cached = 0;
};

// A query's key in the reference cache and the seed of its Monte Carlo paths.
std::string radianceKey(const RadianceQuery& query);
std::string irradianceKey(const IrradianceQuery& query);

// Rays to a point with the sun below the camera's horizon take this many
// times the reference's paths. The air near such a camera is in the
// planet's shadow, so a short segment's value is nearly all multiple
// scattering, which the paths estimate, where a whole ray's is largely the
// sunlit air's single scattering, computed exactly: at the same paths, rays
// to points read 0.68 % relative standard error in civil twilight against
// 0.28 % for sky rays (docs/MEASUREMENTS.md).
inline constexpr int kTwilightPointRayPathFactor = 2;

// The paths of `query`'s reference, for `paths` per query.
int referencePathsFor(const RadianceQuery& query, int paths);
// The paths of item `item` of `queries` (radiance queries by their index,
// then irradiance queries by their index + the radiance count).
int referencePathsFor(const QuerySet& queries, size_t item, int paths);

// The queries of the set the cache does not hold: radiance queries by their
// index, then irradiance queries by their index + the radiance count.
std::vector<size_t> queriesMissingFromCache(const ReferenceCache& cache, const QuerySet& queries);

// The reference is computed in batches of this many queries per thread: small
// enough that a checkpoint comes soon after kReferenceCheckpointSeconds,
// large enough that threads seldom wait for the batch's slowest query.
inline constexpr int kReferenceQueriesPerThreadPerBatch = 16;
// What a killed run may lose: the reference computed so far is saved to the
// cache at least this often (seconds), so a cluster job stopped at its time
// limit leaves its work for the next one.
inline constexpr double kReferenceCheckpointSeconds = 60.0;

// Runs compute(item) for every item in parallel batches and store(item) for
// each after its batch, in order, saving the cache at least every
// kReferenceCheckpointSeconds and at the end. Returns the seconds spent.
// Shared by the spectral and the colour reference.
double computeInCheckpointedBatches(const std::vector<size_t>& items, const std::string& stage, ProgressSink& progress,
                                    ReferenceCache& cache, const std::function<void(size_t)>& compute,
                                    const std::function<void(size_t)>& store);

// The reference for every query of the set, from the cache where it holds
// them; the rest computed and added to the cache as it goes, under the
// progress stage `stage`. `atmosphere` holds at most 4 wavelengths (a
// spectral bake's lane groups are computed one at a time:
// lane_group_validation.h).
ReferenceValues computeReferenceValues(const AtmosphereParameters& atmosphere, const QuerySet& queries,
                                       const ReferenceSettings& settings, ProgressSink& progress,
                                       const std::string& stage = "reference");

// Piece `piece` (1 to `pieces`) of a query set: every pieces-th query,
// radiance then irradiance, so pieces mix cheap and expensive queries alike.
// The pieces together are the set; each can be computed by its own job.
QuerySet queryPiece(const QuerySet& queries, int piece, int pieces);

// A radiance query in the local frame: camera above the +z pole, sun in the
// x-z plane, view azimuth from the sun's.
struct QueryGeometry {
  glm::dvec3 camera, view, sun;
  Moon moon;  // none unless the query has one
};
QueryGeometry geometryOf(const AtmosphereParameters& atmosphere, const RadianceQuery& query);
// An irradiance query's: the surface's point as the camera, its normal (+z)
// as the view.
QueryGeometry geometryOf(const AtmosphereParameters& atmosphere, const IrradianceQuery& query);

// A method's answers for every query of a set.
struct MethodValues {
  std::vector<Spectrum> radiance;       // what the viewer receives (see Sky::receivedRadiance)
  std::vector<Spectrum> transmittance;  // along the same segment
  std::vector<Spectrum> irradiance;     // sky irradiance; empty if the method has none
  double seconds_per_ray = 0.0;         // radiance lookups only
};

MethodValues evaluateBake(const Sky& sky, const QuerySet& queries);

// The quantity a radiance query measures: "sky_radiance", "ground_radiance"
// (a ray that ends on the ground), "radiance_to_point" (a query with a
// distance), or "" for a ray that misses the atmosphere.
std::string radianceQuantity(const AtmosphereParameters& atmosphere, const RadianceQuery& query);

// The queries a bake answers: without radiance to points (scene.outputs) no
// query with a distance; without ground irradiance no ray that ends on the
// ground (its lit ground needs the irradiance) and no irradiance query.
// Also drops the queries outside the bake's scene ranges (camera, sun and,
// for radiance to a point, the point): Sky::bakedRanges.
// `left_out` gets a sentence saying what was dropped, or stays empty.
QuerySet queriesAnsweredBy(const Sky& sky, const QuerySet& queries, std::string& left_out);

ErrorReport compareWithReference(const AtmosphereParameters& atmosphere, const QuerySet& queries,
                                 const ReferenceValues& reference, const MethodValues& method, int reference_paths);

}  // namespace skybake

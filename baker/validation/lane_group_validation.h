// Validation lane group by lane group (Sky::laneGroup). The reference
// solver computes at most 4 wavelengths at a time, so a spectral bake's
// groups are each validated as the ordinary bake of their wavelengths: a
// group's reference is computed for its own atmosphere (the one its bake
// pass used, as the file states it) and cached in that atmosphere's own
// directory, the one an ordinary bake of the same wavelengths uses; its
// lookups are compared channel by channel; the groups' reports are joined
// into one that holds every channel. An ordinary or colour bake is its own
// one group, validated as before.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "baker/validation/validation.h"

namespace skybake {

// Group g's reference for every query of the set (computeReferenceValues on
// laneGroup(g).atmosphere()), one group after the other; the progress
// stage names the group when there are several.
std::vector<ReferenceValues> computeLaneGroupReferences(const Sky& sky, const QuerySet& queries,
                                                        const ReferenceSettings& settings, ProgressSink& progress);

// Group g's lookups for every query of the set (evaluateBake on laneGroup(g)).
std::vector<MethodValues> evaluateLaneGroups(const Sky& sky, const QuerySet& queries);

// What the groups' references cost together: seconds, computed and cached
// queries summed (no values).
ReferenceValues referenceTotals(const std::vector<ReferenceValues>& groups);

// The lookups' seconds per ray for every channel: the groups' summed.
double secondsPerRay(const std::vector<MethodValues>& groups);

// compareWithReference for each group, joined: the report of the bake's
// atmosphere, its channels those of the groups in order.
ErrorReport compareLaneGroupsWithReference(const Sky& sky, const QuerySet& queries,
                                           const std::vector<ReferenceValues>& references,
                                           const std::vector<MethodValues>& bakes, int reference_paths);

// Per group: its wavelengths and its reference's cache use (for the JSON
// report of a spectral bake).
nlohmann::ordered_json laneGroupsJson(const Sky& sky, const std::vector<ReferenceValues>& references);

}  // namespace skybake

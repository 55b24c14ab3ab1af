#include "runtime/lookup_geometry.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "data_formats/error.h"

namespace skybake {
namespace {

bool allFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

[[noreturn]] void refuseGeometry(const char* what, const glm::dvec3& v, const char* reason) {
  char text[160];
  std::snprintf(text, sizeof(text), " = (%g, %g, %g): ", v.x, v.y, v.z);
  throwBadInput(std::string(what) + text + reason);
}

double largestComponent(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

glm::dvec3 normalisedDirection(const glm::dvec3& d, const char* what) {
  if (!allFinite(d)) refuseGeometry(what, d, "not finite");
  const double largest = largestComponent(d);
  if (largest == 0.0) refuseGeometry(what, d, "a direction needs a length above 0");
  const glm::dvec3 scaled = d / largest;  // its length in [1, sqrt(3)]: no underflow or overflow
  return scaled / glm::length(scaled);
}

glm::dvec3 positionWithinReach(const glm::dvec3& p, const char* what) {
  if (!allFinite(p)) refuseGeometry(what, p, "not finite");
  const double largest = largestComponent(p);
  const glm::dvec3 scaled = p / largest;
  const double scaled_length = glm::length(scaled);
  if (largest * scaled_length <= kMaxPositionDistance_m) return p;
  return scaled * (kMaxPositionDistance_m / scaled_length);
}

void requireLookupMoon(const Moon& moon) {
  if (!allFinite(moon.centre_m)) refuseGeometry("moon centre", moon.centre_m, "not finite");
  if (!(std::isfinite(moon.radius_m) && moon.radius_m >= 0.0)) {
    char text[120];
    std::snprintf(text, sizeof(text), "moon radius = %g m: must be finite and >= 0 (0: no moon)", moon.radius_m);
    throwBadInput(text);
  }
}

double lookupShadowLength(double shadow_length_m) {
  if (!(std::isfinite(shadow_length_m) && shadow_length_m >= 0.0)) {
    char text[120];
    std::snprintf(text, sizeof(text), "shadow_length_m = %g: must be finite and >= 0", shadow_length_m);
    throwBadInput(text);
  }
  return shadow_length_m;
}

}  // namespace skybake

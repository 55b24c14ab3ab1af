// Kernel (data_formats/kernel/kernel_language.h): a ray in the spherical
// shell of the atmosphere, where it starts inside: a start in space is
// moved to where the ray enters, one below the ground is put on the ground
// directly above. Every lookup, on the CPU and in the shaders, the
// reference solver and the comparators start their rays here.

struct SkybakeRay {
  bool inside;          // false: the ray misses the atmosphere
  Real3 origin;         // in the atmosphere, m from the planet's centre
  Real r;               // |origin|, m
  Real mu;              // zenith cosine of the direction at origin
  Real length_m;        // to the ground or the top
  bool ends_on_ground;  // whether it ends on the ground
  Real moved_m;         // from the given start to origin
};

// The ray from `start` (m from the planet's centre) along the unit `dir`.
SKYBAKE_KERNEL SkybakeRay skybakeEnterAtmosphere(Real bottom_radius, Real top_radius, Real3 start, Real3 dir) {
  SkybakeRay ray;
  ray.inside = false;
  ray.origin = start;
  ray.r = 0.0;
  ray.mu = 0.0;
  ray.length_m = 0.0;
  ray.ends_on_ground = false;
  ray.moved_m = 0.0;
  Real r = length(start);
  if (r < bottom_radius) {
    start = r > 0.0 ? start * (bottom_radius / r) : Real3(0.0, 0.0, bottom_radius);
    r = bottom_radius;
  }
  Real rmu = dot(start, dir);
  if (r > top_radius) {
    // top^2 minus the squared distance of the ray's line from the centre,
    // taken from the line's point nearest the centre: rmu^2 - r^2 + top^2
    // cancels for a far camera (at 1e12 m rmu^2 and r^2 are 1e24, rounded
    // by 1e8 m^2 in double, an error of 14 km along a grazing ray).
    Real3 nearest = start - dir * rmu;
    Real discriminant = top_radius * top_radius - dot(nearest, nearest);
    // Entering needs the ray to point inward (rmu < 0). The distance
    // -rmu - sqrt(discriminant), which cancels for a start just above the
    // top, written as (r^2 - top^2) / (sqrt(discriminant) - rmu).
    if (discriminant < 0.0 || !(rmu < 0.0)) return ray;
    Real entry = (r - top_radius) * (r + top_radius) / (skybakeSafeSqrt(discriminant) - rmu);
    start = start + dir * entry;
    ray.moved_m = entry;
    r = top_radius;
    rmu = rmu + entry;
  }
  ray.inside = true;
  ray.origin = start;
  ray.r = r;
  ray.mu = skybakeClampCosine(rmu / r);
  ray.ends_on_ground = skybakeRayIntersectsSphere(r, ray.mu, bottom_radius);
  ray.length_m = skybakeDistanceToAtmosphereEnd(r, ray.mu, bottom_radius, top_radius, ray.ends_on_ground);
  return ray;
}

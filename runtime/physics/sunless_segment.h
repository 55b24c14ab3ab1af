// Whether a stretch of a view ray sees none of the sun's disk, known
// without visiting its quadrature nodes.
//
// A point sees none of the disk when sunDiskVisibleFraction is 0 there
// (runtime/kernel/sun_disk.glsl): its height above the horizon is at most
// the disk's half-size, mu_s + sqrt(1 - R^2 / r^2) <= -alpha R / r, with R
// the planet's radius and alpha the sun's angular radius. Written with the
// point's distance a along the direction toward the sun from the planet's
// centre (a = r mu_s) this is
//   a + alpha R <= 0  and  f = r^2 - (a + alpha R)^2 - R^2 <= 0,
// a convex region (the inside of a paraboloid about the shadow's axis, cut
// by a plane). Along a ray a is linear and f a quadratic whose leading
// coefficient 1 - nu^2 is never negative, so both are largest at a
// segment's ends: a segment whose two ends lie inside, by a margin, lies
// inside everywhere, and every node on it reads exactly 0 (the margin keeps
// the nodes' own rounding of the same test far from the ramp's edge).
// Integrators skip such stretches: at twilight most of a view ray's nodes
// lie in the planet's shadow.
#pragma once

namespace skybake {

// The margin, as a share of R^2 for f and of R for a + alpha R: 1e-9 R^2 is
// 4e4 m^2 on Earth, against a rounding of f near 1e-2 m^2, and it puts the
// nodes' height at least 5e-10 (in cosine) below the ramp, whose own
// rounding is near 1e-16. Stretches that close to the penumbra's edge are
// integrated node by node.
inline constexpr double kSunlessSegmentMargin = 1e-9;

// The ray from radius r at zenith cosine mu, the sun at zenith cosine mu_s
// making cosine nu with it, around a planet of radius bottom_radius_m, the
// sun's angular radius sun_angular_radius_rad.
class SunlessSegmentTest {
 public:
  SunlessSegmentTest(double r, double mu, double mu_s, double nu, double bottom_radius_m, double sun_angular_radius_rad)
      : r_(r),
        mu_(mu),
        mu_s_(mu_s),
        nu_(nu),
        bottom_radius_m_(bottom_radius_m),
        disk_m_(sun_angular_radius_rad * bottom_radius_m) {}

  // Whether every point at a distance in [t_start, t_end] along the ray sees
  // none of the sun's disk (false where unsure).
  bool sunless(double t_start, double t_end) const { return sunlessAt(t_start) && sunlessAt(t_end); }

 private:
  bool sunlessAt(double t) const {
    const double R = bottom_radius_m_;
    const double a_shifted = r_ * mu_s_ + t * nu_ + disk_m_;  // a + alpha R
    const double r2 = r_ * r_ + t * (t + 2.0 * r_ * mu_);
    const double f = r2 - a_shifted * a_shifted - R * R;
    return a_shifted <= -kSunlessSegmentMargin * R && f <= -kSunlessSegmentMargin * R * R;
  }

  double r_, mu_, mu_s_, nu_;
  double bottom_radius_m_;
  double disk_m_;  // alpha R
};

}  // namespace skybake

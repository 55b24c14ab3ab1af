#include "runtime/colour/ciede2000.h"

#include <algorithm>
#include <cmath>

#include "data_formats/angles.h"

namespace skybake::colour {
namespace {

// 25^7, where the chroma weights of G and R_C reach one half.
constexpr double kChromaPivot7 = 6103515625.0;

double degrees(double radians) { return radians * (180.0 / kPi); }
double cosDeg(double deg) { return std::cos(radiansFromDegrees(deg)); }
double sinDeg(double deg) { return std::sin(radiansFromDegrees(deg)); }

// Hue angle in [0, 360) degrees; 0 for a neutral colour (Sharma et al., eq. 4).
double hueDeg(double b, double a_prime) {
  if (a_prime == 0.0 && b == 0.0) return 0.0;
  const double h = degrees(std::atan2(b, a_prime));
  return h < 0.0 ? h + 360.0 : h;
}

}  // namespace

double ciede2000(const Lab& c1, const Lab& c2) {
  // Step 1: a* stretched for near-neutral colours, then C' and h'.
  const double chroma_mean = 0.5 * (std::hypot(c1.a, c1.b) + std::hypot(c2.a, c2.b));
  const double chroma_mean7 = std::pow(chroma_mean, 7.0);
  const double g = 0.5 * (1.0 - std::sqrt(chroma_mean7 / (chroma_mean7 + kChromaPivot7)));
  const double a1 = (1.0 + g) * c1.a, a2 = (1.0 + g) * c2.a;
  const double chroma1 = std::hypot(a1, c1.b), chroma2 = std::hypot(a2, c2.b);
  const double hue1 = hueDeg(c1.b, a1), hue2 = hueDeg(c2.b, a2);

  // Step 2: the differences; the hue difference the short way round.
  const double delta_l = c2.l - c1.l;
  const double delta_c = chroma2 - chroma1;
  const bool neutral = chroma1 * chroma2 == 0.0;
  double delta_h_angle = 0.0;
  if (!neutral) {
    delta_h_angle = hue2 - hue1;
    if (delta_h_angle > 180.0) delta_h_angle -= 360.0;
    if (delta_h_angle < -180.0) delta_h_angle += 360.0;
  }
  const double delta_h = 2.0 * std::sqrt(chroma1 * chroma2) * sinDeg(0.5 * delta_h_angle);

  // Step 3: the weights at the pair's mean lightness, chroma and hue.
  const double l_mean = 0.5 * (c1.l + c2.l);
  const double c_mean = 0.5 * (chroma1 + chroma2);
  double h_mean = hue1 + hue2;
  if (!neutral) {
    if (std::abs(hue1 - hue2) <= 180.0) {
      h_mean *= 0.5;
    } else {
      h_mean = h_mean < 360.0 ? 0.5 * (h_mean + 360.0) : 0.5 * (h_mean - 360.0);
    }
  }
  const double t = 1.0 - 0.17 * cosDeg(h_mean - 30.0) + 0.24 * cosDeg(2.0 * h_mean) +
                   0.32 * cosDeg(3.0 * h_mean + 6.0) - 0.20 * cosDeg(4.0 * h_mean - 63.0);
  const double delta_theta = 30.0 * std::exp(-std::pow((h_mean - 275.0) / 25.0, 2.0));
  const double c_mean7 = std::pow(c_mean, 7.0);
  const double r_c = 2.0 * std::sqrt(c_mean7 / (c_mean7 + kChromaPivot7));
  const double l_offset2 = (l_mean - 50.0) * (l_mean - 50.0);
  const double s_l = 1.0 + 0.015 * l_offset2 / std::sqrt(20.0 + l_offset2);
  const double s_c = 1.0 + 0.045 * c_mean;
  const double s_h = 1.0 + 0.015 * c_mean * t;
  const double r_t = -sinDeg(2.0 * delta_theta) * r_c;

  const double dl = delta_l / s_l, dc = delta_c / s_c, dh = delta_h / s_h;
  return std::sqrt(std::max(dl * dl + dc * dc + dh * dh + r_t * dc * dh, 0.0));
}

}  // namespace skybake::colour

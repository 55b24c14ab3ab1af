#include "baker/reference/reference_solver.h"

#include <algorithm>
#include <array>
#include <vector>

#include "baker/numerics/optical_depth_integral.h"
#include "baker/reference/lit_air_guide.h"
#include "baker/reference/log_linear_proposal.h"
#include "baker/reference/path_sampler.h"
#include "runtime/physics/atmosphere_media.h"
#include "runtime/physics/atmosphere_ray.h"
#include "runtime/physics/phase_functions.h"
#include "runtime/physics/planet_shadow.h"
#include "runtime/physics/ray_quadrature.h"
#include "runtime/physics/sun_disk.h"

namespace skybake {
namespace {

// Sub-intervals per smooth piece of the view ray for the deterministic single
// scattering: 64 x 4 Gauss nodes. A vertical piece of 60 km has 0.8 Mie scale
// heights per sub-interval (error ~1e-9); a horizontal ray of 1000 km changes
// altitude by less than that per sub-interval near its lowest point.
constexpr int kSingleScatteringSubintervals = 64;
// Bins of the proposal for vertex positions along a ray (exponential inside
// each bin, see LogLinearProposal).
constexpr int kVertexBins = 32;
// Optical depths inside the Monte Carlo part: ~1e-6 relative (see
// opticalDepthAlongRay), far below the noise they feed.
constexpr int kPathOpticalDepthSegments = 6;
// Share of the vertex proposal spread uniformly over the ray, so every point
// where light can scatter has a positive probability (unbiasedness).
constexpr double kUniformVertexShare = 0.1;
constexpr int kMaxPathVertices = 512;
// Russian roulette starts after this many scattering events (0-based), so the
// second and third orders, most of the multiple scattering, are never cut.
constexpr int kRouletteFromEvent = 2;
// The same with the guide (the sun below the horizon). Deep in twilight a
// path's throughput falls as it climbs from the shadowed air toward the
// sunlit layers while the light it can collect grows, so roulette on the
// throughput ended the paths that were about to find light and multiplied
// the few survivors: with 8192 paths the 440 nm zenith from the ground at
// sun 108 deg read half its value (the fourth to seventh orders carry half
// of that light, and few paths survived to find them), and the standard
// errors of other deep queries were 1.4 to 7 times those without roulette.
// From the ninth event on, where a few percent of the light is left,
// roulette costs no measurable noise.
constexpr int kGuidedRouletteFromEvent = 8;
// With the sun below the horizon, the share of vertices along a ray placed
// by the light that arrives there (scattering times transmittance times the
// sun's light and the once- and twice-scattered light the guide expects at
// the point: LitAirGuide). The rest follow the density proposal as in daylight, so
// every point of the ray keeps a positive density (unbiasedness) and a ray
// the guide sees no light along is sampled as by day.
constexpr double kGuidedVertexShare = 0.5;
// With the sun below the horizon, the share of next directions drawn from
// the guide's distribution of the once- and twice-scattered light arriving
// at the vertex instead of by the phase function. Deep in twilight that light
// arrives from a band a few degrees wide above the sunward horizon, a few
// thousandths of the sphere, so phase sampling alone spends nearly every
// path where no light is; the phase share keeps every direction possible.
// The same share serves the directions leaving the ground and a sky
// irradiance query's first ones, against cosine weighting there (80 %
// measured noisier in nautical twilight and no better at 108 deg).
constexpr double kGuidedDirectionShare = 0.5;

// Any unit vector perpendicular to n, and the third axis of a frame.
void frameAround(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  const glm::dvec3 helper = std::abs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  t = glm::normalize(glm::cross(helper, n));
  b = glm::cross(n, t);
}

glm::dvec3 directionAround(const glm::dvec3& axis, double cos_theta, double phi) {
  glm::dvec3 t, b;
  frameAround(axis, t, b);
  const double sin_theta = safeSqrt(1.0 - cos_theta * cos_theta);
  return glm::normalize(axis * cos_theta + t * (sin_theta * std::cos(phi)) + b * (sin_theta * std::sin(phi)));
}

class PathTracer {
 public:
  // `guide` (for a sun below the query's horizon; else null): place part of
  // the vertices along each ray by the light that arrives there
  // (sampleVertex) and draw part of the next directions from where the
  // light scattered once or twice at the vertex comes from
  // (sampleScatteringDirection).
  PathTracer(const AtmosphereParameters& a, const Moon& moon, const LitAirGuide* guide)
      : a_(a), media_(a), moon_(moon), guide_(guide) {}

  double altitude(const glm::dvec3& p) const { return glm::length(p) - a_.bottom_radius_m; }

  // Sun transmittance at p times the part of the sun disk above p's horizon
  // (as the bake counts it) and past the moon: 0 in the planet's shadow and
  // in the moon's umbra. The visible part of a disk centred below the
  // horizon grazes it.
  SpectrumD sunTransmittance(const glm::dvec3& p, const glm::dvec3& sun, int segments) const {
    const double r = std::max(glm::length(p), a_.bottom_radius_m);
    const double mu_s = clampCosine(glm::dot(p, sun) / glm::length(p));
    const double horizon_mu = tangentZenithCosine(r, a_.bottom_radius_m);
    const double visible =
        sunDiskVisibleFraction(mu_s - horizon_mu,
                               sunDiskHalfSizeAtHorizon(a_.bottom_radius_m, r, a_.sun_angular_radius_rad)) *
        moon_.visibleSunFraction(p, sun, a_.sun_angular_radius_rad);
    if (visible <= 0.0) return SpectrumD(0.0);
    return glm::exp(-integrateOpticalDepthToTop(media_, r, std::max(mu_s, horizon_mu), segments)) * visible;
  }

  // Light scattered at p toward -view_dir, from the sun, per unit length.
  SpectrumD sunScatteringSource(const glm::dvec3& p, const glm::dvec3& view_dir, const glm::dvec3& sun,
                                int segments) const {
    const double h = altitude(p);
    const double nu = clampCosine(glm::dot(view_dir, sun));
    const SpectrumD source =
        SpectrumD(a_.rayleigh_scattering) * (media_.rayleighDensity(h) * rayleighPhase(nu)) +
        SpectrumD(a_.mie_scattering) * (media_.mieDensity(h) * cornetteShanksPhase(a_.mie_phase_g, nu));
    return source * SpectrumD(a_.sun_irradiance) * sunTransmittance(p, sun, segments);
  }

  // Radiance of the Lambertian ground at g lit by the sun alone.
  SpectrumD groundSunRadiance(const glm::dvec3& g, const glm::dvec3& sun, int segments) const {
    const double mu_s = glm::dot(glm::normalize(g), sun);
    if (mu_s <= 0.0) return SpectrumD(0.0);
    return SpectrumD(a_.ground_albedo) * (mu_s / kPi) * SpectrumD(a_.sun_irradiance) *
           sunTransmittance(g, sun, segments);
  }

  // ---- single scattering along a ray, deterministic ----

  // Distances along the ray where the integrand has a kink or a jump: the
  // edges of the planet's shadow and the profiles' layer boundaries.
  std::vector<double> breakpoints(const AtmosphereRay& ray, const glm::dvec3& sun) const {
    std::vector<double> t = {0.0, ray.length};
    auto add = [&](double v) {
      if (v > 0.0 && v < ray.length) t.push_back(v);
    };
    const ShadowCrossings shadow = planetShadowCrossings(ray.origin, ray.dir, sun, a_.bottom_radius_m, ray.length);
    for (int i = 0; i < shadow.count; ++i) add(shadow.distance[i]);
    // Tangent point (lowest altitude), where altitude turns around.
    add(-ray.r * ray.mu);
    std::sort(t.begin(), t.end());
    return t;
  }

  // Single-scattered radiance along the ray (in the air, plus the sunlit
  // ground at its end if it ends there), with the segment's optical depth.
  SpectrumD singleScattering(const AtmosphereRay& ray, const glm::dvec3& sun, bool include_ground) const {
    const std::vector<double> t = breakpoints(ray, sun);
    SpectrumD depth_before(0.0);
    SpectrumD radiance(0.0);
    for (size_t p = 0; p + 1 < t.size(); ++p) {
      const double start = t[p], length = t[p + 1] - t[p];
      if (length <= 0.0) continue;
      auto extinction = [&](double s) { return media_.extinction(altitude(ray.origin + ray.dir * (start + s))); };
      const SpectrumD piece_depth = forEachOpticallyThinNodeWithIntegral<SpectrumD>(
          length, kSingleScatteringSubintervals, -ray.r * ray.mu - start, extinction, largestChannel,
          [&](double s, double w, const SpectrumD& depth) {
            const glm::dvec3 point = ray.origin + ray.dir * (start + s);
            radiance += sunScatteringSource(point, ray.dir, sun, kOpticalDepthSegmentsPerPiece) *
                        glm::exp(-(depth_before + depth)) * w;
          });
      depth_before += piece_depth;
    }
    if (include_ground && ray.ends_on_ground) {
      const glm::dvec3 g = ray.origin + ray.dir * ray.length;
      radiance += groundSunRadiance(g, sun, kOpticalDepthSegmentsPerPiece) * glm::exp(-depth_before);
    }
    return radiance;
  }

  // ---- path tracing of the higher orders ----

  struct Vertex {
    bool valid = false;
    bool ground = false;
    glm::dvec3 position;
    SpectrumD weight;  // transmittance to the vertex over its probability density
  };

  // Samples where the next scattering event on the ray happens, from one
  // uniform number u: a point in the air (density following scattering times
  // transmittance along the ray, mixed with a uniform share) or the ground at
  // its end. With the guide (the sun below the horizon), a share
  // kGuidedVertexShare follows scattering times transmittance times the
  // light expected at each point: the sun's there, if `counts_sun` (the
  // caller connects the vertex to the sun), plus the scattered light the
  // guide expects to arrive (what the vertex's next ray collects). In deep
  // twilight the shadowed air near the viewer holds nearly all the density
  // but little of the light, which grows steeply with altitude, so density
  // alone puts nearly every vertex where the light is not. Each channel's
  // part is normalized before they are summed, so blue light, which reaches
  // a shadowed point from higher and dimmer air than red, gets its share of
  // the vertices. The density is the mixture's (one-sample multiple
  // importance sampling with the balance heuristic), so the estimate stays
  // unbiased.
  Vertex sampleVertex(const AtmosphereRay& ray, bool ground_allowed, double u, const glm::dvec3& sun,
                      bool counts_sun) const {
    Vertex v;
    if (!(ray.length > 0.0)) {
      // A ray that starts on the ground pointing into it: the ground is all it meets.
      if (!(ground_allowed && ray.ends_on_ground)) return v;
      return {true, true, ray.origin, SpectrumD(1.0)};
    }
    // Scattering times transmittance (summed over channels) at the bin edges;
    // optical depth by Simpson's rule per bin, ample for a proposal.
    const double dt = ray.length / kVertexBins;
    auto extinctionAt = [&](double t) { return media_.extinction(altitude(ray.origin + ray.dir * t)); };
    auto scatteringAt = [&](double t) {
      const double h = altitude(ray.origin + ray.dir * t);
      return SpectrumD(a_.rayleigh_scattering) * media_.rayleighDensity(h) +
             SpectrumD(a_.mie_scattering) * media_.mieDensity(h);
    };
    std::array<double, kVertexBins + 1> node_value;
    std::array<SpectrumD, kVertexBins + 1> node_spectrum;
    SpectrumD depth(0.0);
    SpectrumD extinction_start = extinctionAt(0.0);
    for (int i = 0; i <= kVertexBins; ++i) {
      node_spectrum[i] = scatteringAt(i * dt) * glm::exp(-depth);
      node_value[i] = node_spectrum[i].x + node_spectrum[i].y + node_spectrum[i].z + node_spectrum[i].w;
      if (i == kVertexBins) break;
      const SpectrumD extinction_end = extinctionAt((i + 1) * dt);
      depth += (extinction_start + 4.0 * extinctionAt((i + 0.5) * dt) + extinction_end) * (dt / 6.0);
      extinction_start = extinction_end;
    }
    const LogLinearProposal<kVertexBins> proposal(ray.length, node_value);
    // The guided proposal: the same nodes times the light expected there,
    // each channel normalized over the ray.
    std::array<double, kVertexBins + 1> lit_value{};
    if (guide_) {
      SpectrumD channel_total(0.0);
      for (int i = 0; i <= kVertexBins; ++i) {
        const glm::dvec3 point = ray.origin + ray.dir * (i * dt);
        SpectrumD light = guide_->meanInscatteredRadiance(guide_->siteAt(point, sun));
        if (counts_sun) light += SpectrumD(a_.sun_irradiance) * guide_->sunTransmittance(point, sun) / (4.0 * kPi);
        node_spectrum[i] *= light;
        channel_total += node_spectrum[i];
      }
      for (int i = 0; i <= kVertexBins; ++i) {
        for (int k = 0; k < 4; ++k) {
          if (channel_total[k] > 0.0 && std::isfinite(channel_total[k]))
            lit_value[i] += node_spectrum[i][k] / channel_total[k];
        }
      }
    }
    const LogLinearProposal<kVertexBins> lit_proposal(ray.length, lit_value);
    const double lit_share = guide_ && lit_proposal.usable() ? kGuidedVertexShare : 0.0;
    double ground_weight = 0.0;
    if (ground_allowed && ray.ends_on_ground) {
      const SpectrumD w = SpectrumD(a_.ground_albedo) * glm::exp(-depth);
      ground_weight = w.x + w.y + w.z + w.w;
    }
    const double air_weight = proposal.usable() ? proposal.total() : 0.0;
    if (air_weight + ground_weight <= 0.0) return v;
    const double p_ground = ground_weight / (air_weight + ground_weight);
    if (u < p_ground) {
      v.valid = true;
      v.ground = true;
      v.position = ray.origin + ray.dir * ray.length;
      v.weight =
          glm::exp(-integrateOpticalDepthAlongRay(media_, ray.r, ray.mu, ray.length, kPathOpticalDepthSegments)) /
          p_ground;
      return v;
    }
    // In the air: uniformly or by the proposal, the rest of u choosing where.
    const double uniform_share = proposal.usable() ? kUniformVertexShare : 1.0;
    const double u_air = std::min((u - p_ground) / (1.0 - p_ground), std::nextafter(1.0, 0.0));
    double t, pdf;
    if (lit_share == 0.0) {
      t = u_air < uniform_share ? u_air / uniform_share * ray.length
                                : proposal.sample((u_air - uniform_share) / (1.0 - uniform_share));
      pdf = (1.0 - p_ground) * ((1.0 - uniform_share) * proposal.pdf(t) + uniform_share / ray.length);
    } else {
      // The lowest part of u picks the guided proposal, the rest the
      // daylight mixture, each rescaled to [0, 1).
      if (u_air < lit_share) {
        t = lit_proposal.sample(u_air / lit_share);
      } else {
        const double u_day = (u_air - lit_share) / (1.0 - lit_share);
        t = u_day < uniform_share ? u_day / uniform_share * ray.length
                                  : proposal.sample((u_day - uniform_share) / (1.0 - uniform_share));
      }
      pdf = (1.0 - p_ground) *
            (lit_share * lit_proposal.pdf(t) +
             (1.0 - lit_share) * ((1.0 - uniform_share) * proposal.pdf(t) + uniform_share / ray.length));
    }
    v.valid = true;
    v.position = ray.origin + ray.dir * t;
    v.weight = glm::exp(-integrateOpticalDepthAlongRay(media_, ray.r, ray.mu, t, kPathOpticalDepthSegments)) / pdf;
    return v;
  }

  // Samples, from two uniform numbers, a direction over the sky seen from
  // `point` (the hemisphere above `up`, its vertical), for light that
  // reaches a horizontal surface there: cosine-weighted by day; with the
  // guide (the sun below the horizon), a share kGuidedDirectionShare drawn
  // from where the scattered light arriving there comes from, since in deep
  // twilight a band a few degrees above the sunward horizon lights the
  // ground and cosine weighting puts few directions there. Returns the
  // direction and, in `cosine_over_pi_pdf`, cos/pi over the direction's
  // density (1 for cosine weighting; 0 for a guide direction below the
  // plane, which carries no light to the surface).
  glm::dvec3 sampleHemisphereDirection(const glm::dvec3& point, const glm::dvec3& up, const glm::dvec3& sun,
                                       double u_cos, double u_phi, double& cosine_over_pi_pdf) const {
    LitAirGuide::Site site;
    const double lit_share =
        guide_ && LitAirGuide::proposesDirections(site = guide_->siteAt(point, sun)) ? kGuidedDirectionShare : 0.0;
    glm::dvec3 dir;
    if (u_cos < lit_share) {
      dir = guide_->sampleDirection(site, u_cos / lit_share, u_phi);
    } else {
      if (lit_share > 0.0) u_cos = (u_cos - lit_share) / (1.0 - lit_share);
      dir = directionAround(up, std::sqrt(u_cos), 2.0 * kPi * u_phi);
    }
    if (lit_share == 0.0) {
      cosine_over_pi_pdf = 1.0;  // cosine-weighted: cos/pi over a density of cos/pi
      return dir;
    }
    const double cosine = glm::dot(dir, up);
    if (!(cosine > 0.0)) {
      cosine_over_pi_pdf = 0.0;
      return dir;
    }
    const double pdf = lit_share * guide_->directionPdf(site, dir) + (1.0 - lit_share) * cosine / kPi;
    cosine_over_pi_pdf = cosine / kPi / pdf;
    return dir;
  }

  // Samples, from two uniform numbers, the direction light came from before
  // scattering at a point in the air toward -dir, and returns the
  // phase-weighted scattering over the direction's density. With `site`
  // (the guide's, where it proposes directions), a share
  // kGuidedDirectionShare of the directions is drawn from where the
  // scattered light arriving there comes from; the density is the
  // mixture's, so the estimate stays unbiased.
  glm::dvec3 sampleScatteringDirection(const glm::dvec3& point, const glm::dvec3& dir, double u_cos, double u_phi,
                                       const LitAirGuide::Site* site, SpectrumD& weight) const {
    const double h = altitude(point);
    const SpectrumD rayleigh = SpectrumD(a_.rayleigh_scattering) * media_.rayleighDensity(h);
    const SpectrumD mie = SpectrumD(a_.mie_scattering) * media_.mieDensity(h);
    const double rayleigh_sum = rayleigh.x + rayleigh.y + rayleigh.z + rayleigh.w;
    const double mie_sum = mie.x + mie.y + mie.z + mie.w;
    const double g = a_.mie_phase_g;
    // Uniform directions for Rayleigh's gentle lobe, Henyey-Greenstein for
    // Mie's forward peak, mixed by their shares (each at least 10 % when
    // present, so neither lobe is ever left unsampled). One number picks the
    // lobe and, rescaled, the cosine within it.
    double p_uniform = rayleigh_sum + mie_sum > 0.0 ? rayleigh_sum / (rayleigh_sum + mie_sum) : 1.0;
    if (rayleigh_sum > 0.0 && mie_sum > 0.0) p_uniform = std::clamp(p_uniform, 0.1, 0.9);
    if (g == 0.0) p_uniform = 1.0;
    const double lit_share = site ? kGuidedDirectionShare : 0.0;
    glm::dvec3 incoming;
    if (u_cos < lit_share) {
      incoming = guide_->sampleDirection(*site, u_cos / lit_share, u_phi);
    } else {
      if (lit_share > 0.0) u_cos = (u_cos - lit_share) / (1.0 - lit_share);
      double cos_theta;
      if (u_cos < p_uniform) {
        cos_theta = 2.0 * (u_cos / p_uniform) - 1.0;
      } else {
        const double x = (u_cos - p_uniform) / (1.0 - p_uniform);
        const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * x);
        cos_theta = std::clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
      }
      incoming = directionAround(dir, cos_theta, 2.0 * kPi * u_phi);
    }
    const double c = clampCosine(glm::dot(incoming, dir));
    double pdf = p_uniform / (4.0 * kPi) + (1.0 - p_uniform) * henyeyGreensteinPhase(g, c);
    if (lit_share > 0.0) pdf = lit_share * guide_->directionPdf(*site, incoming) + (1.0 - lit_share) * pdf;
    weight = (rayleigh * rayleighPhase(c) + mie * cornetteShanksPhase(g, c)) / pdf;
    return incoming;
  }

  // Radiance arriving along -dir at `start` from scattering events along the
  // ray (start, dir) and beyond, each connected to the sun. With
  // `skip_first_sun`, the first event's own sun connection is left out (the
  // caller has it already, deterministically).
  SpectrumD tracePath(AtmosphereRay ray, const glm::dvec3& sun, bool ground_allowed, bool skip_first_sun,
                      PathSampler& rng) const {
    SpectrumD throughput(1.0);
    double first_event_peak = 0.0;
    SpectrumD total(0.0);
    for (int depth = 0; depth < kMaxPathVertices && ray.inside; ++depth) {
      // The first vertex's own sun connection is the caller's, if it skips it.
      const Vertex v = sampleVertex(ray, ground_allowed, rng.next(), sun, depth > 0 || !skip_first_sun);
      if (!v.valid) break;
      throughput *= v.weight;
      glm::dvec3 next_dir;
      if (v.ground) {
        if (depth > 0 || !skip_first_sun)
          total += throughput * groundSunRadiance(v.position, sun, kPathOpticalDepthSegments);
        const double u_cos = rng.next(), u_phi = rng.next();
        double reflected_share;
        next_dir =
            sampleHemisphereDirection(v.position, glm::normalize(v.position), sun, u_cos, u_phi, reflected_share);
        if (!(reflected_share > 0.0)) break;                          // a guide direction below the ground: no light
        throughput *= SpectrumD(a_.ground_albedo) * reflected_share;  // (albedo/pi) cos / pdf
      } else {
        if (depth > 0 || !skip_first_sun)
          total += throughput * sunScatteringSource(v.position, ray.dir, sun, kPathOpticalDepthSegments);
        SpectrumD phase_weight;
        const double u_cos = rng.next(), u_phi = rng.next();
        // Aim part of the directions where the scattered light comes from.
        LitAirGuide::Site site;
        const bool aim = guide_ && LitAirGuide::proposesDirections(site = guide_->siteAt(v.position, sun));
        next_dir = sampleScatteringDirection(v.position, ray.dir, u_cos, u_phi, aim ? &site : nullptr, phase_weight);
        throughput *= phase_weight;
      }
      // Russian roulette from the third event on (the ninth with the guide,
      // see kGuidedRouletteFromEvent): unbiased, bounds path length. The
      // survival probability is the throughput relative to the
      // one after the first event, i.e. the share of light that each later
      // ray scatters back (<= 1, falling with the order); the first event's
      // own factor only says how much the view ray scatters and, in thin air,
      // is so small that rouletting on it would kill nearly every path and
      // multiply the noise.
      const double peak = std::max({throughput.x, throughput.y, throughput.z, throughput.w});
      if (depth == 0) first_event_peak = peak;
      if (depth >= (guide_ ? kGuidedRouletteFromEvent : kRouletteFromEvent)) {
        const double survive = first_event_peak > 0.0 ? std::min(1.0, peak / first_event_peak) : 0.0;
        if (!(survive > 0.0) || rng.nextIndependent() >= survive) break;
        throughput /= survive;
      }
      ray = atmosphereRay(a_.bottom_radius_m, a_.top_radius_m,
                          v.position + (v.ground ? glm::normalize(v.position) * 1e-3 : glm::dvec3(0.0)), next_dir, 0.0);
      ground_allowed = true;
    }
    return total;
  }

  const AtmosphereParameters& a_;
  AtmosphereMedia media_;
  Moon moon_;                 // none: the sun is hidden by the planet alone
  const LitAirGuide* guide_;  // null: daylight sampling
};

// Estimates the mean of path(sampler) from `paths` paths split into
// independently shifted replicates (see PathSampler): the mean of the
// replicate means and its standard error from their spread.
template <typename PathFn>
ReferenceEstimate estimateOverReplicates(int paths, uint64_t seed, PathFn&& path) {
  if (paths <= 0) return {SpectrumD(0.0), SpectrumD(0.0)};
  const int replicates = std::min(kReplicates, paths);
  const int per_replicate = paths / replicates;
  PathSampler sampler(seed);
  SpectrumD sum(0.0), sum_squares(0.0);
  for (int r = 0; r < replicates; ++r) {
    SpectrumD replicate_sum(0.0);
    for (int i = 0; i < per_replicate; ++i) {
      sampler.startPath(r, static_cast<uint64_t>(i));
      replicate_sum += path(sampler);
    }
    const SpectrumD mean = replicate_sum / static_cast<double>(per_replicate);
    sum += mean;
    sum_squares += mean * mean;
  }
  const SpectrumD mean = sum / static_cast<double>(replicates);
  const SpectrumD variance = glm::max(sum_squares / static_cast<double>(replicates) - mean * mean, SpectrumD(0.0));
  return {mean, glm::sqrt(variance / static_cast<double>(std::max(replicates - 1, 1)))};
}

}  // namespace

ReferenceSolver::ReferenceSolver(const AtmosphereParameters& atmosphere, VertexSampling sampling,
                                 std::shared_ptr<LitAirGuide> guide)
    : a_(atmosphere),
      sampling_(sampling),
      guide_(guide ? std::move(guide) : std::make_shared<LitAirGuide>(atmosphere)) {}

const LitAirGuide* ReferenceSolver::guideFor(double camera_sun_zenith_cosine) const {
  return sampling_ == VertexSampling::TowardLitAirBelowHorizon && referenceSamplesTowardLitAir(camera_sun_zenith_cosine)
             ? guide_.get()
             : nullptr;
}

namespace {

// The radiance estimate with each contribution through `map` (a linear map
// of the channels, or the identity).
template <typename MapFn>
ReferenceEstimate radianceThrough(const AtmosphereParameters& a, const LitAirGuide* guide, const ReferenceRay& query,
                                  int paths, uint64_t seed, const Moon& moon, MapFn&& map) {
  const PathTracer tracer(a, moon, guide);
  const AtmosphereRay ray =
      atmosphereRay(a.bottom_radius_m, a.top_radius_m, query.camera, query.view, query.distance_m);
  if (!ray.inside) return {SpectrumD(0.0), SpectrumD(0.0)};
  const bool ground_end = ray.ends_on_ground && !(query.distance_m > 0.0);
  const SpectrumD single = map(tracer.singleScattering(ray, query.sun, ground_end));
  ReferenceEstimate e = estimateOverReplicates(paths, seed, [&](PathSampler& sampler) {
    return map(tracer.tracePath(ray, query.sun, ground_end, true, sampler));
  });
  e.value += single;
  return e;
}

// The vertical at `point` (+z at the planet's centre).
glm::dvec3 upAt(const glm::dvec3& point) {
  const double length = glm::length(point);
  return length > 0.0 ? point / length : glm::dvec3(0.0, 0.0, 1.0);
}

template <typename MapFn>
ReferenceEstimate skyIrradianceThrough(const AtmosphereParameters& a, const LitAirGuide* guide, const glm::dvec3& point,
                                       const glm::dvec3& sun, int paths, uint64_t seed, const Moon& moon, MapFn&& map) {
  const PathTracer tracer(a, moon, guide);
  const double length = glm::length(point);
  const glm::dvec3 up = upAt(point);
  const glm::dvec3 start = up * std::clamp(length, a.bottom_radius_m, a.top_radius_m);
  return estimateOverReplicates(paths, seed, [&](PathSampler& sampler) {
    // Irradiance = pi x the mean over directions of radiance x cos/(pi pdf).
    const double u_cos = sampler.next(), u_phi = sampler.next();
    double cosine_over_pi_pdf;
    const glm::dvec3 dir = tracer.sampleHemisphereDirection(start, up, sun, u_cos, u_phi, cosine_over_pi_pdf);
    if (!(cosine_over_pi_pdf > 0.0)) return SpectrumD(0.0);
    const AtmosphereRay ray = atmosphereRay(a.bottom_radius_m, a.top_radius_m, start, dir, 0.0);
    return ray.inside ? map(tracer.tracePath(ray, sun, true, false, sampler) * (kPi * cosine_over_pi_pdf))
                      : SpectrumD(0.0);
  });
}

SpectrumD unmapped(const SpectrumD& s) { return s; }

}  // namespace

ReferenceEstimate ReferenceSolver::radiance(const ReferenceRay& query, int paths, uint64_t seed,
                                            const Moon& moon) const {
  return radianceThrough(a_, guideFor(glm::dot(glm::normalize(query.camera), query.sun)), query, paths, seed, moon,
                         unmapped);
}

ReferenceEstimate ReferenceSolver::mappedRadiance(const ReferenceRay& query, int paths, uint64_t seed,
                                                  const glm::dmat4& lanes_to_output, const Moon& moon) const {
  return radianceThrough(a_, guideFor(glm::dot(glm::normalize(query.camera), query.sun)), query, paths, seed, moon,
                         [&](const SpectrumD& s) { return lanes_to_output * s; });
}

SpectrumD ReferenceSolver::transmittance(const ReferenceRay& query) const {
  const AtmosphereRay ray =
      atmosphereRay(a_.bottom_radius_m, a_.top_radius_m, query.camera, query.view, query.distance_m);
  if (!ray.inside) return SpectrumD(1.0);
  return glm::exp(-integrateOpticalDepthAlongRay(AtmosphereMedia(a_), ray.r, ray.mu, ray.length));
}

ReferenceEstimate ReferenceSolver::skyIrradiance(const glm::dvec3& point, const glm::dvec3& sun, int paths,
                                                 uint64_t seed, const Moon& moon) const {
  return skyIrradianceThrough(a_, guideFor(glm::dot(upAt(point), sun)), point, sun, paths, seed, moon, unmapped);
}

ReferenceEstimate ReferenceSolver::mappedSkyIrradiance(const glm::dvec3& point, const glm::dvec3& sun, int paths,
                                                       uint64_t seed, const glm::dmat4& lanes_to_output,
                                                       const Moon& moon) const {
  return skyIrradianceThrough(a_, guideFor(glm::dot(upAt(point), sun)), point, sun, paths, seed, moon,
                              [&](const SpectrumD& s) { return lanes_to_output * s; });
}

}  // namespace skybake

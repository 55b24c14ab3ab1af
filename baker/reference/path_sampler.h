// Random numbers for the reference's paths: randomized quasi-Monte Carlo.
//
// The first kQuasiRandomDimensions numbers of a path (where the first few
// scattering events are chosen: the orders that carry most of the multiple
// scattering) come from a Halton point set shifted modulo 1 by a random
// vector (a Cranley-Patterson rotation); the rest, and Russian roulette, from
// a pseudo-random stream. Each of kReplicates independent shifts gives an
// unbiased estimate; their spread gives an honest standard error, while the
// stratified points make each replicate far less noisy than independent
// paths for the smooth integrals of the second and third orders.
#pragma once

#include <array>
#include <cstdint>

namespace skybake {

// Uniform double in [0, 1) from 53 random bits: the same on every platform.
class SplitMix {
 public:
  explicit SplitMix(uint64_t seed) : state_(seed) {}
  double next() {
    // splitmix64: small, fast, statistically sound for this use.
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }

 private:
  uint64_t state_;
};

// Independent shifted point sets a query's paths are split into; 16 gives the
// standard error to about +-18 % (chi distribution with 15 degrees of freedom).
inline constexpr int kReplicates = 16;
// Halton bases for the quasi-random dimensions: three per scattering event
// (where on the ray, two for the new direction), so events one to three.
inline constexpr int kQuasiRandomDimensions = 9;
inline constexpr std::array<uint32_t, kQuasiRandomDimensions> kHaltonBase = {2, 3, 5, 7, 11, 13, 17, 19, 23};

// The radical inverse of `index` in `base`: the index's digits mirrored
// about the radix point.
inline double radicalInverse(uint64_t index, uint32_t base) {
  const double inverse_base = 1.0 / base;
  double scale = inverse_base, value = 0.0;
  while (index > 0) {
    value += static_cast<double>(index % base) * scale;
    index /= base;
    scale *= inverse_base;
  }
  return value;
}

class PathSampler {
 public:
  explicit PathSampler(uint64_t seed) : pseudo_(seed) {
    for (auto& shift : shifts_)
      for (double& s : shift) s = pseudo_.next();
  }

  // Starts path `index` of replicate `replicate`.
  void startPath(int replicate, uint64_t index) {
    replicate_ = replicate;
    index_ = index;
    dimension_ = 0;
  }

  // The next number of the current path.
  double next() {
    if (dimension_ >= kQuasiRandomDimensions) return pseudo_.next();
    const double shifted = radicalInverse(index_, kHaltonBase[dimension_]) + shifts_[replicate_][dimension_];
    ++dimension_;
    return shifted >= 1.0 ? shifted - 1.0 : shifted;
  }

  // A number outside the quasi-random dimensions (Russian roulette, whose
  // decisions must not shift the dimensions of later events).
  double nextIndependent() { return pseudo_.next(); }

 private:
  SplitMix pseudo_;
  std::array<std::array<double, kQuasiRandomDimensions>, kReplicates> shifts_{};
  int replicate_ = 0;
  uint64_t index_ = 0;
  int dimension_ = 0;
};

}  // namespace skybake

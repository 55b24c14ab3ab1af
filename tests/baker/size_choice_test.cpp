// --target-error picks the cheapest swept size that meets the target.
#include <gtest/gtest.h>

#include "baker/cli/size_choice.h"

namespace skybake {
namespace {

TEST(SizeChoice, PicksTheCheapestSweptSizeThatMeetsTheTarget) {
  // The sweep's worst of day and low sun: 1.31, 0.75, 0.35 %.
  const std::optional<SizeChoice> one = chooseSizesForError(0.5);
  ASSERT_TRUE(one);
  EXPECT_EQ(one->scale, 1.0);
  EXPECT_EQ(one->predicted_percent, 0.35);
  EXPECT_EQ(chooseSizesForError(0.35)->scale, 1.0);  // a target equal to a swept figure meets it
  EXPECT_EQ(chooseSizesForError(1.0)->scale, 0.75);
  EXPECT_EQ(chooseSizesForError(1.5)->scale, 0.5);
  EXPECT_EQ(chooseSizesForError(50.0)->scale, 0.5);
  EXPECT_FALSE(chooseSizesForError(0.3));
  // Cheaper sizes never come with a smaller swept error (else the choice
  // would not be the cheapest).
  const std::vector<SweepPoint>& sweep = earthSweep();
  for (size_t i = 1; i < sweep.size(); ++i) {
    EXPECT_GT(sweep[i].scale, sweep[i - 1].scale);
    EXPECT_LT(worstPercent(sweep[i]), worstPercent(sweep[i - 1]));
  }
}

TEST(SizeChoice, ScalesEveryDefaultSizeAsTheSweepDoes) {
  const TextureSizes defaults;
  const TextureSizes one = scaledDefaultSizes(1.0);
  EXPECT_EQ(one.scattering_r, defaults.scattering_r);
  EXPECT_EQ(one.scattering_mu, defaults.scattering_mu);
  EXPECT_EQ(one.transmittance_mu, defaults.transmittance_mu);
  // scripts/sweep/make_config.py at 0.75: 32 x 128 x 41 x 16 -> 24 x 96 x 31 x 12.
  const TextureSizes s = scaledDefaultSizes(0.75);
  EXPECT_EQ(s.scattering_r, 24);
  EXPECT_EQ(s.scattering_mu, 96);
  EXPECT_EQ(s.scattering_mu_s, 31);
  EXPECT_EQ(s.scattering_nu, 12);
  EXPECT_EQ(s.irradiance_r, 12);
  // Tiny scales keep at least 2 texels per axis and an even mu of at least 4.
  const TextureSizes tiny = scaledDefaultSizes(0.01);
  EXPECT_EQ(tiny.scattering_r, 2);
  EXPECT_EQ(tiny.scattering_mu, 4);
}

}  // namespace
}  // namespace skybake

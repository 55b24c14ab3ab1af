// The sun disk in an image, integrated over each pixel's area: a pixel the
// disk covers in part gets the disk's radiance, seen through the air along
// each part, times the fraction of the pixel's solid angle that part covers.
// So an image's integral of radiance over solid angle holds the sun's whole
// irradiance at any size, where sampling the disk at pixel centres would
// miss it or count it whole in pixels larger than the sun.
#pragma once

#include "baker/render/sky_image.h"

namespace skybake {

// Adds the sun disk of `view` (the bake's sun: its angular radius and
// radiance, Sky::solarRadiance) to `image`, as renderSkyRadiance rendered
// it; nothing when view.sun_disk is false or the bake's sun is a point. A
// view's moon hides the part of the disk behind it.
void addSunDisk(const Sky& sky, const SkyView& view, SpectralImage& image);

}  // namespace skybake

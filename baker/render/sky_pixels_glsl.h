// baker/render/sky_pixels.glsl, compiled in: the fragment stage that gives
// each pixel of a sky image its radiance (`skybake render --backend gl`,
// the browser viewer). Goes after the GLSL library.
#pragma once

#include <span>
#include <string_view>

#include "baker/render/embedded_text.h"

namespace skybake {

std::span<const EmbeddedText> skyPixelsGlslFiles();  // generated: the one file
inline std::string_view skyPixelsGlsl() { return skyPixelsGlslFiles()[0].text; }

}  // namespace skybake

// The viewer's page, compiled in (baker/CMakeLists.txt): index.html,
// viewer.js, viewer.css from baker/view/page/, the web export's loader
// runtime/glsl/web/skybake_web.js and the sky image's fragment stage
// baker/render/sky_pixels.glsl, each served under its own name.
#pragma once

#include <span>

#include "baker/render/embedded_text.h"

namespace skybake {

std::span<const EmbeddedText> viewerPageFiles();  // generated

}  // namespace skybake

// Text files compiled into the program (the build's
// skybake_embed_text_files, baker/CMakeLists.txt): shaders and the
// viewer's page, so that an installed skybake needs no files beside it.
#pragma once

#include <string_view>

namespace skybake {

struct EmbeddedText {
  std::string_view name;  // the source file's name, without its folder
  std::string_view text;
};

}  // namespace skybake

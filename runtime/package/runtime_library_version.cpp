#include "runtime/version.h"

namespace skybake {

const char* runtimeLibraryVersion() { return SKYBAKE_VERSION; }

}  // namespace skybake

// The version of the skybake runtime library a program runs with (the shared
// skybake::runtime of the installed package). A program can compare it with
// the version its headers came with, SKYBAKE_VERSION_STRING in the package.
#pragma once

namespace skybake {

// "MAJOR.MINOR.PATCH", e.g. "0.1.0".
const char* runtimeLibraryVersion();

}  // namespace skybake

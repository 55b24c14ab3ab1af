// Pi and the conversions between degrees and radians: the one definition of
// each that every layer uses (degrees appear only in configs and flags that
// say so; physics works in radians and cosines).
#pragma once

namespace skybake {

inline constexpr double kPi = 3.14159265358979323846;

constexpr double radiansFromDegrees(double degrees) { return degrees * (kPi / 180.0); }
constexpr double degreesFromRadians(double radians) { return radians * (180.0 / kPi); }

}  // namespace skybake

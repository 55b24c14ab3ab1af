// How the divisor that multiple scattering is stored divided by weighs its
// peak (runtime/physics/multiple_scattering_phase.h). The stored values are
// the radiance over that divisor, so a reader must use the weight the bake
// used: the file's format version says which (multipleShapeWeightOfFormatVersion).
#pragma once

namespace skybake {

enum class MultipleShapeWeight {
  // w = m_local m_column^order (format versions 2 to 7).
  ColumnShare,
  // The same times max(1 - tau_s, 0), tau_s the vertical scattering optical
  // depth (format version 8 on; what new bakes use).
  ThinnedByScatteringDepth,
};

}  // namespace skybake

// The CIEDE2000 colour difference between two CIELAB colours (CIE 142-2001),
// as written out step by step in G. Sharma, W. Wu and E. N. Dalal, "The
// CIEDE2000 color-difference formula: implementation notes, supplementary
// test data, and mathematical observations", Color Research & Application
// 30(1), 21-30 (2005), with the parametric factors kL = kC = kH = 1.
// About 1 is a just noticeable difference between two patches side by side.
#pragma once

#include "runtime/colour/cielab.h"

namespace skybake::colour {

double ciede2000(const Lab& first, const Lab& second);

}  // namespace skybake::colour

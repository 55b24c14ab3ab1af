// BakeContents <-> the typed header attributes that state it (FORMAT.md,
// "Header attributes"). Shared by the writer and the reader so that the two
// cannot disagree on a name, a type or a layout.
#pragma once

#include <functional>
#include <string>

#include <OpenEXR/ImfHeader.h>

#include "data_formats/bake_file/bake_file.h"

namespace skybake {

// Adds every attribute that states `contents` to `header`.
void insertContentsAttributes(const BakeContents& contents, Imf::Header& header);

// Reads them back (format version 3 or later: `format_version` says whether
// skybake:channels is there; version 3's channels are wavelengths). `fail` is
// called with a description of the first missing, mistyped or malformed
// attribute and must not return. The result is not yet checked for physical
// sense (validateContents).
BakeContents readContentsAttributes(const Imf::Header& header, int format_version,
                                    const std::function<void(const std::string&)>& fail);

// Refuses contents that no bake writes: the atmosphere and sizes as the
// config check judges them, and a domain outside the atmosphere or with its
// ends reversed. `source` names the file.
void validateContents(const BakeContents& contents, const std::string& source);

}  // namespace skybake

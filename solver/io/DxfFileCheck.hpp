#pragma once
/// \file DxfFileCheck.hpp
/// What must hold of a DXF file before dxflib reads it (io/DxfImport.hpp). dxflib trusts the
/// file: it allocates what a count declares (a 104-byte file declaring 10⁸ vertices takes 3 GB),
/// reads a coordinate "abc", "NaN" or "" as 0 without a word, and takes a binary or UTF-16 DXF
/// for an empty drawing. Read here first, line by line, the file is refused with the line and,
/// where known, the entity and layer when
///   - it is a binary DXF, UTF-16 text or holds NUL bytes, or a line is longer than dxflib reads;
///   - a group code is not a whole number (not an ASCII DXF, or damaged);
///   - a number of an entity that is imported (LWPOLYLINE, POLYLINE, VERTEX, LINE, POINT) is not
///     a finite number in decimal notation;
///   - a count that dxflib allocates by (LWPOLYLINE vertices; SPLINE knots, control and fit
///     points; LEADER vertices) exceeds what the entity holds, or an LWPOLYLINE's differs from it
///     (dxflib would then drop or overwrite vertices).

#include "model/Diagnostic.hpp"

#include <string>
#include <vector>

namespace mcdda {

/// The problems of the DXF file at `path` (errors; empty when dxflib may read it).
std::vector<Diagnostic> check_dxf_file(const std::string& path);

}  // namespace mcdda

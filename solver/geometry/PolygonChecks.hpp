#pragma once
/// \file PolygonChecks.hpp
/// Exact checks of region rings: simple (no self-intersection), non-zero area, holes strictly
/// inside their boundary and apart from each other.

#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <vector>

namespace mcdda {

/// Appends a diagnostic per bad ring of `model.regions`. Uses exact predicates (CGAL).
void check_region_rings(const Model& model, std::vector<Diagnostic>& diagnostics);

/// Signed area of a ring (m²), positive when counter-clockwise.
double signed_area(const Ring& ring);

/// True when `p` lies strictly inside region `r` (inside the boundary, outside every hole).
bool region_contains(const Region& r, Point2 p);

}  // namespace mcdda

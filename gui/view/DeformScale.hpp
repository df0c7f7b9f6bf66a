#pragma once
/// \file DeformScale.hpp
/// The automatic deformation scale of result pictures. Drawing the largest displacement as 5 %
/// of the model's size (the visual rule) turned small elements next to large displacements
/// inside out (×82, "20 element(s) drawn inside out" on a tunnel). The scale is therefore also
/// capped at half the smallest factor at which any element's area reaches zero. Plain data, no
/// VTK.

#include "model/Model.hpp"

#include <array>
#include <vector>

namespace mcdda::view {

/// The smallest factor s > 0 at which a triangle of `triangles` (indices into `points`), drawn
/// at points + s · displacement, has zero area; +∞ when no factor does (e.g. a translation).
/// Degenerate triangles are skipped.
double largest_untangled_scale(const std::vector<Point2>& points, const std::vector<Point2>& displacement,
                               const std::vector<std::array<int, 3>>& triangles);

/// The automatic scale: the largest displacement drawn as 5 % of `model_size`, but at most half
/// of `untangled` (largest_untangled_scale), so no element is drawn inverted. 0 when nothing moved.
double automatic_deform_scale(double model_size, double max_displacement, double untangled);

}  // namespace mcdda::view

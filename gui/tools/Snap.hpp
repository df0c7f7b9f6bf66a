#pragma once
/// \file Snap.hpp
/// Where a drawn point lands: on an existing vertex within a tolerance, else on the grid.

#include "model/Model.hpp"

#include <vector>

namespace mcdda::gui {

struct SnapOptions {
    bool grid = true;
    double spacing = 0.5;          ///< grid spacing (m); ≤ 0 = no grid
    double vertex_tolerance = 0.0; ///< distance (m) within which a vertex attracts
};

/// `p` moved to the nearest region vertex of `model` or of `extra` within the tolerance, else
/// to the nearest grid node (when the grid is on), else unchanged.
Point2 snap_point(const Point2& p, const Model& model, const std::vector<Point2>& extra, const SnapOptions& options);

}  // namespace mcdda::gui

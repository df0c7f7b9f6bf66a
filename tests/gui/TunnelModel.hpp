#pragma once
// A small model built in code for the rendering tests: a 10 m square of one material with a
// circular opening (radius 2 m, 32 vertices) at its centre, one joint across the whole square
// through the opening, a fixed point, a roller, a point load, an edge pressure and a
// measurement point.

#include "Preprocess.hpp"

namespace mcdda::guitest {

inline constexpr double hole_radius = 2.0;
inline constexpr Point2 hole_centre{5.0, 5.0};

/// The joint runs along y = joint_y0 + joint_slope · x.
inline constexpr double joint_y0 = 1.5;
inline constexpr double joint_slope = 0.7;

Model tunnel_model();

/// Points well inside the rock, away from the joint, the opening, symbols and labels.
std::vector<Point2> rock_samples();
/// Points inside the opening, away from the joint.
std::vector<Point2> opening_samples();

}  // namespace mcdda::guitest

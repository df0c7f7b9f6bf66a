#pragma once
/// \file Symbols.hpp
/// Engineering symbols for supports, loads and measurement points as plain shapes (no VTK), so
/// the scene and its legend draw the same figures and tests can check them without rendering.
/// `size` is the symbol size from symbol_size() (m); in the legend it is in pixels.

#include "view/SceneGeometry.hpp"

namespace mcdda::view {

/// An arrow whose head ends exactly at `tip`: a shaft quad and a head triangle.
Shapes arrow(Point2 tail, Point2 tip, double head_length, double head_width, double shaft_width);

/// A pin support (both directions fixed): filled triangle with its apex at `at`, opening along
/// the unit vector `outward`, standing on a hatched ground line.
Shapes fixed_point_symbol(Point2 at, Point2 outward, double size);

/// A roller bearing: hollow triangle with its apex at `at` whose axis is the fixed direction
/// `outward` (unit), on two wheels and a ground line.
Shapes roller_symbol(Point2 at, Point2 outward, double size);

/// A small filled diamond centred on `at`.
Shapes measurement_symbol(Point2 at, double size);

/// The water-table symbol: an inverted triangle ▽ standing with its apex on the water level at
/// `at`, and two short dashes under the level, the lower one shorter.
Shapes water_table_symbol(Point2 at, double size);

/// The piezometric line of `water` across [xmin, xmax], held level beyond its end points as the
/// solver holds it (and reaching them where they lie outside), with water_table_symbol() on the
/// line at `symbol_x`. Empty when the ground is dry.
Shapes water_table_shapes(const Water& water, double xmin, double xmax, double symbol_x, double size);

/// A dashpot (viscous damper) standing on the boundary at `at` and reaching out along the unit
/// vector `outward`: a rod to a piston inside a cylinder open towards the boundary, and the
/// cylinder's rod to a hatched ground line.
Shapes dashpot_symbol(Point2 at, Point2 outward, double size);

/// A dashed line along [from, to] with dashpots spread along it on the side away from the rock:
/// an absorbing (Lysmer–Kuhlemeyer) boundary. With `input` an arrow into the rock beside every
/// dashpot: the compliant base, where the earthquake enters.
Shapes dashpot_line_shapes(const Model& model, Point2 from, Point2 to, double size, bool input = false);
/// Every absorbing boundary of `model`.
Shapes absorbing_boundary_shapes(const Model& model, double size);
/// The compliant base of `model` (none unless its base motion is compliant).
Shapes compliant_base_shapes(const Model& model, double size);

/// Pin symbols at every fixed point, drawn on the side away from the rock.
Shapes fixed_point_shapes(const Model& model, double size);
/// The roller lines and roller markers spread along them, one marker per fixed direction.
Shapes roller_shapes(const Model& model, double size);
/// Arrows ending at the loaded points, in the force direction; length grows with |force|.
Shapes point_load_shapes(const Model& model, double size);
/// Rows of arrows standing outside the loaded edges; positive pressures point into the rock,
/// negative ones (suction) away from it.
Shapes edge_pressure_shapes(const Model& model, double size);
/// Diamonds at the measurement points.
Shapes measurement_shapes(const Model& model, double size);

}  // namespace mcdda::view

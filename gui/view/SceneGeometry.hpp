#pragma once
/// \file SceneGeometry.hpp
/// Plain 2-D geometry the model pictures need (no VTK): line work and fills as point lists,
/// boxes, and "which side is rock" questions answered against the model's regions.

#include "Preprocess.hpp"

#include <limits>
#include <vector>

namespace mcdda::view {

/// Line work and filled shapes in model coordinates (m) — or in pixels for the legend.
/// Fills must be convex (triangles, quads, discs): the renderer does not triangulate them.
struct Shapes {
    std::vector<std::vector<Point2>> lines;  ///< open polylines (repeat the first point to close)
    std::vector<std::vector<Point2>> fills;  ///< convex polygons, any orientation

    bool empty() const { return lines.empty() && fills.empty(); }
    void append(const Shapes& other);
};

/// Axis-aligned box (m); starts empty.
struct Box {
    double xmin = std::numeric_limits<double>::infinity();
    double ymin = std::numeric_limits<double>::infinity();
    double xmax = -std::numeric_limits<double>::infinity();
    double ymax = -std::numeric_limits<double>::infinity();

    bool valid() const { return xmin <= xmax && ymin <= ymax; }
    void add(Point2 p);
    /// The larger side; 0 for a point, 0 for an empty box.
    double size() const;
    Point2 centre() const { return {(xmin + xmax) / 2, (ymin + ymax) / 2}; }
};

/// Box of everything the picture draws at its true position: regions, blocks, mesh nodes,
/// joints, supports, load points and measurement points.
Box model_box(const Preprocessed& p);

/// Length that symbols (arrows, support markers) are scaled from: 1/40 of the model box, or 1 m
/// for an empty model, so symbols look the same whatever the model's size.
double symbol_size(const Box& box);

/// Whether `q` lies in rock: inside some region's boundary and outside all of its holes.
bool inside_material(const Model& model, Point2 q);

/// One piece of a segment, after splitting it where it crosses region boundaries or holes.
struct SegmentPiece {
    Point2 from, to;
    bool in_material = false;
};

/// Splits [a, b] at every crossing with a region ring and says for each piece whether it lies
/// in rock. Pieces are in order from a to b and cover the whole segment.
std::vector<SegmentPiece> split_by_material(const Model& model, Point2 a, Point2 b);

/// Unit vector normal to [a, b] pointing into rock (checked just beside the midpoint at
/// `probe` distance); the left normal when neither or both sides are rock.
Point2 normal_into_material(const Model& model, Point2 a, Point2 b, double probe);

/// Whether a symbol standing `distance` away from `q` along the unit vector `d` (and half as
/// wide to either side) is free of rock.
bool clear_of_material(const Model& model, Point2 q, Point2 d, double distance);

/// The first of −y, −x, +x, +y along which the point `distance` away from `q` is not rock;
/// −y for a point deep inside. Support symbols are drawn on that side.
Point2 direction_out_of_material(const Model& model, Point2 q, double distance);

/// A regular polygon approximating a circle (m).
std::vector<Point2> circle(Point2 centre, double radius, int segments = 24);

/// Signed area of a ring (m²): positive when counter-clockwise.
double signed_area(const Ring& ring);

}  // namespace mcdda::view

#pragma once
/// \file ResultProbe.hpp
/// The value a result picture shows at a point: the triangle drawn there (deformed as drawn)
/// and the field's value in it, in the legend's units — what the desktop program puts in the
/// status bar under the cursor. Plain data, no VTK; made by build_result_scene.

#include "model/Model.hpp"

#include <array>
#include <string>
#include <vector>

namespace mcdda::view {

class ResultProbe {
public:
    /// The field at the model point (x, y) of the picture as text, e.g. "principal stress 1 =
    /// -12.3 MPa" or "plastic state: yielding now" (translated by picture_text), led by the axial
    /// force of a bolt there; empty outside the mesh or for an empty probe.
    std::string describe(double x, double y) const;
    /// The value at (x, y) in the legend's units (a state 0, 1, 2 for plastic_state); false
    /// outside the mesh.
    bool valueAt(double x, double y, double* value) const;
    bool empty() const { return triangles.empty(); }

    // Filled by build_result_scene.
    std::vector<Point2> points;                       ///< as drawn (x + deform · u)
    std::vector<std::array<int, 3>> triangles;        ///< point indices
    std::vector<double> values;                       ///< per point or per triangle
    bool point_values = false;
    bool categorical = false;                         ///< plastic_state
    std::string title;                                ///< the field as the legend names it
    std::string units;                                ///< m, kPa, MPa, -, ...

    /// A bolt as drawn, with its axial force (N/m, tension positive).
    struct Bolt {
        Point2 from, to;
        double force = 0.0;
    };
    std::vector<Bolt> bolts;
    double bolt_reach = 0.0;  ///< how near a bolt (m) a point is on it: a few pixels

private:
    std::string describe_field(double x, double y) const;
};

}  // namespace mcdda::view

#pragma once
/// \file ModelItems.hpp
/// Names one drawn item of a model (a region, a hole of it, a joint, a support, a load, a
/// measurement point, a water table or an absorbing boundary), or one vertex of it, and the edits the Select tool makes with it:
/// finding what is under the cursor, moving it and deleting it. Plain model operations, no Qt,
/// so they are tested without a display.

#include "model/Model.hpp"

#include <vector>

namespace mcdda::gui {

struct ItemRef {
    enum class Kind { None, Region, Joint, FixedPoint, Roller, PointLoad, EdgePressure, MeasurementPoint, WaterTable,
                      AbsorbingBoundary, CompliantBase };
    Kind kind = Kind::None;
    /// Into the model's list of that kind; a water table: 0 = the model's (Model::water), k = the
    /// one stage k − 1 sets; the compliant base (Model::base_motion's segment): 0.
    int index = -1;
    int ring = 0;     ///< regions: 0 = the boundary, k = hole k − 1
    int vertex = -1;  ///< a vertex of the item (of `ring` for regions); −1 = the whole item

    bool valid() const { return kind != Kind::None && index >= 0; }
    /// The same item (or hole) as a whole: no vertex.
    ItemRef whole() const { return {kind, index, ring, -1}; }
    friend bool operator==(const ItemRef& a, const ItemRef& b) {
        return a.kind == b.kind && a.index == b.index && a.ring == b.ring && a.vertex == b.vertex;
    }
    friend bool operator!=(const ItemRef& a, const ItemRef& b) { return !(a == b); }
};

/// Whether `ref` names an item (and vertex) that exists in `model`.
bool item_exists(const Model& model, const ItemRef& ref);

/// What lies under `p`: a vertex within `tolerance` (m) first (the nearest one), then a line
/// (joint, roller, edge pressure, absorbing boundary, the water table; a region's boundary edge gives the region, a hole's edge the
/// hole), then the innermost region whose area
/// holds `p`. Joints generated from joint sets are not picked (they are edited through their
/// set). The water table picked is the one in force in `stage` (-1: the model as drawn), as the
/// picture of that stage draws it: its line held level to the model's sides. A None reference
/// when nothing is there.
ItemRef pick_item(const Model& model, const Point2& p, double tolerance, int stage = -1);

/// The water table that is in force in `stage` (-1: the model as drawn), as a reference: the
/// model's or that of the last stage up to `stage` that sets one. Invalid when that is dry.
ItemRef water_table_in(const Model& model, int stage);

/// The points of an item as drawn: a closed ring for regions (`closed` set), the line of a
/// joint, roller or edge pressure, the single point of the others. A vertex reference gives
/// that vertex only. Empty when `ref` does not exist.
std::vector<Point2> item_points(const Model& model, const ItemRef& ref, bool* closed = nullptr);

/// Where the item is gripped for snapping while it is dragged: the vertex, or the first point.
Point2 item_anchor(const Model& model, const ItemRef& ref);

/// Moves the vertex, the hole, or the whole item (a region with its holes) by `delta`. False when `ref`
/// does not exist, or when a water table's vertex would pass a neighbour (the line must run
/// left to right).
bool move_item(Model& model, const ItemRef& ref, const Point2& delta);

/// Deletes a vertex of a ring (which keeps at least 3), of a joint or of a water table (a
/// two-point one goes as a whole); a vertex of a point or two-point item deletes the item; a hole named without a
/// vertex goes as a hole, anything else as a whole item. A water table that goes leaves the
/// model, or its stage, dry. False when `ref` does not exist or
/// the vertex is one of a triangle's. The compliant base that goes takes the base motion with
/// it (no base shakes).
bool delete_item(Model& model, const ItemRef& ref);

}  // namespace mcdda::gui

#include "document/ModelItems.hpp"

#include "geometry/PolygonChecks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace mcdda::gui {

namespace {

using Kind = ItemRef::Kind;

double distance(const Point2& a, const Point2& b) { return std::hypot(a.x - b.x, a.y - b.y); }

double segment_distance(const Point2& p, const Point2& a, const Point2& b)
{
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double l2 = dx * dx + dy * dy;
    double t = l2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0.0;
    t = std::fmax(0.0, std::fmin(1.0, t));
    return distance(p, {a.x + t * dx, a.y + t * dy});
}

template <typename T>
bool in_range(const std::vector<T>& list, int index)
{
    return index >= 0 && static_cast<std::size_t>(index) < list.size();
}

/// The water a water-table reference names (the model's, or a stage's), null when there is none.
template <typename M>
auto water_of(M& m, int index) -> decltype(&m.water)
{
    if (index == 0) return &m.water;
    if (index < 1 || static_cast<std::size_t>(index) > m.stages.size()) return nullptr;
    auto& water = m.stages[static_cast<std::size_t>(index - 1)].water;
    return water ? &*water : nullptr;
}

/// Point2 or const Point2, as the model is.
template <typename M>
using PointOf = std::conditional_t<std::is_const_v<M>, const Point2, Point2>;

/// The editable points of an item, in a fixed order (a region: boundary then holes).
template <typename M>
std::vector<PointOf<M>*> points_of(M& m, Kind kind, int index)
{
    std::vector<PointOf<M>*> out;
    switch (kind) {
    case Kind::Region:
        if (!in_range(m.regions, index)) break;
        for (auto& p : m.regions[index].boundary) out.push_back(&p);
        for (auto& hole : m.regions[index].holes)
            for (auto& p : hole) out.push_back(&p);
        break;
    case Kind::Joint:
        if (in_range(m.joints, index))
            for (auto& p : m.joints[index].points) out.push_back(&p);
        break;
    case Kind::FixedPoint:
        if (in_range(m.fixed_points, index)) out.push_back(&m.fixed_points[index].point);
        break;
    case Kind::Roller:
        if (in_range(m.rollers, index)) out = {&m.rollers[index].from, &m.rollers[index].to};
        break;
    case Kind::PointLoad:
        if (in_range(m.point_loads, index)) out.push_back(&m.point_loads[index].point);
        break;
    case Kind::EdgePressure:
        if (in_range(m.edge_pressures, index)) out = {&m.edge_pressures[index].from, &m.edge_pressures[index].to};
        break;
    case Kind::MeasurementPoint:
        if (in_range(m.measurement_points, index)) out.push_back(&m.measurement_points[index].point);
        break;
    case Kind::CompliantBase:
        if (index == 0 && m.base_motion.kind == BaseMotion::Kind::Compliant) out = {&m.base_motion.from, &m.base_motion.to};
        break;
    case Kind::AbsorbingBoundary:
        if (in_range(m.absorbing_boundaries, index))
            out = {&m.absorbing_boundaries[index].from, &m.absorbing_boundaries[index].to};
        break;
    case Kind::WaterTable:
        if (auto* water = water_of(m, index); water && water->present())
            for (auto& p : water->piezometric_line) out.push_back(&p);
        break;
    case Kind::None:
        break;
    }
    return out;
}

/// The vertices a vertex reference counts in: one ring of a region, else all the item's points.
template <typename M>
std::vector<PointOf<M>*> vertex_list(M& m, const ItemRef& ref)
{
    if (ref.kind != Kind::Region) return points_of(m, ref.kind, ref.index);
    std::vector<PointOf<M>*> out;
    if (!in_range(m.regions, ref.index)) return out;
    auto& r = m.regions[ref.index];
    if (ref.ring < 0 || static_cast<std::size_t>(ref.ring) > r.holes.size()) return out;
    auto& ring = ref.ring == 0 ? r.boundary : r.holes[ref.ring - 1];
    for (auto& p : ring) out.push_back(&p);
    return out;
}

template <typename T>
void erase_at(std::vector<T>& list, int index)
{
    list.erase(list.begin() + index);
}

}  // namespace

bool item_exists(const Model& model, const ItemRef& ref)
{
    if (!ref.valid()) return false;
    if (points_of(model, ref.kind, ref.index).empty()) return false;
    if (ref.kind == Kind::Region) {
        const Region& r = model.regions[ref.index];
        if (ref.ring < 0 || static_cast<std::size_t>(ref.ring) > r.holes.size()) return false;
    }
    if (ref.vertex < 0) return true;
    return static_cast<std::size_t>(ref.vertex) < vertex_list(model, ref).size();
}

ItemRef water_table_in(const Model& model, int stage)
{
    int index = 0;
    for (int k = std::min(stage, static_cast<int>(model.stages.size()) - 1); k >= 0; --k)
        if (model.stages[static_cast<std::size_t>(k)].water) {
            index = k + 1;
            break;
        }
    const Water* water = water_of(model, index);
    return water && water->present() ? ItemRef{Kind::WaterTable, index} : ItemRef{};
}

ItemRef pick_item(const Model& model, const Point2& p, double tolerance, int stage)
{
    ItemRef best;
    double best_d = tolerance;
    auto consider = [&](const Point2& q, Kind kind, int index, int ring, int vertex) {
        const double d = distance(p, q);
        if (d <= best_d) {
            best_d = d;
            best = {kind, index, ring, vertex};
        }
    };
    // Vertices. Points of supports, loads and measurement points come last so that, at equal
    // distance, they win over the region corner they sit on (they are the smaller targets).
    for (int i = 0; i < static_cast<int>(model.regions.size()); ++i) {
        const Region& r = model.regions[i];
        for (int v = 0; v < static_cast<int>(r.boundary.size()); ++v) consider(r.boundary[v], Kind::Region, i, 0, v);
        for (int h = 0; h < static_cast<int>(r.holes.size()); ++h)
            for (int v = 0; v < static_cast<int>(r.holes[h].size()); ++v) consider(r.holes[h][v], Kind::Region, i, h + 1, v);
    }
    for (int i = 0; i < static_cast<int>(model.joints.size()); ++i) {
        if (model.joints[i].joint_set >= 0) continue;
        for (int v = 0; v < static_cast<int>(model.joints[i].points.size()); ++v)
            consider(model.joints[i].points[v], Kind::Joint, i, 0, v);
    }
    for (int i = 0; i < static_cast<int>(model.rollers.size()); ++i) {
        consider(model.rollers[i].from, Kind::Roller, i, 0, 0);
        consider(model.rollers[i].to, Kind::Roller, i, 0, 1);
    }
    for (int i = 0; i < static_cast<int>(model.edge_pressures.size()); ++i) {
        consider(model.edge_pressures[i].from, Kind::EdgePressure, i, 0, 0);
        consider(model.edge_pressures[i].to, Kind::EdgePressure, i, 0, 1);
    }
    for (int i = 0; i < static_cast<int>(model.absorbing_boundaries.size()); ++i) {
        consider(model.absorbing_boundaries[i].from, Kind::AbsorbingBoundary, i, 0, 0);
        consider(model.absorbing_boundaries[i].to, Kind::AbsorbingBoundary, i, 0, 1);
    }
    const bool compliant = model.base_motion.kind == BaseMotion::Kind::Compliant;
    if (compliant) {
        consider(model.base_motion.from, Kind::CompliantBase, 0, 0, 0);
        consider(model.base_motion.to, Kind::CompliantBase, 0, 0, 1);
    }
    for (int i = 0; i < static_cast<int>(model.fixed_points.size()); ++i)
        consider(model.fixed_points[i].point, Kind::FixedPoint, i, 0, -1);
    for (int i = 0; i < static_cast<int>(model.point_loads.size()); ++i)
        consider(model.point_loads[i].point, Kind::PointLoad, i, 0, -1);
    for (int i = 0; i < static_cast<int>(model.measurement_points.size()); ++i)
        consider(model.measurement_points[i].point, Kind::MeasurementPoint, i, 0, -1);
    const ItemRef water = water_table_in(model, stage);
    const std::vector<Point2>* water_line = water.valid() ? &water_of(model, water.index)->piezometric_line : nullptr;
    if (water_line)
        for (int v = 0; v < static_cast<int>(water_line->size()); ++v)
            consider((*water_line)[static_cast<std::size_t>(v)], Kind::WaterTable, water.index, 0, v);
    if (best.valid()) return best;

    // Lines: a whole joint, roller or pressure; a region edge picks its region.
    auto line = [&](const std::vector<Point2>& pts, bool closed, Kind kind, int index, int ring = 0) {
        const std::size_t n = pts.size();
        for (std::size_t k = 0; k + 1 < n + (closed ? 1 : 0); ++k) {
            const double d = segment_distance(p, pts[k], pts[(k + 1) % n]);
            if (d <= best_d) {
                best_d = d;
                best = {kind, index, ring, -1};
            }
        }
    };
    for (int i = 0; i < static_cast<int>(model.joints.size()); ++i)
        if (model.joints[i].joint_set < 0) line(model.joints[i].points, false, Kind::Joint, i);
    for (int i = 0; i < static_cast<int>(model.rollers.size()); ++i)
        line({model.rollers[i].from, model.rollers[i].to}, false, Kind::Roller, i);
    for (int i = 0; i < static_cast<int>(model.edge_pressures.size()); ++i)
        line({model.edge_pressures[i].from, model.edge_pressures[i].to}, false, Kind::EdgePressure, i);
    for (int i = 0; i < static_cast<int>(model.absorbing_boundaries.size()); ++i)
        line({model.absorbing_boundaries[i].from, model.absorbing_boundaries[i].to}, false, Kind::AbsorbingBoundary, i);
    if (compliant) line({model.base_motion.from, model.base_motion.to}, false, Kind::CompliantBase, 0);
    if (water_line && !model.regions.empty()) {
        // As drawn: held level from its end points to the model's sides.
        std::vector<Point2> drawn = *water_line;
        const auto box = model.bounds();
        if (box[0] < drawn.front().x) drawn.insert(drawn.begin(), Point2{box[0], drawn.front().y});
        if (box[2] > drawn.back().x) drawn.push_back({box[2], drawn.back().y});
        line(drawn, false, Kind::WaterTable, water.index);
    } else if (water_line) {
        line(*water_line, false, Kind::WaterTable, water.index);
    }
    if (best.valid()) return best;
    for (int i = 0; i < static_cast<int>(model.regions.size()); ++i) {
        const Region& r = model.regions[i];
        line(r.boundary, true, Kind::Region, i);
        for (int h = 0; h < static_cast<int>(r.holes.size()); ++h) line(r.holes[h], true, Kind::Region, i, h + 1);
    }
    if (best.valid()) return best;

    // Areas: the smallest region holding the point (a region drawn inside another's hole).
    double best_area = std::numeric_limits<double>::infinity();
    for (int i = 0; i < static_cast<int>(model.regions.size()); ++i) {
        const Region& r = model.regions[i];
        if (!region_contains(r, p)) continue;
        const double area = std::fabs(signed_area(r.boundary));
        if (area < best_area) {
            best_area = area;
            best = {Kind::Region, i, 0, -1};
        }
    }
    return best;
}

std::vector<Point2> item_points(const Model& model, const ItemRef& ref, bool* closed)
{
    if (closed) *closed = false;
    std::vector<Point2> out;
    if (!item_exists(model, ref)) return out;
    if (ref.vertex >= 0) return {*vertex_list(model, ref)[ref.vertex]};
    if (ref.kind == Kind::Region) {
        if (closed) *closed = true;
        const Region& r = model.regions[ref.index];
        return ref.ring == 0 ? r.boundary : r.holes[ref.ring - 1];
    }
    for (const Point2* p : points_of(model, ref.kind, ref.index)) out.push_back(*p);
    return out;
}

Point2 item_anchor(const Model& model, const ItemRef& ref)
{
    const std::vector<Point2> pts = item_points(model, ref);
    return pts.empty() ? Point2{} : pts.front();
}

bool move_item(Model& model, const ItemRef& ref, const Point2& delta)
{
    if (!item_exists(model, ref)) return false;
    std::vector<Point2*> pts;
    if (ref.vertex >= 0) pts = {vertex_list(model, ref)[ref.vertex]};
    else if (ref.kind == Kind::Region && ref.ring > 0) pts = vertex_list(model, ref);  // one hole
    else pts = points_of(model, ref.kind, ref.index);
    if (ref.kind == Kind::WaterTable && ref.vertex >= 0) {
        // Not past a neighbour: one level at each x. Only the moved point's own order is asked
        // for, so a line read from a file that folds back elsewhere can still be mended.
        const std::vector<Point2>& line = water_of(model, ref.index)->piezometric_line;
        const auto v = static_cast<std::size_t>(ref.vertex);
        const double x = line[v].x + delta.x;
        if ((v > 0 && !(x > line[v - 1].x)) || (v + 1 < line.size() && !(x < line[v + 1].x))) return false;
    }
    for (Point2* p : pts) {
        p->x += delta.x;
        p->y += delta.y;
    }
    return true;
}

bool delete_item(Model& model, const ItemRef& ref)
{
    if (!item_exists(model, ref)) return false;
    if (ref.kind == Kind::Region && ref.vertex >= 0) {
        Region& r = model.regions[ref.index];
        Ring& ring = ref.ring == 0 ? r.boundary : r.holes[ref.ring - 1];
        if (ring.size() <= 3) return false;
        erase_at(ring, ref.vertex);
        return true;
    }
    if (ref.kind == Kind::Region && ref.ring > 0) {
        erase_at(model.regions[ref.index].holes, ref.ring - 1);
        return true;
    }
    if (ref.kind == Kind::Joint && ref.vertex >= 0 && model.joints[ref.index].points.size() > 2) {
        erase_at(model.joints[ref.index].points, ref.vertex);
        return true;
    }
    if (ref.kind == Kind::WaterTable) {
        // A vertex of a longer line goes alone; else the line goes and the ground is dry (a
        // stage keeps its water set, now dry, rather than the water of the stage before).
        std::vector<Point2>& line = water_of(model, ref.index)->piezometric_line;
        if (ref.vertex >= 0 && line.size() > 2) erase_at(line, ref.vertex);
        else line.clear();
        return true;
    }
    switch (ref.kind) {
    case Kind::Region: erase_at(model.regions, ref.index); break;
    case Kind::Joint: erase_at(model.joints, ref.index); break;
    case Kind::FixedPoint: erase_at(model.fixed_points, ref.index); break;
    case Kind::Roller: erase_at(model.rollers, ref.index); break;
    case Kind::PointLoad: erase_at(model.point_loads, ref.index); break;
    case Kind::EdgePressure: erase_at(model.edge_pressures, ref.index); break;
    case Kind::MeasurementPoint: erase_at(model.measurement_points, ref.index); break;
    case Kind::AbsorbingBoundary: erase_at(model.absorbing_boundaries, ref.index); break;
    case Kind::CompliantBase: model.base_motion = BaseMotion{}; break;
    case Kind::WaterTable:  // handled above
    case Kind::None: return false;
    }
    return true;
}

}  // namespace mcdda::gui

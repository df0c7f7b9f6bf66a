#include "view/Symbols.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mcdda::view {

namespace {

Point2 add(Point2 a, Point2 b) { return {a.x + b.x, a.y + b.y}; }
Point2 scale(Point2 a, double s) { return {a.x * s, a.y * s}; }
Point2 perp(Point2 a) { return {-a.y, a.x}; }
/// `at` + u·d + v·perp(d): coordinates in a symbol's own frame.
Point2 frame(Point2 at, Point2 d, double u, double v) { return add(at, add(scale(d, u), scale(perp(d), v))); }

/// Markers along [from, to]: both ends plus evenly spaced ones about every 4 symbol sizes.
std::vector<Point2> markers_along(Point2 from, Point2 to, double size)
{
    const double len = std::hypot(to.x - from.x, to.y - from.y);
    if (len <= 0.0) return {from};
    const int n = std::clamp(static_cast<int>(len / (4.0 * size)) + 1, 2, 12);
    std::vector<Point2> points;
    for (int i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / (n - 1);
        points.push_back({from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)});
    }
    return points;
}

/// ±axis chosen so that a symbol drawn along it lies outside the rock.
Point2 outward_along_axis(const Model& model, Point2 at, Point2 axis, double size)
{
    const Point2 minus{-axis.x, -axis.y};
    if (clear_of_material(model, at, minus, 1.5 * size)) return minus;
    if (clear_of_material(model, at, axis, 1.5 * size)) return axis;
    return minus;
}

}  // namespace

Shapes arrow(Point2 tail, Point2 tip, double head_length, double head_width, double shaft_width)
{
    Shapes s;
    const double len = std::hypot(tip.x - tail.x, tip.y - tail.y);
    if (len <= 0.0) return s;
    const Point2 d{(tip.x - tail.x) / len, (tip.y - tail.y) / len};
    const double head = std::min(head_length, len);
    const double shaft = len - head;
    if (shaft > 0.0) {
        const double w = shaft_width / 2;
        s.fills.push_back({frame(tail, d, 0, -w), frame(tail, d, shaft + 0.01 * head, -w),
                           frame(tail, d, shaft + 0.01 * head, w), frame(tail, d, 0, w)});
    }
    s.fills.push_back({tip, frame(tail, d, shaft, head_width / 2), frame(tail, d, shaft, -head_width / 2)});
    return s;
}

Shapes fixed_point_symbol(Point2 at, Point2 outward, double size)
{
    Shapes s;
    const double h = size, w = 0.6 * size, g = 0.8 * size;
    s.fills.push_back({at, frame(at, outward, h, w), frame(at, outward, h, -w)});
    s.lines.push_back({frame(at, outward, h, -g), frame(at, outward, h, g)});
    for (int i = 0; i < 5; ++i) {  // hatching below the ground line
        const double v = -g + 0.4 * size * i;
        s.lines.push_back({frame(at, outward, h, v + 0.25 * size), frame(at, outward, h + 0.3 * size, v)});
    }
    return s;
}

Shapes roller_symbol(Point2 at, Point2 outward, double size)
{
    Shapes s;
    const double h = 0.9 * size, w = 0.55 * size, r = 0.17 * size, gap = 0.08 * size;
    s.lines.push_back({at, frame(at, outward, h, w), frame(at, outward, h, -w), at});
    s.fills.push_back(circle(frame(at, outward, h + gap + r, 0.3 * size), r, 12));
    s.fills.push_back(circle(frame(at, outward, h + gap + r, -0.3 * size), r, 12));
    const double ground = h + 2 * (gap + r);
    s.lines.push_back({frame(at, outward, ground, -0.75 * size), frame(at, outward, ground, 0.75 * size)});
    return s;
}

Shapes measurement_symbol(Point2 at, double size)
{
    const double r = 0.45 * size;
    Shapes s;
    s.fills.push_back({{at.x + r, at.y}, {at.x, at.y + r}, {at.x - r, at.y}, {at.x, at.y - r}});
    return s;
}

Shapes water_table_symbol(Point2 at, double size)
{
    Shapes s;
    const double h = 0.8 * size, w = 0.5 * size;
    s.lines.push_back({at, {at.x + w, at.y + h}, {at.x - w, at.y + h}, at});
    for (const auto& [depth, half] : {std::pair{0.3, 0.45}, std::pair{0.6, 0.25}})
        s.lines.push_back({{at.x - half * size, at.y - depth * size}, {at.x + half * size, at.y - depth * size}});
    return s;
}

Shapes water_table_shapes(const Water& water, double xmin, double xmax, double symbol_x, double size)
{
    Shapes s;
    if (!water.present()) return s;
    const std::vector<Point2>& line = water.piezometric_line;
    std::vector<Point2> drawn;
    if (xmin < line.front().x) drawn.push_back({xmin, line.front().y});
    drawn.insert(drawn.end(), line.begin(), line.end());
    if (xmax > line.back().x) drawn.push_back({xmax, line.back().y});
    s.lines.push_back(std::move(drawn));
    // On the line as drawn (a line that folds back, refused by the checker, still gets one).
    const double lo = std::min({xmin, line.front().x, line.back().x}), hi = std::max({xmax, line.front().x, line.back().x});
    const double x = std::clamp(symbol_x, lo, hi);
    const double y = water.level(x);
    if (std::isfinite(x) && std::isfinite(y)) s.append(water_table_symbol({x, y}, size));
    return s;
}

Shapes fixed_point_shapes(const Model& model, double size)
{
    Shapes s;
    for (const FixedPoint& f : model.fixed_points)
        s.append(fixed_point_symbol(f.point, direction_out_of_material(model, f.point, 1.5 * size), size));
    return s;
}

Shapes roller_shapes(const Model& model, double size)
{
    Shapes s;
    for (const Roller& r : model.rollers) {
        s.lines.push_back({r.from, r.to});
        const Point2 mid{(r.from.x + r.to.x) / 2, (r.from.y + r.to.y) / 2};
        for (const Point2& at : markers_along(r.from, r.to, size)) {
            if (r.fix_x && r.fix_y) {
                s.append(fixed_point_symbol(at, direction_out_of_material(model, mid, 1.5 * size), 0.8 * size));
                continue;
            }
            if (r.fix_x) s.append(roller_symbol(at, outward_along_axis(model, mid, {1, 0}, size), 0.8 * size));
            if (r.fix_y) s.append(roller_symbol(at, outward_along_axis(model, mid, {0, 1}, size), 0.8 * size));
        }
    }
    return s;
}

Shapes point_load_shapes(const Model& model, double size)
{
    double largest = 0.0;
    for (const PointLoad& l : model.point_loads) largest = std::max(largest, std::hypot(l.force.x, l.force.y));
    Shapes s;
    for (const PointLoad& l : model.point_loads) {
        const double f = std::hypot(l.force.x, l.force.y);
        if (!(f > 0.0) || !std::isfinite(f)) {  // no direction: mark the point with a ring
            std::vector<Point2> ring = circle(l.point, 0.3 * size, 16);
            ring.push_back(ring.front());
            s.lines.push_back(ring);
            continue;
        }
        const double length = 3.0 * size * (0.5 + 0.5 * f / largest);
        const Point2 tail{l.point.x - length * l.force.x / f, l.point.y - length * l.force.y / f};
        s.append(arrow(tail, l.point, 0.9 * size, 0.7 * size, 0.18 * size));
    }
    return s;
}

Shapes edge_pressure_shapes(const Model& model, double size)
{
    Shapes s;
    const double length = 2.2 * size;
    for (const EdgePressure& e : model.edge_pressures) {
        const Point2 n = normal_into_material(model, e.from, e.to, 0.25 * size);
        const Point2 back{-length * n.x, -length * n.y};  // from the edge to the row of tails
        s.lines.push_back({add(e.from, back), add(e.to, back)});
        if (e.pressure == 0.0 || !std::isfinite(e.pressure)) continue;
        const double len = std::hypot(e.to.x - e.from.x, e.to.y - e.from.y);
        const int count = std::clamp(static_cast<int>(std::lround(len / (2.0 * size))) + 1, 2, 25);
        for (int i = 0; i < count; ++i) {
            const double t = static_cast<double>(i) / (count - 1);
            const Point2 on{e.from.x + t * (e.to.x - e.from.x), e.from.y + t * (e.to.y - e.from.y)};
            const Point2 off = add(on, back);
            if (e.pressure > 0.0)
                s.append(arrow(off, on, 0.7 * size, 0.55 * size, 0.12 * size));
            else
                s.append(arrow(on, off, 0.7 * size, 0.55 * size, 0.12 * size));
        }
    }
    return s;
}

Shapes dashpot_symbol(Point2 at, Point2 outward, double size)
{
    Shapes s;
    const double rod = 0.7 * size, cup_from = 0.45 * size, cup_to = 1.1 * size, half = 0.32 * size;
    const double ground = 1.4 * size;
    s.lines.push_back({at, frame(at, outward, rod, 0)});
    s.lines.push_back({frame(at, outward, rod, -0.8 * half), frame(at, outward, rod, 0.8 * half)});  // the piston
    s.lines.push_back({frame(at, outward, cup_from, -half), frame(at, outward, cup_to, -half),
                       frame(at, outward, cup_to, half), frame(at, outward, cup_from, half)});
    s.lines.push_back({frame(at, outward, cup_to, 0), frame(at, outward, ground, 0)});
    s.lines.push_back({frame(at, outward, ground, -1.4 * half), frame(at, outward, ground, 1.4 * half)});
    for (int i = 0; i < 4; ++i) {  // hatching beyond the ground line
        const double v = -1.4 * half + 0.8 * half * i;
        s.lines.push_back({frame(at, outward, ground, v + 0.5 * half), frame(at, outward, ground + 0.25 * size, v)});
    }
    return s;
}

Shapes dashpot_line_shapes(const Model& model, Point2 from, Point2 to, double size, bool input)
{
    Shapes s;
    const double len = std::hypot(to.x - from.x, to.y - from.y);
    if (!(len > 0.0) || !std::isfinite(len)) return s;
    const Point2 d{(to.x - from.x) / len, (to.y - from.y) / len};
    // Dashed, so it is not taken for a block edge or a roller's line.
    const double dash = 0.6 * size, gap = 0.35 * size;
    for (double t = 0.0; t < len; t += dash + gap)
        s.lines.push_back({add(from, scale(d, t)), add(from, scale(d, std::min(len, t + dash)))});
    const Point2 n = normal_into_material(model, from, to, 0.25 * size);
    const Point2 out{-n.x, -n.y};
    for (const Point2& at : markers_along(from, to, 1.5 * size)) {
        s.append(dashpot_symbol(at, out, 1.2 * size));
        if (input)  // the wave coming in: an arrow from beyond the ground line up to the boundary
            s.append(arrow(add(at, add(scale(out, 2.0 * size), scale(d, 0.6 * size))), add(at, scale(d, 0.6 * size)),
                           0.6 * size, 0.5 * size, 0.12 * size));
    }
    return s;
}

Shapes absorbing_boundary_shapes(const Model& model, double size)
{
    Shapes s;
    for (const AbsorbingBoundary& a : model.absorbing_boundaries) s.append(dashpot_line_shapes(model, a.from, a.to, size));
    return s;
}

Shapes compliant_base_shapes(const Model& model, double size)
{
    if (model.base_motion.kind != BaseMotion::Kind::Compliant) return {};
    return dashpot_line_shapes(model, model.base_motion.from, model.base_motion.to, size, true);
}

Shapes measurement_shapes(const Model& model, double size)
{
    Shapes s;
    for (const MeasurementPoint& m : model.measurement_points) s.append(measurement_symbol(m.point, size));
    return s;
}

}  // namespace mcdda::view

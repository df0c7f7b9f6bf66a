#include "view/SceneGeometry.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda::view {

namespace {

double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
Point2 sub(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
Point2 lerp(Point2 a, Point2 b, double t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }

/// Even–odd test; points exactly on the ring count either way.
bool inside_ring(const Ring& ring, Point2 q)
{
    bool inside = false;
    const std::size_t n = ring.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const Point2 a = ring[i];
        const Point2 b = ring[j];
        if ((a.y > q.y) != (b.y > q.y)) {
            const double x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (q.x < x) inside = !inside;
        }
    }
    return n >= 3 && inside;
}

/// Parameters t in (0, 1) where [a, b] crosses the edges of `ring`.
void add_crossings(const Ring& ring, Point2 a, Point2 b, std::vector<double>& ts)
{
    const Point2 d = sub(b, a);
    const std::size_t n = ring.size();
    if (n < 2) return;
    for (std::size_t i = 0; i < n; ++i) {
        const Point2 q0 = ring[i];
        const Point2 q1 = ring[(i + 1) % n];
        const Point2 e = sub(q1, q0);
        const double denom = cross(d, e);
        if (std::abs(denom) < 1e-300) continue;  // parallel: the midpoint tests settle it
        const Point2 w = sub(q0, a);
        const double t = cross(w, e) / denom;
        const double u = cross(w, d) / denom;
        if (t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0) ts.push_back(t);
    }
}

}  // namespace

void Shapes::append(const Shapes& other)
{
    lines.insert(lines.end(), other.lines.begin(), other.lines.end());
    fills.insert(fills.end(), other.fills.begin(), other.fills.end());
}

void Box::add(Point2 p)
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    xmin = std::min(xmin, p.x);
    ymin = std::min(ymin, p.y);
    xmax = std::max(xmax, p.x);
    ymax = std::max(ymax, p.y);
}

double Box::size() const { return valid() ? std::max(xmax - xmin, ymax - ymin) : 0.0; }

Box model_box(const Preprocessed& p)
{
    Box box;
    const Model& m = p.model;
    for (const Region& r : m.regions) {
        for (const Point2& q : r.boundary) box.add(q);
        for (const Ring& h : r.holes)
            for (const Point2& q : h) box.add(q);
    }
    for (const Block& b : p.blocks)
        for (const Point2& q : b.outer) box.add(q);
    for (const Point2& q : p.mesh.nodes) box.add(q);
    for (const Joint& j : m.joints)
        for (const Point2& q : j.points) box.add(q);
    for (const FixedPoint& f : m.fixed_points) box.add(f.point);
    for (const Roller& r : m.rollers) {
        box.add(r.from);
        box.add(r.to);
    }
    for (const PointLoad& l : m.point_loads) box.add(l.point);
    for (const EdgePressure& e : m.edge_pressures) {
        box.add(e.from);
        box.add(e.to);
    }
    for (const MeasurementPoint& q : m.measurement_points) box.add(q.point);
    return box;
}

double symbol_size(const Box& box)
{
    const double size = box.size();
    return size > 0.0 ? size / 40.0 : 1.0;
}

bool inside_material(const Model& model, Point2 q)
{
    for (const Region& r : model.regions) {
        if (!inside_ring(r.boundary, q)) continue;
        const bool in_hole = std::any_of(r.holes.begin(), r.holes.end(),
                                         [&](const Ring& h) { return inside_ring(h, q); });
        if (!in_hole) return true;
    }
    return false;
}

std::vector<SegmentPiece> split_by_material(const Model& model, Point2 a, Point2 b)
{
    std::vector<double> ts{0.0, 1.0};
    for (const Region& r : model.regions) {
        add_crossings(r.boundary, a, b, ts);
        for (const Ring& h : r.holes) add_crossings(h, a, b, ts);
    }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end(), [](double u, double v) { return v - u < 1e-12; }),
             ts.end());

    std::vector<SegmentPiece> pieces;
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
        const Point2 from = lerp(a, b, ts[i]);
        const Point2 to = lerp(a, b, ts[i + 1]);
        const bool in = inside_material(model, lerp(a, b, 0.5 * (ts[i] + ts[i + 1])));
        if (!pieces.empty() && pieces.back().in_material == in)
            pieces.back().to = to;  // merge pieces split at a vertex without a change of side
        else
            pieces.push_back({from, to, in});
    }
    return pieces;
}

Point2 normal_into_material(const Model& model, Point2 a, Point2 b, double probe)
{
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len = std::hypot(dx, dy);
    if (len <= 0.0) return {0.0, 1.0};
    const Point2 left{-dy / len, dx / len};
    const Point2 mid = lerp(a, b, 0.5);
    const bool left_in = inside_material(model, {mid.x + probe * left.x, mid.y + probe * left.y});
    const bool right_in = inside_material(model, {mid.x - probe * left.x, mid.y - probe * left.y});
    if (right_in && !left_in) return {-left.x, -left.y};
    return left;
}

bool clear_of_material(const Model& model, Point2 q, Point2 d, double distance)
{
    // Probe the middle and both sides of where a symbol would stand: a point on a boundary
    // has rock-free directions along the boundary too, which are not wanted.
    const Point2 c{q.x + distance * d.x, q.y + distance * d.y};
    const Point2 side{-d.y * 0.5 * distance, d.x * 0.5 * distance};
    return !inside_material(model, c) && !inside_material(model, {c.x + side.x, c.y + side.y}) &&
           !inside_material(model, {c.x - side.x, c.y - side.y});
}

Point2 direction_out_of_material(const Model& model, Point2 q, double distance)
{
    static constexpr Point2 candidates[] = {{0, -1}, {-1, 0}, {1, 0}, {0, 1}};
    for (const Point2& d : candidates)
        if (clear_of_material(model, q, d, distance)) return d;
    return {0, -1};
}

std::vector<Point2> circle(Point2 centre, double radius, int segments)
{
    std::vector<Point2> points;
    points.reserve(static_cast<std::size_t>(segments));
    for (int i = 0; i < segments; ++i) {
        const double a = 2.0 * M_PI * i / segments;
        points.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
    }
    return points;
}

double signed_area(const Ring& ring)
{
    double twice = 0.0;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) twice += cross(ring[i], ring[(i + 1) % n]);
    return 0.5 * twice;
}

}  // namespace mcdda::view

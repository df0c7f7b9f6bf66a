#include "view/DeformScale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcdda::view {

namespace {

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

/// The smallest positive root of a + b s + c s² (a > 0), or +∞.
double first_zero(double a, double b, double c)
{
    const double inf = std::numeric_limits<double>::infinity();
    const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
    if (std::abs(c) <= 1e-14 * scale) return b < 0.0 ? -a / b : inf;
    const double d = b * b - 4.0 * a * c;
    if (d < 0.0) return inf;
    // The stable pair of roots: q / c and a / q.
    const double q = -0.5 * (b + std::copysign(std::sqrt(d), b));
    double best = inf;
    for (double r : {q != 0.0 ? a / q : inf, q / c})
        if (r > 0.0 && std::isfinite(r)) best = std::min(best, r);
    return best;
}

}  // namespace

double largest_untangled_scale(const std::vector<Point2>& points, const std::vector<Point2>& displacement,
                               const std::vector<std::array<int, 3>>& triangles)
{
    double smallest = std::numeric_limits<double>::infinity();
    const int n = static_cast<int>(std::min(points.size(), displacement.size()));
    for (const auto& t : triangles) {
        if (std::any_of(t.begin(), t.end(), [n](int i) { return i < 0 || i >= n; })) continue;
        const Point2 &p0 = points[t[0]], &p1 = points[t[1]], &p2 = points[t[2]];
        const Point2 &u0 = displacement[t[0]], &u1 = displacement[t[1]], &u2 = displacement[t[2]];
        const double ax = p1.x - p0.x, ay = p1.y - p0.y, bx = p2.x - p0.x, by = p2.y - p0.y;
        const double dax = u1.x - u0.x, day = u1.y - u0.y, dbx = u2.x - u0.x, dby = u2.y - u0.y;
        // Twice the drawn area at scale s: a + b s + c s², made positive at s = 0.
        double a = cross(ax, ay, bx, by);
        double b = cross(ax, ay, dbx, dby) + cross(dax, day, bx, by);
        double c = cross(dax, day, dbx, dby);
        if (a == 0.0) continue;
        if (a < 0.0) a = -a, b = -b, c = -c;
        smallest = std::min(smallest, first_zero(a, b, c));
    }
    return smallest;
}

double automatic_deform_scale(double model_size, double max_displacement, double untangled)
{
    if (!(max_displacement > 0.0)) return 0.0;
    const double visual = 0.05 * model_size / max_displacement;
    return std::min(visual, 0.5 * untangled);  // half-way to the first inverted element
}

}  // namespace mcdda::view

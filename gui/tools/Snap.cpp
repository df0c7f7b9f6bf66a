#include "tools/Snap.hpp"

#include <cmath>
#include <limits>

namespace mcdda::gui {

Point2 snap_point(const Point2& p, const Model& model, const std::vector<Point2>& extra, const SnapOptions& options)
{
    double best = std::numeric_limits<double>::infinity();
    Point2 found = p;
    auto consider = [&](const Point2& q) {
        const double d = std::hypot(q.x - p.x, q.y - p.y);
        if (d <= options.vertex_tolerance && d < best) {
            best = d;
            found = q;
        }
    };
    if (options.vertex_tolerance > 0.0) {
        for (const Region& r : model.regions) {
            for (const Point2& q : r.boundary) consider(q);
            for (const Ring& h : r.holes)
                for (const Point2& q : h) consider(q);
        }
        for (const Point2& q : extra) consider(q);
    }
    if (std::isfinite(best)) return found;
    if (options.grid && options.spacing > 0.0) {
        const double s = options.spacing;
        Point2 g{std::round(p.x / s) * s, std::round(p.y / s) * s};
        if (g.x == 0.0) g.x = 0.0;  // no -0 in the file
        if (g.y == 0.0) g.y = 0.0;
        return g;
    }
    return p;
}

}  // namespace mcdda::gui

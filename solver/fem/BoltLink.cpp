#include "fem/BoltLink.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcdda {

std::optional<BoltAnchor> locate_anchor(const Mesh& mesh, const std::vector<Point2>& nodes, Point2 p,
                                        const std::vector<char>& active) {
    // Bolts are few: a scan of the triangles, taking the one the point is least outside of
    // (a point on an edge shared by two elements belongs to either).
    std::optional<BoltAnchor> best;
    double best_outside = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!active.empty() && !active[t]) continue;
        const auto& tri = mesh.triangles[t];
        const Point2 a = nodes[tri[0]], b = nodes[tri[1]], c = nodes[tri[2]];
        const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        if (area <= 0.0) continue;
        const double l0 = ((b.x - p.x) * (c.y - p.y) - (c.x - p.x) * (b.y - p.y)) / area;
        const double l1 = ((c.x - p.x) * (a.y - p.y) - (a.x - p.x) * (c.y - p.y)) / area;
        const double l2 = 1.0 - l0 - l1;
        const double outside = -std::min({l0, l1, l2, 0.0});
        if (outside < best_outside) {
            best_outside = outside;
            best = BoltAnchor{static_cast<int>(t), {tri[0], tri[1], tri[2]}, {l0, l1, l2}};
        }
    }
    if (!best || best_outside > 1e-9) return std::nullopt;
    for (double& w : best->weights) w = std::clamp(w, 0.0, 1.0);
    const double sum = best->weights[0] + best->weights[1] + best->weights[2];
    for (double& w : best->weights) w /= sum;
    return best;
}

Point2 anchor_position(const BoltAnchor& a, const std::vector<Point2>& nodes) {
    Point2 p{0.0, 0.0};
    for (int i = 0; i < 3; ++i) {
        p.x += a.weights[i] * nodes[a.nodes[i]].x;
        p.y += a.weights[i] * nodes[a.nodes[i]].y;
    }
    return p;
}

BoltLink make_bolt_link(const BoltAnchor& from, const BoltAnchor& to, const std::vector<Point2>& nodes,
                        double axial_stiffness, double length, double force, bool large_displacements) {
    BoltLink link;
    const Point2 p = anchor_position(from, nodes), q = anchor_position(to, nodes);
    const double dx = q.x - p.x, dy = q.y - p.y;
    const double l = std::hypot(dx, dy);
    const double tx = l > 0.0 ? dx / l : 0.0, ty = l > 0.0 ? dy / l : 0.0;
    for (int i = 0; i < 3; ++i) {
        link.nodes[i] = from.nodes[i];
        link.nodes[3 + i] = to.nodes[i];
        link.g[2 * i] = -from.weights[i] * tx;
        link.g[2 * i + 1] = -from.weights[i] * ty;
        link.g[6 + 2 * i] = to.weights[i] * tx;
        link.g[6 + 2 * i + 1] = to.weights[i] * ty;
        // The sideways direction (−ty, tx).
        link.h[2 * i] = from.weights[i] * ty;
        link.h[2 * i + 1] = -from.weights[i] * tx;
        link.h[6 + 2 * i] = -to.weights[i] * ty;
        link.h[6 + 2 * i + 1] = to.weights[i] * tx;
    }
    // A slack (compressed) bolt has no lateral stiffness: never a negative one.
    link.geometric = large_displacements && l > 0.0 ? std::max(0.0, force) / l : 0.0;
    link.stiffness = axial_stiffness / length;
    link.force = force;
    return link;
}

double BoltLink::force_after(const Eigen::VectorXd& d) const {
    double elongation = 0.0;
    for (int a = 0; a < 6; ++a)
        for (int dir = 0; dir < 2; ++dir) elongation += g[2 * a + dir] * d[2 * nodes[a] + dir];
    return force + stiffness * elongation;
}

void BoltLink::add_forces(const Eigen::VectorXd& d, Eigen::VectorXd& out) const {
    const double n = force_after(d);
    double sideways = 0.0;
    for (int a = 0; a < 6; ++a)
        for (int dir = 0; dir < 2; ++dir) sideways += h[2 * a + dir] * d[2 * nodes[a] + dir];
    for (int a = 0; a < 6; ++a)
        for (int dir = 0; dir < 2; ++dir)
            out[2 * nodes[a] + dir] -= n * g[2 * a + dir] + geometric * sideways * h[2 * a + dir];
}

}  // namespace mcdda

#include "geometry/JointSets.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

namespace {

/// Clips the line p + t·d to the box (Liang–Barsky); false when it misses the box.
bool clip_line(Point2 p, Point2 d, const std::array<double, 4>& box, Point2& a, Point2& b) {
    double t0 = -1e300, t1 = 1e300;
    const double lo[2] = {box[0], box[1]}, hi[2] = {box[2], box[3]};
    const double origin[2] = {p.x, p.y}, dir[2] = {d.x, d.y};
    for (int k = 0; k < 2; ++k) {
        if (std::fabs(dir[k]) < 1e-14) {
            if (origin[k] < lo[k] || origin[k] > hi[k]) return false;
            continue;
        }
        double ta = (lo[k] - origin[k]) / dir[k], tb = (hi[k] - origin[k]) / dir[k];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (!(t1 > t0)) return false;
    a = {p.x + t0 * d.x, p.y + t0 * d.y};
    b = {p.x + t1 * d.x, p.y + t1 * d.y};
    return true;
}

}  // namespace

void expand_joint_sets(Model& model) {
    model.joints.erase(std::remove_if(model.joints.begin(), model.joints.end(),
                                      [](const Joint& j) { return j.joint_set >= 0; }),
                       model.joints.end());
    const std::array<double, 4> model_box = model.bounds();
    for (std::size_t s = 0; s < model.joint_sets.size(); ++s) {
        const JointSet& set = model.joint_sets[s];
        if (!(set.spacing > 0.0)) continue;  // reported by the validator
        std::array<double, 4> box = set.extent.value_or(model_box);
        // A margin keeps traces off the outer boundary itself, where they would cut nothing.
        const double margin = 1e-6 * std::hypot(box[2] - box[0], box[3] - box[1]);
        box = {box[0] - margin, box[1] - margin, box[2] + margin, box[3] + margin};
        const Point2 d{std::cos(set.angle), std::sin(set.angle)};
        const Point2 n{-d.y, d.x};
        double lo = 1e300, hi = -1e300;
        for (double x : {box[0], box[2]})
            for (double y : {box[1], box[3]}) {
                const double t = (x - set.origin.x) * n.x + (y - set.origin.y) * n.y;
                lo = std::min(lo, t);
                hi = std::max(hi, t);
            }
        const long first = static_cast<long>(std::ceil(lo / set.spacing));
        const long last = static_cast<long>(std::floor(hi / set.spacing));
        if (last - first > 5000) continue;  // reported by the validator
        int counter = 0;
        for (long k = first; k <= last; ++k) {
            const Point2 p{set.origin.x + k * set.spacing * n.x, set.origin.y + k * set.spacing * n.y};
            Point2 a, b;
            if (!clip_line(p, d, box, a, b)) continue;
            Joint j;
            j.name = set.name + " #" + std::to_string(++counter);
            j.points = {a, b};
            j.joint_material = set.joint_material;
            j.joint_set = static_cast<int>(s);
            model.joints.push_back(std::move(j));
        }
    }
}

}  // namespace mcdda

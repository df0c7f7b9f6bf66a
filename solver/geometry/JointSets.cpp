#include "geometry/JointSets.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace mcdda {

namespace {

/// Parameters t0 < t1 where the line p + t·d crosses the box (Liang–Barsky); false when it
/// misses the box.
bool clip_parameters(Point2 p, Point2 d, const std::array<double, 4>& box, double& t0, double& t1) {
    t0 = -1e300;
    t1 = 1e300;
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
    return t1 > t0;
}

/// Clips the line p + t·d to the box; false when it misses the box.
bool clip_line(Point2 p, Point2 d, const std::array<double, 4>& box, Point2& a, Point2& b) {
    double t0, t1;
    if (!clip_parameters(p, d, box, t0, t1)) return false;
    a = {p.x + t0 * d.x, p.y + t0 * d.y};
    b = {p.x + t1 * d.x, p.y + t1 * d.y};
    return true;
}

Joint generated_joint(const JointSet& set, int set_index, int number, Point2 a, Point2 b) {
    Joint j;
    j.name = set.name + " #" + std::to_string(number);
    j.points = {a, b};
    j.joint_material = set.joint_material;
    j.joint_set = set_index;
    return j;
}

/// The joint segments of a set with persistence < 1 on the trace p + t·d (t = 0 at the projection
/// of the set's origin), trace number k. Segments are cut to `exact_box`; a segment reaching an
/// edge of that box runs on to `margin_box`, as a full trace does. Appends to `out`; false when
/// the set would exceed max_joint_set_segments.
bool append_segments(const JointSet& set, int set_index, long k, Point2 p, Point2 d,
                     const std::array<double, 4>& exact_box, const std::array<double, 4>& margin_box,
                     double tolerance, std::vector<Joint>& out) {
    double u0, u1, t0, t1;
    // A trace that only grazes the margin would give slivers, not joints.
    if (!clip_parameters(p, d, exact_box, u0, u1) || !clip_parameters(p, d, margin_box, t0, t1)) return true;
    const double length = set.trace_length;
    const double period = length / set.persistence;
    // Far too many segments (or segment numbers beyond a long): the validator refuses the set.
    if (!((u1 - u0) / period <= max_joint_set_segments && std::fabs(u0) / period < 1e15 && std::fabs(u1) / period < 1e15))
        return false;
    // Only the fractional part of k·stagger matters; taking it keeps far traces exact.
    double phase = static_cast<double>(k) * set.stagger;
    phase -= std::floor(phase);
    const double shift = phase * period;
    const long m_first = static_cast<long>(std::floor((u0 - shift - length) / period));
    const long m_last = static_cast<long>(std::ceil((u1 - shift) / period));
    for (long m = m_first; m <= m_last; ++m) {
        const double start = shift + static_cast<double>(m) * period, end = start + length;
        if (!(std::min(end, u1) - std::max(start, u0) > tolerance)) continue;  // no piece inside the box
        const double from = start <= u0 + tolerance ? t0 : start;
        const double to = end >= u1 - tolerance ? t1 : end;
        if (static_cast<long>(out.size()) >= max_joint_set_segments) return false;
        out.push_back(generated_joint(set, set_index, static_cast<int>(out.size()) + 1,
                                      {p.x + from * d.x, p.y + from * d.y}, {p.x + to * d.x, p.y + to * d.y}));
    }
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
        const bool bridged = set.persistence < 1.0;
        if (bridged && !(set.persistence > 0.0 && set.trace_length > 0.0 && set.stagger >= 0.0 && set.stagger < 1.0))
            continue;  // reported by the validator
        const std::array<double, 4> exact_box = set.extent.value_or(model_box);
        // A margin keeps traces off the outer boundary itself, where they would cut nothing.
        const double diagonal = std::hypot(exact_box[2] - exact_box[0], exact_box[3] - exact_box[1]);
        const double margin = 1e-6 * diagonal;
        const std::array<double, 4> box = {exact_box[0] - margin, exact_box[1] - margin, exact_box[2] + margin,
                                           exact_box[3] + margin};
        const Point2 d{std::cos(set.angle), std::sin(set.angle)};
        const Point2 n{-d.y, d.x};
        double lo = 1e300, hi = -1e300;
        for (double x : {box[0], box[2]})
            for (double y : {box[1], box[3]}) {
                const double t = (x - set.origin.x) * n.x + (y - set.origin.y) * n.y;
                lo = std::min(lo, t);
                hi = std::max(hi, t);
            }
        // Counted in floating point before any trace number is made a long: over an extent of
        // 1e25 m the numbers overflowed, and the loop below never ended.
        if (!((hi - lo) / set.spacing <= static_cast<double>(max_joint_set_traces)) ||
            !(std::fabs(lo / set.spacing) < 1e15 && std::fabs(hi / set.spacing) < 1e15))
            continue;  // reported by the validator
        const long first = static_cast<long>(std::ceil(lo / set.spacing));
        const long last = static_cast<long>(std::floor(hi / set.spacing));
        std::vector<Joint> generated;
        bool within_limit = true;
        for (long k = first; k <= last && within_limit; ++k) {
            const Point2 p{set.origin.x + k * set.spacing * n.x, set.origin.y + k * set.spacing * n.y};
            if (bridged) {
                within_limit = append_segments(set, static_cast<int>(s), k, p, d, exact_box, box, 1e-9 * diagonal,
                                               generated);
                continue;
            }
            Point2 a, b;
            if (!clip_line(p, d, box, a, b)) continue;
            generated.push_back(generated_joint(set, static_cast<int>(s), static_cast<int>(generated.size()) + 1, a, b));
        }
        if (!within_limit) continue;  // reported by the validator
        model.joints.insert(model.joints.end(), std::make_move_iterator(generated.begin()),
                            std::make_move_iterator(generated.end()));
    }
}

}  // namespace mcdda

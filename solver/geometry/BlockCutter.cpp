#include "geometry/BlockCutter.hpp"

#include "geometry/BlockFeatures.hpp"
#include "geometry/PolygonChecks.hpp"
#include "model/Model.hpp"

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <unordered_map>

namespace mcdda {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
// Each curve carries its source: id ≥ 0 is a joint, id < 0 is the boundary of region −id−1.
// Consolidated data merges the ids of curves that overlap (a joint along a region boundary).
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, int>;
using Arrangement = CGAL::Arrangement_2<Traits>;
using Curve = Traits::Curve_2;
using FaceHandle = Arrangement::Face_const_handle;
using Halfedge = Arrangement::Halfedge_const_handle;

int region_id(int r) { return -r - 1; }

void add_ring(std::vector<Curve>& curves, const Ring& ring, int id) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point2& a = ring[i];
        const Point2& b = ring[(i + 1) % ring.size()];
        curves.emplace_back(Kernel::Segment_2({a.x, a.y}, {b.x, b.y}), id);
    }
}

/// The regions whose boundary contains the edge: crossing it toggles membership of each.
std::vector<int> regions_of(Halfedge e) {
    std::vector<int> out;
    for (auto it = e->curve().data().begin(); it != e->curve().data().end(); ++it)
        if (*it < 0) out.push_back(-*it - 1);
    return out;
}

std::vector<int> joints_of(Halfedge e) {
    std::vector<int> out;
    for (auto it = e->curve().data().begin(); it != e->curve().data().end(); ++it)
        if (*it >= 0) out.push_back(*it);
    std::sort(out.begin(), out.end());
    return out;
}

/// Membership (sorted region indices) of every face, found by walking from the unbounded face:
/// crossing an edge of region r's boundary (outer ring or hole) toggles being inside r.
std::map<const void*, std::vector<int>> face_membership(const Arrangement& arr) {
    std::map<const void*, std::vector<int>> inside;
    std::queue<FaceHandle> queue;
    inside[&*arr.unbounded_face()] = {};
    queue.push(arr.unbounded_face());
    auto visit_ccb = [&](Arrangement::Ccb_halfedge_const_circulator first, const std::vector<int>& here) {
        auto c = first;
        do {
            const FaceHandle other = c->twin()->face();
            if (!inside.count(&*other)) {
                std::vector<int> next = here;
                for (int r : regions_of(c)) {
                    const auto it = std::find(next.begin(), next.end(), r);
                    if (it == next.end()) next.push_back(r); else next.erase(it);
                }
                std::sort(next.begin(), next.end());
                inside[&*other] = next;
                queue.push(other);
            }
        } while (++c != first);
    };
    while (!queue.empty()) {
        const FaceHandle f = queue.front();
        queue.pop();
        const std::vector<int> here = inside[&*f];
        if (!f->is_unbounded()) visit_ccb(f->outer_ccb(), here);
        for (auto h = f->inner_ccbs_begin(); h != f->inner_ccbs_end(); ++h) visit_ccb(*h, here);
    }
    return inside;
}

Point2 to_point(const Arrangement::Point_2& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

/// A boundary ring of a block from one CCB, skipping halfedges that have the block on both sides
/// (dangling joint pieces); empty if nothing is left.
void ccb_ring(Arrangement::Ccb_halfedge_const_circulator first, Ring& ring, std::vector<EdgeTag>& tags) {
    auto c = first;
    do {
        if (c->twin()->face() != c->face()) {
            ring.push_back(to_point(c->source()->point()));
            EdgeTag tag;
            const auto joints = joints_of(c);
            if (!joints.empty()) tag.joint = joints.front();
            const auto regions = regions_of(c);
            if (!regions.empty()) tag.region_boundary = *std::min_element(regions.begin(), regions.end());
            tags.push_back(tag);
        }
    } while (++c != first);
}

/// The joint edges of a boundary cycle with the same face on both sides (dangling ends, traces
/// floating in the block), once each: the block's cracks.
void add_cracks(Arrangement::Ccb_halfedge_const_circulator first, std::vector<Block::Crack>& out) {
    auto c = first;
    do {
        // The cycle passes such an edge in both directions: the one from the lexicographically
        // smaller end (not the smaller address, which changes from run to run and with it the
        // order in which the mesher inserts the crack's ends, and so the mesh).
        if (c->twin()->face() == c->face() &&
            CGAL::compare_xy(c->source()->point(), c->target()->point()) == CGAL::SMALLER) {
            const auto joints = joints_of(c);
            if (!joints.empty()) out.push_back({to_point(c->source()->point()), to_point(c->target()->point()), joints.front()});
        }
    } while (++c != first);
}

std::vector<Point2> region_vertices(const Model& model) {
    std::vector<Point2> out;
    for (const Region& r : model.regions) {
        out.insert(out.end(), r.boundary.begin(), r.boundary.end());
        for (const Ring& h : r.holes) out.insert(out.end(), h.begin(), h.end());
    }
    return out;
}

/// The joints' polylines with every anchor (a region vertex, a point where joints meet) that
/// lies within `tolerance` of a joint made a vertex of it: a joint drawn through a corner (a
/// joint set through a tunnel's polygon) then passes exactly through it instead of a rounding
/// error away, which would leave an edge of 1e-16 m that no mesher can resolve. The joint moves
/// by less than the tolerance.
std::vector<std::vector<Point2>> joints_through_anchors(const Model& model, const std::vector<Point2>& anchors,
                                                        double tolerance) {
    std::vector<std::vector<Point2>> out;
    out.reserve(model.joints.size());
    if (anchors.empty() || !(tolerance > 0.0)) {
        for (const Joint& j : model.joints) out.push_back(j.points);
        return out;
    }
    Point2 low = anchors.front(), high = low;
    for (const Point2& p : anchors) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    // Anchors binned in cells sized so that there are about as many cells as anchors.
    const double extent = std::max(high.x - low.x, high.y - low.y);
    const double cell = std::max(extent / std::max(1.0, std::sqrt(static_cast<double>(anchors.size()))), 4.0 * tolerance);
    auto index = [&](double v, double origin) { return static_cast<long long>(std::floor((v - origin) / cell)); };
    // Cell indices packed into one key, unsigned (a neighbour of the first cell has index −1;
    // shifting a negative number left is undefined).
    auto key = [](long long i, long long j) {
        return (static_cast<unsigned long long>(i) << 32) ^ (static_cast<unsigned long long>(j) & 0xffffffffULL);
    };
    std::unordered_map<unsigned long long, std::vector<int>> bins;
    for (std::size_t k = 0; k < anchors.size(); ++k) bins[key(index(anchors[k].x, low.x), index(anchors[k].y, low.y))].push_back(static_cast<int>(k));
    for (const Joint& joint : model.joints) {
        // The polyline's points and the anchors near each segment, in order along it.
        std::vector<std::pair<Point2, bool>> sequence;  // point, is an anchor
        for (std::size_t s = 0; s < joint.points.size(); ++s) {
            const Point2 a = joint.points[s];
            sequence.push_back({a, false});
            if (s + 1 == joint.points.size()) break;
            const Point2 b = joint.points[s + 1];
            const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
            if (!(length2 > 0.0)) continue;
            std::vector<std::pair<double, int>> near;  // position along the segment, anchor
            std::set<int> seen;
            const int pieces = static_cast<int>(std::ceil(std::sqrt(length2) / cell)) + 1;
            for (int p = 0; p <= pieces; ++p) {
                const double t = static_cast<double>(p) / pieces;
                const long long i = index(a.x + t * dx, low.x), j = index(a.y + t * dy, low.y);
                for (long long di = -1; di <= 1; ++di)
                    for (long long dj = -1; dj <= 1; ++dj) {
                        const auto it = bins.find(key(i + di, j + dj));
                        if (it == bins.end()) continue;
                        for (int k : it->second) {
                            if (!seen.insert(k).second) continue;
                            const Point2 q = anchors[k];
                            const double u = std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / length2, 0.0, 1.0);
                            if (std::hypot(q.x - (a.x + u * dx), q.y - (a.y + u * dy)) < tolerance) near.push_back({u, k});
                        }
                    }
            }
            std::sort(near.begin(), near.end());
            for (const auto& [u, k] : near) sequence.push_back({anchors[k], true});
        }
        // Points closer than the tolerance merge, into the anchor where there is one.
        std::vector<Point2> path;
        bool last_is_anchor = false;
        for (const auto& [q, is_anchor] : sequence) {
            if (!path.empty() && std::hypot(q.x - path.back().x, q.y - path.back().y) < tolerance) {
                if (is_anchor && !last_is_anchor) {
                    path.back() = q;
                    last_is_anchor = true;
                }
                continue;
            }
            path.push_back(q);
            last_is_anchor = is_anchor;
        }
        out.push_back(std::move(path));
    }
    return out;
}

/// One point (the mean) for each cluster of arrangement vertices closer than `tolerance` to one
/// another, leaving out clusters with a region vertex (joints near one already pass through it:
/// such a cluster is two regions' vertices, which stay as drawn); empty when there is none.
std::vector<Point2> near_coincident_vertices(const Arrangement& arr, const std::vector<Point2>& region_points,
                                             double tolerance) {
    std::vector<Point2> points;
    points.reserve(arr.number_of_vertices());
    for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) points.push_back(to_point(v->point()));
    if (points.empty()) return {};
    // Vertices binned in cells of the tolerance, counted from the lowest corner (the model is a
    // million tolerances across, whatever its coordinates): a close pair lies in neighbouring cells.
    Point2 low = points.front(), high = low;
    for (const Point2& p : points) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    // Joints reaching far beyond the rock: cell numbers would overflow, and at that range a
    // tolerance this fine is below the coordinates' own resolution.
    if (!(std::max(high.x - low.x, high.y - low.y) < 1e12 * tolerance)) return {};
    auto cell_x = [&](double v) { return static_cast<long long>(std::floor((v - low.x) / tolerance)); };
    auto cell_y = [&](double v) { return static_cast<long long>(std::floor((v - low.y) / tolerance)); };
    std::map<std::pair<long long, long long>, std::vector<int>> bins;
    for (std::size_t k = 0; k < points.size(); ++k) bins[{cell_x(points[k].x), cell_y(points[k].y)}].push_back(static_cast<int>(k));
    std::vector<int> parent(points.size());
    for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = static_cast<int>(k);
    auto root = [&](int k) {
        while (parent[k] != k) k = parent[k] = parent[parent[k]];
        return k;
    };
    bool any = false;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const long long i = cell_x(points[k].x), j = cell_y(points[k].y);
        for (long long di = -1; di <= 1; ++di)
            for (long long dj = -1; dj <= 1; ++dj) {
                const auto it = bins.find({i + di, j + dj});
                if (it == bins.end()) continue;
                for (int m : it->second)
                    if (m > static_cast<int>(k) &&
                        std::hypot(points[m].x - points[k].x, points[m].y - points[k].y) < tolerance) {
                        parent[root(m)] = root(static_cast<int>(k));
                        any = true;
                    }
            }
    }
    if (!any) return {};
    std::set<std::pair<double, double>> fixed;
    for (const Point2& p : region_points) fixed.insert({p.x, p.y});
    struct Cluster {
        Point2 sum{0.0, 0.0};
        int count = 0;
        bool fixed = false;
    };
    std::map<int, Cluster> clusters;  // by root
    for (std::size_t k = 0; k < points.size(); ++k) {
        Cluster& c = clusters[root(static_cast<int>(k))];
        c.sum = {c.sum.x + points[k].x, c.sum.y + points[k].y};
        ++c.count;
        c.fixed = c.fixed || fixed.count({points[k].x, points[k].y});
    }
    std::vector<Point2> out;
    for (const auto& [r, c] : clusters)
        if (c.count > 1 && !c.fixed) out.push_back({c.sum.x / c.count, c.sum.y / c.count});
    return out;
}

}  // namespace

std::vector<Block> cut_blocks(const Model& model, std::vector<Diagnostic>& diagnostics) {
    // The arrangement's size grows with the crossings of the joint sets: every pair of
    // non-parallel sets crosses at most (segments of one) × (segments of the other) times, and
    // each crossing makes a block corner that needs triangles. More crossings than the mesh may
    // have elements cannot end in a mesh; refuse before spending minutes and gigabytes on them.
    std::vector<double> set_segments(model.joint_sets.size(), 0.0);
    for (const Joint& j : model.joints)
        if (j.joint_set >= 0 && j.joint_set < static_cast<int>(set_segments.size()))
            set_segments[j.joint_set] += static_cast<double>(std::max<std::size_t>(1, j.points.size() - 1));
    double crossings = 0.0;
    for (std::size_t a = 0; a < set_segments.size(); ++a)
        for (std::size_t b = a + 1; b < set_segments.size(); ++b)
            if (std::fabs(std::sin(model.joint_sets[a].angle - model.joint_sets[b].angle)) > 1e-9)
                crossings += set_segments[a] * set_segments[b];
    if (crossings > static_cast<double>(model.mesh.max_elements)) {
        std::ostringstream text;
        text << "the joint sets may cross up to " << crossings << " times, each crossing a block corner, more than "
             << "the mesh may have elements (mesh.max_elements " << model.mesh.max_elements
             << "): widen the spacing, limit the sets' extent, or raise mesh.max_elements";
        diagnostics.push_back({Diagnostic::Severity::Error, "/joint_sets", text.str()});
        return {};
    }
    std::vector<Curve> curves;
    for (std::size_t r = 0; r < model.regions.size(); ++r) {
        add_ring(curves, model.regions[r].boundary, region_id(static_cast<int>(r)));
        for (const Ring& h : model.regions[r].holes) add_ring(curves, h, region_id(static_cast<int>(r)));
    }
    const auto box = model.bounds();
    const double size = std::hypot(box[2] - box[0], box[3] - box[1]);
    const double tolerance = smallest_feature_ratio * size;
    const std::size_t region_curves = curves.size();
    auto add_joints = [&](const std::vector<Point2>& anchors) {
        curves.resize(region_curves);
        const auto joint_paths = joints_through_anchors(model, anchors, tolerance);
        for (std::size_t j = 0; j < model.joints.size(); ++j) {
            const auto& pts = joint_paths[j];
            for (std::size_t k = 1; k < pts.size(); ++k) {
                if (pts[k].x == pts[k - 1].x && pts[k].y == pts[k - 1].y) continue;
                curves.emplace_back(Kernel::Segment_2({pts[k - 1].x, pts[k - 1].y}, {pts[k].x, pts[k].y}),
                                    static_cast<int>(j));
            }
        }
    };
    std::vector<Point2> anchors = region_vertices(model);
    add_joints(anchors);
    Arrangement arr;
    CGAL::insert(arr, curves.begin(), curves.end());
    // Joints drawn through one point (three or more) meet there only up to rounding: exactly,
    // their crossings are a few points 1e-15 m apart, and the cut a sliver block. Such crossings
    // become one point that every joint passes through, and the joints are cut again.
    const std::vector<Point2> meeting = near_coincident_vertices(arr, anchors, tolerance);
    if (!meeting.empty()) {
        anchors.insert(anchors.end(), meeting.begin(), meeting.end());
        add_joints(anchors);
        arr.clear();
        CGAL::insert(arr, curves.begin(), curves.end());
    }

    const auto inside = face_membership(arr);

    // Overlapping regions: a face inside two regions at once.
    // (The first few pairs are named: a thousand copies of one region are half a million pairs.)
    constexpr std::size_t named_overlaps = 10;
    std::set<std::pair<int, int>> overlaps;
    bool more_overlaps = false;
    for (auto f = arr.faces_begin(); f != arr.faces_end() && !more_overlaps; ++f) {
        const auto& in = inside.at(&*f);
        for (std::size_t a = 0; a < in.size() && !more_overlaps; ++a)
            for (std::size_t b = a + 1; b < in.size(); ++b) {
                overlaps.insert({in[a], in[b]});
                if (overlaps.size() > named_overlaps) {
                    more_overlaps = true;
                    break;
                }
            }
    }
    std::size_t named = 0;
    for (const auto& [a, b] : overlaps) {
        if (++named > named_overlaps) break;
        diagnostics.push_back({Diagnostic::Severity::Error, "/regions/" + std::to_string(b),
                               "region \"" + model.regions[b].name + "\" overlaps region \"" +
                                   model.regions[a].name + "\" (/regions/" + std::to_string(a) + ")"});
    }
    if (more_overlaps)
        diagnostics.push_back({Diagnostic::Severity::Error, "/regions", "more regions overlap (the first " +
                                                                            std::to_string(named_overlaps) + " pairs are named)"});
    if (!overlaps.empty()) return {};

    // A joint with no piece in any region is a mistake; the pieces that separate no blocks (they
    // end in the rock, or float in it) become cracks inside their block (add_cracks).
    std::vector<char> in_region(model.joints.size(), 0);
    for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e)
        if (!inside.at(&*e->face()).empty() || !inside.at(&*e->twin()->face()).empty())
            for (int j : joints_of(e)) in_region[j] = 1;
    for (std::size_t j = 0; j < model.joints.size(); ++j)
        if (model.joints[j].joint_set < 0 && !in_region[j])
            diagnostics.push_back({Diagnostic::Severity::Error, joint_path(model, static_cast<int>(j)),
                                   "joint \"" + model.joints[j].name + "\" lies outside every region"});

    std::vector<Block> blocks;
    for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
        if (f->is_unbounded()) continue;
        const auto& in = inside.at(&*f);
        if (in.size() != 1) continue;
        Block b;
        b.region = in.front();
        b.material = model.regions[b.region].material;
        b.tags.emplace_back();
        ccb_ring(f->outer_ccb(), b.outer, b.tags.back());
        add_cracks(f->outer_ccb(), b.cracks);
        for (auto h = f->inner_ccbs_begin(); h != f->inner_ccbs_end(); ++h) {
            add_cracks(*h, b.cracks);
            Ring ring;
            std::vector<EdgeTag> tags;
            ccb_ring(*h, ring, tags);
            if (ring.size() < 3) continue;  // a joint trace floating inside the block
            b.holes.push_back(std::move(ring));
            b.tags.push_back(std::move(tags));
        }
        b.area = signed_area(b.outer);
        for (const Ring& h : b.holes) b.area += signed_area(h);  // holes are clockwise
        blocks.push_back(std::move(b));
    }
    // A stable order (by region, then lowest-left vertex) so block numbers do not depend on
    // the arrangement's internal order.
    auto key = [](const Block& b) {
        Point2 low = b.outer.front();
        for (const Point2& p : b.outer)
            if (p.y < low.y || (p.y == low.y && p.x < low.x)) low = p;
        return std::make_tuple(b.region, low.y, low.x);
    };
    std::stable_sort(blocks.begin(), blocks.end(), [&](const Block& a, const Block& b) { return key(a) < key(b); });
    return blocks;
}

}  // namespace mcdda

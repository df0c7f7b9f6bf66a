#include "geometry/PolygonChecks.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <cmath>

namespace mcdda {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using P = Kernel::Point_2;
using Segment = Kernel::Segment_2;

std::vector<P> to_cgal(const Ring& ring) {
    std::vector<P> out;
    out.reserve(ring.size());
    for (const Point2& p : ring) out.emplace_back(p.x, p.y);
    return out;
}

/// Exact test whether any edge of ring a touches any edge of ring b (bounding boxes first).
bool rings_touch(const std::vector<P>& a, const std::vector<P>& b) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Segment sa(a[i], a[(i + 1) % a.size()]);
        const auto ba = sa.bbox();
        for (std::size_t k = 0; k < b.size(); ++k) {
            const Segment sb(b[k], b[(k + 1) % b.size()]);
            if (CGAL::do_overlap(ba, sb.bbox()) && CGAL::do_intersect(sa, sb)) return true;
        }
    }
    return false;
}

/// Why the ring is unusable, or empty when it is fine.
std::string ring_problem(const std::vector<P>& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i)
        if (ring[i] == ring[(i + 1) % ring.size()])
            return "vertex " + std::to_string((i + 1) % ring.size()) + " repeats vertex " + std::to_string(i);
    bool collinear = true;
    for (std::size_t i = 2; i < ring.size() && collinear; ++i) collinear = CGAL::collinear(ring[0], ring[1], ring[i]);
    if (collinear) return "the polygon has zero area (all vertices on one line)";
    if (!CGAL::is_simple_2(ring.begin(), ring.end(), Kernel()))
        return "the polygon intersects itself";
    return {};
}

}  // namespace

double signed_area(const Ring& ring) {
    double twice = 0.0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point2& a = ring[i];
        const Point2& b = ring[(i + 1) % ring.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * twice;
}

bool region_contains(const Region& r, Point2 p) {
    const P q(p.x, p.y);
    const auto outer = to_cgal(r.boundary);
    if (outer.size() < 3 || CGAL::bounded_side_2(outer.begin(), outer.end(), q, Kernel()) != CGAL::ON_BOUNDED_SIDE)
        return false;
    for (const Ring& h : r.holes) {
        const auto hole = to_cgal(h);
        if (hole.size() >= 3 && CGAL::bounded_side_2(hole.begin(), hole.end(), q, Kernel()) != CGAL::ON_UNBOUNDED_SIDE)
            return false;
    }
    return true;
}

void check_region_rings(const Model& model, std::vector<Diagnostic>& diagnostics) {
    auto error = [&](const std::string& path, const std::string& message) {
        diagnostics.push_back({Diagnostic::Severity::Error, path, message});
    };
    for (std::size_t i = 0; i < model.regions.size(); ++i) {
        const Region& region = model.regions[i];
        const std::string path = "/regions/" + std::to_string(i);
        const std::string name = " of region \"" + region.name + "\"";
        if (region.boundary.size() < 3) continue;  // reported by the validator
        const auto outer = to_cgal(region.boundary);
        const std::string outer_problem = ring_problem(outer);
        if (!outer_problem.empty()) {
            error(path + "/boundary", "boundary" + name + ": " + outer_problem);
            continue;
        }
        std::vector<std::vector<P>> holes;
        for (std::size_t h = 0; h < region.holes.size(); ++h) {
            const std::string hpath = path + "/holes/" + std::to_string(h);
            if (region.holes[h].size() < 3) continue;
            auto hole = to_cgal(region.holes[h]);
            const std::string problem = ring_problem(hole);
            if (!problem.empty()) {
                error(hpath, "hole " + std::to_string(h) + name + ": " + problem);
                continue;
            }
            if (rings_touch(outer, hole) ||
                CGAL::bounded_side_2(outer.begin(), outer.end(), hole.front(), Kernel()) != CGAL::ON_BOUNDED_SIDE) {
                error(hpath, "hole " + std::to_string(h) + name + " is not strictly inside the region's boundary");
                continue;
            }
            for (std::size_t k = 0; k < holes.size(); ++k) {
                if (rings_touch(holes[k], hole) ||
                    CGAL::bounded_side_2(holes[k].begin(), holes[k].end(), hole.front(), Kernel()) != CGAL::ON_UNBOUNDED_SIDE ||
                    CGAL::bounded_side_2(hole.begin(), hole.end(), holes[k].front(), Kernel()) != CGAL::ON_UNBOUNDED_SIDE) {
                    error(hpath, "hole " + std::to_string(h) + name + " overlaps or touches another hole of the same region");
                    break;
                }
            }
            holes.push_back(std::move(hole));
        }
    }
}

}  // namespace mcdda

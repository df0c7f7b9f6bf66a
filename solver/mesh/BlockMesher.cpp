#include "mesh/BlockMesher.hpp"

#include "mesh/SizeField.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <list>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

namespace mcdda {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using Fb = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using CgalPoint = Kernel::Point_2;

/// Mesh_2 criteria: the shape bound of Delaunay_mesh_criteria_2 plus a size bound that varies
/// over the plane (CGAL's own size criteria has one constant bound). Same structure as
/// CGAL::Delaunay_mesh_size_criteria_2, whose Quality ordering it copies.
class SizeFieldCriteria {
public:
    using Face_handle = CDT::Face_handle;

    struct Quality : public std::pair<double, double> {
        Quality() = default;
        Quality(double sine, double size) : std::pair<double, double>(sine, size) {}
        double size() const { return second; }
        double sine() const { return first; }
        bool operator<(const Quality& q) const {  // q1 < q2: q1 is refined first
            if (size() > 1) return q.size() > 1 ? size() > q.size() : true;
            if (q.size() > 1) return false;
            return sine() < q.sine();
        }
    };

    /// Faces with a longest edge below this fraction of the local size are not refined for their
    /// shape.
    static constexpr double smallest_refined = 1e-3;

    class Is_bad {
    public:
        Is_bad(double squared_sine_bound, const SizeField* field) : bound_(squared_sine_bound), field_(field) {}
        CGAL::Mesh_2::Face_badness operator()(const Quality& q) const {
            if (q.size() > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
            return q.sine() < bound_ ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
        }
        CGAL::Mesh_2::Face_badness operator()(const Face_handle& fh, Quality& q) const {
            const CgalPoint& pa = fh->vertex(0)->point();
            const CgalPoint& pb = fh->vertex(1)->point();
            const CgalPoint& pc = fh->vertex(2)->point();
            double l[3] = {CGAL::squared_distance(pb, pc), CGAL::squared_distance(pc, pa), CGAL::squared_distance(pa, pb)};
            std::sort(l, l + 3);
            const Point2 centroid{(pa.x() + pb.x() + pc.x()) / 3.0, (pa.y() + pb.y() + pc.y()) / 3.0};
            const double h = (*field_)(centroid);
            q.second = l[2] / (h * h);
            if (q.size() > 1) {
                q.first = 1;
                return CGAL::Mesh_2::IMPERATIVELY_BAD;
            }
            // A face a thousand times below the size it is asked for sits in an input angle too
            // sharp for the angle bound (two cracks meeting at a fraction of a degree): refining it
            // for its shape would go on until the constructions break down (CGAL's mesher then
            // crashes). It is kept as it is.
            if (l[2] < smallest_refined * smallest_refined * h * h) {
                q.first = 1;
                return CGAL::Mesh_2::NOT_BAD;
            }
            const double area2 = 2.0 * CGAL::area(pa, pb, pc);
            q.first = area2 * area2 / (l[2] * l[1]);  // squared sine of the smallest angle
            return q.sine() < bound_ ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
        }

    private:
        double bound_;
        const SizeField* field_;
    };

    SizeFieldCriteria(double min_angle, const SizeField& field)
        : bound_(std::pow(std::sin(min_angle), 2)), field_(&field) {}
    Is_bad is_bad_object() const { return Is_bad(bound_, field_); }

private:
    double bound_;
    const SizeField* field_;
};

bool ring_contains(const Ring& ring, Point2 p) {
    bool inside = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Point2& a = ring[i];
        const Point2& b = ring[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

bool block_contains(const Block& b, Point2 p) {
    if (!ring_contains(b.outer, p)) return false;
    for (const Ring& h : b.holes)
        if (ring_contains(h, p)) return false;
    return true;
}

/// One point inside every hole of the constrained triangulation: a face centroid from each
/// component at even nesting depth ≥ 2 (depth counts constraints crossed from infinity).
std::list<CgalPoint> hole_seeds(CDT& cdt) {
    std::list<CgalPoint> seeds;
    std::unordered_map<CDT::Face_handle, int> depth;
    std::vector<CDT::Face_handle> frontier{cdt.infinite_face()};
    depth[cdt.infinite_face()] = 0;
    // Breadth over depths: flood each depth through unconstrained edges, queue across constraints.
    for (int level = 0; !frontier.empty(); ++level) {
        std::vector<CDT::Face_handle> next;
        while (!frontier.empty()) {
            CDT::Face_handle start = frontier.back();
            frontier.pop_back();
            if (depth[start] != level) continue;
            bool first_of_component = true;
            std::vector<CDT::Face_handle> stack{start};
            while (!stack.empty()) {
                CDT::Face_handle f = stack.back();
                stack.pop_back();
                if (first_of_component && level >= 2 && level % 2 == 0 && !cdt.is_infinite(f)) {
                    seeds.push_back(CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
                    first_of_component = false;
                }
                for (int i = 0; i < 3; ++i) {
                    CDT::Face_handle n = f->neighbor(i);
                    if (depth.count(n)) continue;
                    if (cdt.is_constrained({f, i})) {
                        next.push_back(n);
                    } else {
                        depth[n] = level;
                        stack.push_back(n);
                    }
                }
            }
        }
        for (CDT::Face_handle n : next)
            if (!depth.count(n)) {
                depth[n] = level + 1;
                frontier.push_back(n);
            }
    }
    return seeds;
}

void insert_ring(CDT& cdt, const Ring& ring) {
    std::vector<CDT::Vertex_handle> v;
    v.reserve(ring.size());
    for (const Point2& p : ring) v.push_back(cdt.insert(CgalPoint(p.x, p.y)));
    for (std::size_t i = 0; i < v.size(); ++i)
        if (v[i] != v[(i + 1) % v.size()]) cdt.insert_constraint(v[i], v[(i + 1) % v.size()]);
}

/// The free ends of a block's cracks (crack_tips), each with the length of the crack piece it
/// ends.
using CrackTips = std::map<std::pair<double, double>, double>;

/// Inserts the block's cracks as constraints inside it. A crack piece with both ends free in the
/// rock goes in as two halves: a crack must have a node between its tips to open at all (its
/// tips are not doubled).
void insert_cracks(CDT& cdt, const Block& block, const CrackTips& tips) {
    auto is_tip = [&](Point2 p) { return tips.count({p.x, p.y}) != 0; };
    for (const Block::Crack& c : block.cracks) {
        const CDT::Vertex_handle a = cdt.insert(CgalPoint(c.from.x, c.from.y));
        const CDT::Vertex_handle b = cdt.insert(CgalPoint(c.to.x, c.to.y));
        if (a == b) continue;
        if (is_tip(c.from) && is_tip(c.to)) {
            const CDT::Vertex_handle m = cdt.insert(CgalPoint(0.5 * (c.from.x + c.to.x), 0.5 * (c.from.y + c.to.y)));
            cdt.insert_constraint(a, m);
            cdt.insert_constraint(m, b);
        } else {
            cdt.insert_constraint(a, b);
        }
    }
}

/// Splits every mesh vertex on a crack into one node per sector of the triangles around it, the
/// sectors being separated by crack edges (constrained edges with the block on both sides): a
/// vertex inside a crack gets two nodes, a crack's tip one (the rock is continuous beyond it), a
/// crack's mouth on the block outline two, a crossing of two cracks four. `triangle_of` maps each
/// face of the block to its triangle in `mesh`; the new nodes are appended to `mesh` for block
/// `block`.
void split_crack_vertices(const CDT& cdt, const std::vector<CDT::Face_handle>& faces,
                          const std::unordered_map<CDT::Face_handle, int>& triangle_of, Mesh& mesh, int block) {
    auto inside = [&](CDT::Face_handle f) { return !cdt.is_infinite(f) && f->is_in_domain(); };
    auto is_crack = [&](CDT::Face_handle f, int i) {
        return cdt.is_constrained({f, i}) && inside(f) && inside(f->neighbor(i));
    };
    // Vertices on cracks, in the faces' order (a deterministic numbering of the new nodes).
    std::vector<CDT::Vertex_handle> on_crack;
    std::unordered_map<CDT::Vertex_handle, char> seen;
    for (const CDT::Face_handle& f : faces)
        for (int i = 0; i < 3; ++i)
            if (is_crack(f, i))
                for (const CDT::Vertex_handle v : {f->vertex(CDT::cw(i)), f->vertex(CDT::ccw(i))})
                    if (seen.emplace(v, 1).second) on_crack.push_back(v);
    for (const CDT::Vertex_handle v : on_crack) {
        std::vector<CDT::Face_handle> around;
        auto fc = cdt.incident_faces(v), done = fc;
        do around.push_back(fc); while (++fc != done);
        const std::size_t n = around.size();
        // Two faces in turn around v are joined unless one is outside the block or the edge
        // between them is a crack or the outline.
        auto joined = [&](std::size_t k) {
            const CDT::Face_handle f = around[k], g = around[(k + 1) % n];
            return inside(f) && inside(g) && !cdt.is_constrained({f, f->index(g)});
        };
        std::size_t start = 0;
        while (start < n && joined(start)) ++start;
        if (start == n) continue;  // no break around v: nothing to split
        int sector = -1, node = -1;
        bool open = false;  // the current sector has its node
        for (std::size_t step = 1; step <= n; ++step) {
            const std::size_t k = (start + step) % n;
            if (!joined((k + n - 1) % n)) open = false;
            const CDT::Face_handle f = around[k];
            if (!inside(f)) continue;
            auto& tri = mesh.triangles[triangle_of.at(f)];
            const int corner = f->index(v);
            if (!open) {
                ++sector;
                open = true;
                if (sector == 0) {
                    node = tri[corner];
                } else {
                    node = static_cast<int>(mesh.nodes.size());
                    mesh.nodes.push_back(mesh.nodes[tri[corner]]);
                    mesh.node_block.push_back(block);
                }
            }
            tri[corner] = node;
        }
    }
}

/// The ends of the block's cracks that lie free in the rock: on no other crack and not on the
/// block's outline.
CrackTips crack_tips(const Block& block) {
    std::map<std::pair<double, double>, std::pair<int, double>> ends;  // end → pieces, shortest length
    for (const Block::Crack& c : block.cracks) {
        const double length = std::hypot(c.to.x - c.from.x, c.to.y - c.from.y);
        for (const Point2& p : {c.from, c.to}) {
            auto& [count, shortest] = ends.try_emplace({p.x, p.y}, 0, length).first->second;
            ++count;
            shortest = std::min(shortest, length);
        }
    }
    std::set<std::pair<double, double>> outline;
    for (const Point2& p : block.outer) outline.insert({p.x, p.y});
    for (const Ring& h : block.holes)
        for (const Point2& p : h) outline.insert({p.x, p.y});
    CrackTips tips;
    for (const auto& [p, end] : ends)
        if (end.first == 1 && !outline.count(p)) tips.emplace(p, end.second);
    return tips;
}

/// Element size at a crack tip, as a fraction of the crack piece's length: the mesh resolves the
/// opening's square-root profile near the tip, and a short crack is never one element.
constexpr double crack_tip_size_fraction = 0.1;

/// The size field of one block: the model's, or its region's uniform size where the region has
/// one (a stiff structure need not follow the refinement of the ground it stands on), finer
/// towards the tips of its cracks.
SizeField block_size_field(const Model& model, const Block& block, const SizeField& model_field, const CrackTips& tips) {
    double region_size =
        block.region >= 0 && block.region < static_cast<int>(model.regions.size()) ? model.regions[block.region].mesh_size : 0.0;
    if (region_size > 0.0) {
        // Not beyond the block's extent: a size a thousand times the block's edges would leave
        // its triangles unrefined for their shape (the refinement's rule for faces far below the
        // size asked, SizeFieldCriteria), below the minimum angle.
        double box[4] = {1e300, 1e300, -1e300, -1e300};
        for (const Point2& p : block.outer) {
            box[0] = std::min(box[0], p.x); box[1] = std::min(box[1], p.y);
            box[2] = std::max(box[2], p.x); box[3] = std::max(box[3], p.y);
        }
        region_size = std::min(region_size, std::hypot(box[2] - box[0], box[3] - box[1]));
    }
    MeshControls controls = model.mesh;
    if (region_size > 0.0) controls.local.clear();
    for (const auto& [at, length] : tips) {
        const Point2 tip{at.first, at.second};
        const double size = crack_tip_size_fraction * length;
        if (size < (region_size > 0.0 ? region_size : model_field(tip))) controls.local.push_back({tip, tip, size, 0.0});
    }
    return SizeField(controls, region_size > 0.0 ? region_size : model_field.global_size());
}

/// Blocks that need more triangles than this are seeded before refinement (below).
constexpr double seeded_block_triangles = 100000;

/// Points for the interior of a large block: the centres of the leaves of a quadtree over its
/// bounding box, each leaf no wider than 0.63 h at its centre (so the square grid they form
/// triangulates into edges no longer than h), only where that width fits h closely (where the
/// size is uniform), leaves within about a leaf of the boundary left out. Inserted (spatially
/// sorted) before Delaunay refinement, they leave the refiner the boundary layer and the zones
/// where the size grades: its queue of bad faces, ordered over the whole block, made a
/// million-triangle block mesh at a fifth of the speed of many small ones.
class InteriorSeeds {
public:
    InteriorSeeds(const Block& block, const SizeField& field) : block_(block), field_(field) {
        auto add_ring = [&](const Ring& r) {
            for (std::size_t i = 0; i < r.size(); ++i) segments_.push_back({r[i], r[(i + 1) % r.size()]});
        };
        add_ring(block.outer);
        for (const Ring& h : block.holes) add_ring(h);
        // Cracks too: the seeds keep their distance from them as from the outline.
        for (const Block::Crack& c : block.cracks) segments_.push_back({c.from, c.to});
    }

    /// `sizes`: the sizes the field is uniform at somewhere (the global size, each local one).
    std::vector<CgalPoint> points(const std::vector<double>& sizes) {
        double box[4] = {1e300, 1e300, -1e300, -1e300};
        for (const Point2& p : block_.outer) {
            box[0] = std::min(box[0], p.x); box[1] = std::min(box[1], p.y);
            box[2] = std::max(box[2], p.x); box[3] = std::max(box[3], p.y);
        }
        // The root is a power of two of the leaf width that the size holding most of the block's
        // triangles asks for, so that leaves come out at exactly that width where it holds
        // (elsewhere only where the width happens to fit, below).
        const double extent = std::max(box[2] - box[0], box[3] - box[1]);
        double half = 0.5 * leaf_fraction * dominant_size(box, sizes);
        while (2.0 * half < extent) half *= 2.0;
        std::vector<int> all(segments_.size());
        for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
        visit({0.5 * (box[0] + box[2]), 0.5 * (box[1] + box[3])}, half, false, all, false);
        return std::move(points_);
    }

    /// Leaf width over the local size h: the square grid's diagonals (0.89 h) stay below h, and
    /// its triangles have the mean area of Delaunay refinement's to the same h (about 0.2 h²).
    static constexpr double leaf_fraction = 0.63;

private:
    struct Segment {
        Point2 a, b;
    };
    const Block& block_;
    const SizeField& field_;
    std::vector<Segment> segments_;
    std::vector<CgalPoint> points_;

    /// Of `sizes`, the one whose zone (where the field equals it) holds the most triangles,
    /// sampled on a 64 × 64 grid over the block's box.
    double dominant_size(const double box[4], const std::vector<double>& sizes) const {
        std::vector<double> weight(sizes.size(), 0.0);
        constexpr int n = 64;
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < n; ++k) {
                const Point2 p{box[0] + (i + 0.5) * (box[2] - box[0]) / n, box[1] + (k + 0.5) * (box[3] - box[1]) / n};
                if (!block_contains(block_, p)) continue;
                const double h = field_(p);
                for (std::size_t s = 0; s < sizes.size(); ++s)
                    if (std::fabs(h - sizes[s]) <= 1e-9 * sizes[s]) weight[s] += 1.0 / (h * h);
            }
        const auto best = std::max_element(weight.begin(), weight.end());
        return *best > 0.0 ? sizes[best - weight.begin()] : field_.global_size();
    }

    /// A cell of half-width r at c; `odd`: whether its column plus row on its level is odd, which
    /// its position within its parent decides, the parent's doubled column and row being even
    /// (the indices themselves overflowed 64 bits under a mesh size of 10³⁰⁸ m, a thousand
    /// levels above a local size: undefined behaviour); `near`: the boundary segments that may
    /// pass within reach of it; `inside`: the whole cell is known to lie inside the block, clear
    /// of the boundary.
    void visit(Point2 c, double r, bool odd, const std::vector<int>& near, bool inside) {
        const double h = field_(c);
        const double allowed = leaf_fraction * h * (1.0 + 1e-9);
        const bool leaf = 2.0 * r <= allowed;
        if (leaf) {
            // Seeds only where their spacing fits the size to within 10 %: the leaf's own width, or
            // every other centre (a chessboard's black squares: a grid turned by 45° with spacing
            // 2√2 r). Elsewhere (where the size grades) refinement alone fills in, so that the
            // mesh is as fine as refinement makes it, not finer.
            const double width = 2.0 * r;
            const bool fits = width >= 0.9 * allowed;
            const bool fits_turned = !fits && std::sqrt(2.0) * width <= allowed && std::sqrt(2.0) * width >= 0.9 * allowed;
            if (!fits && !(fits_turned && !odd)) return;
        }
        std::vector<int> closer;
        if (!inside) {
            // Reach: the cell's circumradius plus the clearance a leaf keeps from the boundary.
            const double reach = r * std::sqrt(2.0) + 2.0 * r;
            for (int s : near)
                if (distance_to_segment(c, segments_[s].a, segments_[s].b) <= reach) closer.push_back(s);
            if (closer.empty()) {
                if (!block_contains(block_, c)) return;  // wholly outside
                inside = true;
            }
        }
        if (leaf) {
            if (inside || (closer.empty() && block_contains(block_, c))) points_.emplace_back(c.x, c.y);
            else if (block_contains(block_, c)) {
                double clearance = 1e300;
                for (int s : closer) clearance = std::min(clearance, distance_to_segment(c, segments_[s].a, segments_[s].b));
                if (clearance > 1.5 * r) points_.emplace_back(c.x, c.y);
            }
            return;
        }
        const double q = 0.5 * r;
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx)
                visit({c.x + (dx ? q : -q), c.y + (dy ? q : -q)}, q, dx != dy, closer, inside);
    }
};

/// Triangles between cracks closer together than the size asked for there: the mesh between
/// them is as fine as their gap (the minimum angle forbids long thin triangles), as in a block
/// narrower than the size. A crack piece of length L whose nearest near-parallel neighbour lies
/// g < h away takes about L / (0.3 g) triangles in the strip between them where the size field
/// counted L g / (0.3 h²); each of the two pieces counts half. (A joint set of persistence 0.9
/// spaced 12 mm across the Lavarak cavern was estimated below the element limit and then meshed
/// for 28 s before refinement gave up.) Pieces are binned in a grid of cells no smaller than the
/// global size, which bounds the size asked anywhere: each piece looks at the cells around it.
template <typename SizeAt>
double crack_gap_triangles(const Block& b, const SizeAt& size_at, double global_size, double area_per_h2) {
    const std::vector<Block::Crack>& cracks = b.cracks;
    if (cracks.size() < 2) return 0.0;
    double box[4] = {1e300, 1e300, -1e300, -1e300};
    for (const Block::Crack& c : cracks)
        for (const Point2& p : {c.from, c.to}) {
            box[0] = std::min(box[0], p.x); box[1] = std::min(box[1], p.y);
            box[2] = std::max(box[2], p.x); box[3] = std::max(box[3], p.y);
        }
    const double extent = std::max(box[2] - box[0], box[3] - box[1]);
    if (!std::isfinite(extent) || !(global_size > 0.0)) return 0.0;
    const double cell = std::max({global_size, extent / 2048.0, 1e-12});
    const long long nx = static_cast<long long>((box[2] - box[0]) / cell) + 1;
    const long long ny = static_cast<long long>((box[3] - box[1]) / cell) + 1;
    const auto column = [&](double x) { return std::clamp(static_cast<long long>((x - box[0]) / cell), 0LL, nx - 1); };
    const auto row = [&](double y) { return std::clamp(static_cast<long long>((y - box[1]) / cell), 0LL, ny - 1); };
    // Each piece is binned where it passes (points half a cell apart, not its box: a long
    // diagonal crack would fill millions of cells); a search one cell wider than the size then
    // meets every piece passing within the size.
    std::unordered_map<long long, std::vector<int>> cells;
    for (std::size_t i = 0; i < cracks.size(); ++i) {
        const Block::Crack& c = cracks[i];
        const double length = std::hypot(c.to.x - c.from.x, c.to.y - c.from.y);
        const long long samples = static_cast<long long>(2.0 * length / cell) + 1;
        long long last = -1;
        for (long long k = 0; k <= samples; ++k) {
            const double t = static_cast<double>(k) / static_cast<double>(samples);
            const long long at = row(c.from.y + t * (c.to.y - c.from.y)) * nx + column(c.from.x + t * (c.to.x - c.from.x));
            if (at != last) cells[at].push_back(static_cast<int>(i));
            last = at;
        }
    }
    const auto same = [](const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; };
    constexpr double near_parallel_sine = 0.5;  // within 30°
    double extra = 0.0;
    for (std::size_t i = 0; i < cracks.size(); ++i) {
        const Block::Crack& c = cracks[i];
        const double length = std::hypot(c.to.x - c.from.x, c.to.y - c.from.y);
        if (!(length > 0.0)) continue;
        const Point2 mid{0.5 * (c.from.x + c.to.x), 0.5 * (c.from.y + c.to.y)};
        const double ux = (c.to.x - c.from.x) / length, uy = (c.to.y - c.from.y) / length;
        const double h = size_at(mid);
        double gap = h;
        std::set<int> seen;
        for (long long x = column(mid.x - h - cell); x <= column(mid.x + h + cell); ++x)
            for (long long y = row(mid.y - h - cell); y <= row(mid.y + h + cell); ++y) {
                const auto found = cells.find(y * nx + x);
                if (found == cells.end()) continue;
                for (int j : found->second) {
                    const Block::Crack& o = cracks[j];
                    if (!seen.insert(j).second || j == static_cast<int>(i) || same(o.from, c.from) || same(o.from, c.to) || same(o.to, c.from) ||
                        same(o.to, c.to))
                        continue;
                    const double olength = std::hypot(o.to.x - o.from.x, o.to.y - o.from.y);
                    if (!(olength > 0.0)) continue;
                    const double vx = (o.to.x - o.from.x) / olength, vy = (o.to.y - o.from.y) / olength;
                    if (std::fabs(ux * vy - uy * vx) > near_parallel_sine) continue;
                    // Only a neighbour beside the piece's middle bounds a strip with it.
                    const double along = (mid.x - o.from.x) * vx + (mid.y - o.from.y) * vy;
                    if (along < 0.0 || along > olength) continue;
                    const double d = std::fabs((mid.x - o.from.x) * vy - (mid.y - o.from.y) * vx);
                    if (d > 0.0) gap = std::min(gap, d);
                }
            }
        if (gap < h) extra += 0.5 * length * (1.0 / (area_per_h2 * gap) - gap / (area_per_h2 * h * h));
    }
    return extra;
}

}  // namespace

double estimate_triangle_count(const Model& model, const std::vector<Block>& blocks) {
    const SizeField model_field(model.mesh, resolved_global_size(model));
    // Refinement to a max-edge bound h gives triangles of about 0.3 h² on average.
    constexpr double area_per_h2 = 0.3;
    double count = 0.0;
    for (const Block& b : blocks) {
        double box[4] = {1e300, 1e300, -1e300, -1e300};
        for (const Point2& p : b.outer) {
            box[0] = std::min(box[0], p.x); box[1] = std::min(box[1], p.y);
            box[2] = std::max(box[2], p.x); box[3] = std::max(box[3], p.y);
        }
        // A block narrower than the size asked for is meshed at its width (the minimum angle
        // forbids long thin triangles): a sliver of width w and length L takes about L / w
        // triangles, whatever the size field says. 4 A / P measures the width: twice it for a
        // long strip, the side for a square.
        double perimeter = 0.0;
        const auto add_ring = [&perimeter](const Ring& ring) {
            for (std::size_t k = 0; k < ring.size(); ++k) {
                const Point2& p = ring[k];
                const Point2& q = ring[(k + 1) % ring.size()];
                perimeter += std::hypot(q.x - p.x, q.y - p.y);
            }
        };
        add_ring(b.outer);
        for (const Ring& h : b.holes) add_ring(h);
        const double width = perimeter > 0.0 ? 4.0 * b.area / perimeter : 0.0;
        // Thousands of cracks make the mesh fine at their tips all over the block.
        const SizeField field = block_size_field(model, b, model_field, crack_tips(b));
        const auto size_at = [&](const Point2& c) { return width > 0.0 ? std::min(field(c), width) : field(c); };
        constexpr int n = 24;
        const double dx = (box[2] - box[0]) / n, dy = (box[3] - box[1]) / n;
        double sampled = 0.0, inside_cells = 0.0;
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < n; ++k) {
                const Point2 c{box[0] + (i + 0.5) * dx, box[1] + (k + 0.5) * dy};
                if (!block_contains(b, c)) continue;
                const double h = size_at(c);
                sampled += 1.0 / (area_per_h2 * h * h);
                inside_cells += 1.0;
            }
        if (inside_cells > 0) count += b.area * sampled / inside_cells;
        else count += b.area / (area_per_h2 * std::pow(size_at(b.outer.front()), 2));
        count += crack_gap_triangles(b, size_at, field.global_size(), area_per_h2);
    }
    return count;
}

Mesh mesh_blocks(const Model& model, const std::vector<Block>& blocks, std::vector<Diagnostic>& diagnostics) {
    Mesh mesh;
    const double estimate = estimate_triangle_count(model, blocks);
    if (estimate > static_cast<double>(model.mesh.max_elements)) {
        std::ostringstream msg;
        msg.precision(3);
        msg << "the mesh would have about " << estimate << " triangles, above the limit of "
            << model.mesh.max_elements
            << " (blocks narrower than the mesh size, between joints closer together than it, are meshed at "
               "their width, and the mesh is finer towards crack tips; raise /mesh/max_elements, coarsen /mesh/size or space the joints wider)";
        diagnostics.push_back({Diagnostic::Severity::Error, "/mesh", msg.str()});
        return mesh;
    }
    const SizeField model_field(model.mesh, resolved_global_size(model));
    std::vector<double> uniform_sizes{model_field.global_size()};
    for (const LocalSize& l : model.mesh.local) uniform_sizes.push_back(l.size);
    for (const Region& r : model.regions)
        if (r.mesh_size > 0.0) uniform_sizes.push_back(r.mesh_size);
    const double smallest_size = *std::min_element(uniform_sizes.begin(), uniform_sizes.end());

    for (std::size_t bi = 0; bi < blocks.size(); ++bi) {
        const Block& block = blocks[bi];
        // The size field of the block: the model's or its region's, finer towards the tips of its
        // cracks.
        const CrackTips tips = crack_tips(block);
        const SizeField field = block_size_field(model, block, model_field, tips);
        const SizeFieldCriteria criteria(model.mesh.min_angle, field);
        CDT cdt;
        insert_ring(cdt, block.outer);
        for (const Ring& h : block.holes) insert_ring(cdt, h);
        const std::list<CgalPoint> seeds = hole_seeds(cdt);
        insert_cracks(cdt, block, tips);
        // (About two triangles per seed: only large blocks are seeded, so that the meshes of
        // smaller ones stay those of plain refinement. A block that could not hold that many
        // seeds even at the smallest size is not looked at: thousands of small blocks.)
        if (2.0 * block.area / std::pow(InteriorSeeds::leaf_fraction * smallest_size, 2) > seeded_block_triangles) {
            std::vector<CgalPoint> interior = InteriorSeeds(block, field).points(uniform_sizes);
            if (2.0 * static_cast<double>(interior.size()) > seeded_block_triangles)
                cdt.insert(interior.begin(), interior.end());
        }
        // Step by step, so that a refinement that cannot finish (a minimum angle near the
        // theoretical limit next to sharp corners) is stopped instead of running forever.
        CGAL::Delaunay_mesher_2<CDT, SizeFieldCriteria> mesher(cdt, criteria);
        mesher.set_seeds(seeds.begin(), seeds.end(), /*seeds in domain=*/false);
        mesher.init();
        const std::size_t vertex_budget = static_cast<std::size_t>(model.mesh.max_elements) + 1000;
        long steps = 0;
        while (!mesher.is_refinement_done()) {
            mesher.step_by_step_refine_mesh();
            if (++steps % 4096 == 0 && mesh.nodes.size() + cdt.number_of_vertices() > vertex_budget) {
                // Where refinement went furthest below the size asked for is where it got stuck.
                double worst = 0.0;
                Point2 where = block.outer.front();
                for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
                    if (!f->is_in_domain()) continue;
                    const CgalPoint& a = f->vertex(0)->point();
                    const CgalPoint& b = f->vertex(1)->point();
                    const CgalPoint& c = f->vertex(2)->point();
                    const Point2 centre{(a.x() + b.x() + c.x()) / 3.0, (a.y() + b.y() + c.y()) / 3.0};
                    const double longest = std::sqrt(std::max({CGAL::squared_distance(a, b), CGAL::squared_distance(b, c),
                                                               CGAL::squared_distance(c, a)}));
                    const double below = field(centre) / longest;
                    if (below > worst) {
                        worst = below;
                        where = centre;
                    }
                }
                std::ostringstream place;
                place.precision(6);
                place << "(" << where.x << ", " << where.y << ")";
                diagnostics.push_back({Diagnostic::Severity::Error, "/mesh",
                                       "refinement of block " + std::to_string(bi) + " (region \"" +
                                           model.regions[block.region].name +
                                           "\") exceeded the element limit, with its smallest triangles near " +
                                           place.str() +
                                           " (joints or cracks meeting at a sharp angle or passing close to "
                                           "each other there?); move them apart, lower /mesh/min_angle or raise "
                                           "/mesh/max_elements"});
                return Mesh{};
            }
        }

        std::unordered_map<CDT::Vertex_handle, int> node_of;
        std::vector<CDT::Face_handle> faces;
        std::unordered_map<CDT::Face_handle, int> triangle_of;
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            if (!f->is_in_domain()) continue;
            faces.push_back(f);
            triangle_of.emplace(f, static_cast<int>(mesh.triangles.size()));
            std::array<int, 3> tri{};
            for (int k = 0; k < 3; ++k) {
                const CDT::Vertex_handle v = f->vertex(k);
                auto it = node_of.find(v);
                if (it == node_of.end()) {
                    it = node_of.emplace(v, static_cast<int>(mesh.nodes.size())).first;
                    mesh.nodes.push_back({v->point().x(), v->point().y()});
                    mesh.node_block.push_back(static_cast<int>(bi));
                }
                tri[k] = it->second;
            }
            mesh.triangles.push_back(tri);
            mesh.triangle_block.push_back(static_cast<int>(bi));
            mesh.triangle_material.push_back(block.material);
        }
        if (!block.cracks.empty()) split_crack_vertices(cdt, faces, triangle_of, mesh, static_cast<int>(bi));
        mesh.block_node_begin.push_back(static_cast<int>(mesh.nodes.size()));
        mesh.block_triangle_begin.push_back(static_cast<int>(mesh.triangles.size()));
    }
    return mesh;
}

}  // namespace mcdda

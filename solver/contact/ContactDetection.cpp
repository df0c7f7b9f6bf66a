#include "contact/ContactDetection.hpp"

#include "parallel/ParallelFor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <unordered_map>

namespace mcdda {

double signed_gap(Point2 p, Point2 a, Point2 b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double l = std::hypot(dx, dy);
    return l > 0.0 ? ((p.x - a.x) * dy - (p.y - a.y) * dx) / l : 0.0;
}

namespace {

/// Boundary edges bucketed by the grid cells their (enlarged) bounding boxes cover.
class EdgeGrid {
public:
    EdgeGrid(const std::vector<Point2>& nodes, const MeshTopology& topology, double cell, double margin)
        : cell_(cell) {
        for (std::size_t e = 0; e < topology.edges.size(); ++e) {
            const Point2& a = nodes[topology.edges[e].from];
            const Point2& b = nodes[topology.edges[e].to];
            const long x0 = index(std::min(a.x, b.x) - margin), x1 = index(std::max(a.x, b.x) + margin);
            const long y0 = index(std::min(a.y, b.y) - margin), y1 = index(std::max(a.y, b.y) + margin);
            for (long i = x0; i <= x1; ++i)
                for (long k = y0; k <= y1; ++k) cells_[key(i, k)].push_back(static_cast<int>(e));
        }
    }
    const std::vector<int>* edges_near(Point2 p) const {
        const auto it = cells_.find(key(index(p.x), index(p.y)));
        return it == cells_.end() ? nullptr : &it->second;
    }

private:
    long index(double v) const { return static_cast<long>(std::floor(v / cell_)); }
    // Unsigned arithmetic: shifting a negative index (models with negative coordinates) left is
    // undefined behaviour (UBSan flagged it); the key stays one-to-one on the cell indices.
    static unsigned long long key(long i, long k) {
        return (static_cast<unsigned long long>(i) << 32) ^ (static_cast<unsigned long long>(k) & 0xffffffffULL);
    }
    double cell_;
    std::unordered_map<unsigned long long, std::vector<int>> cells_;
};

/// Whether segment (a, b) crosses segment (p, q) farther than `margin` from both p and q
/// (touching at an end, or lying along it, is not crossing). The margin keeps the blocks that
/// meet at a joint junction, whose edges pass within a step's displacement of p or q, from hiding
/// each other.
bool crosses_between(Point2 p, Point2 q, Point2 a, Point2 b, double margin) {
    const auto side = [](Point2 o, Point2 u, Point2 v) { return (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x); };
    const double ap = side(a, b, p), aq = side(a, b, q);
    if (!((ap > 0.0 && aq < 0.0) || (ap < 0.0 && aq > 0.0))) return false;
    const double pa = side(p, q, a), pb = side(p, q, b);
    if (!((pa > 0.0 && pb < 0.0) || (pa < 0.0 && pb > 0.0))) return false;
    const double t = ap / (ap - aq);  // where (a, b) crosses, along (p, q)
    const double length = std::hypot(q.x - p.x, q.y - p.y);
    return t * length > margin && (1.0 - t) * length > margin;
}

/// Whether p lies inside `block`: the parity of its boundary edges a ray from p towards +x
/// crosses. The two faces of a crack cross it together and cancel.
bool inside_block(Point2 p, const std::vector<Point2>& nodes, const MeshTopology& topology, int block) {
    bool inside = false;
    for (int e = topology.block_edge_begin[block]; e < topology.block_edge_begin[block + 1]; ++e) {
        const Point2& a = nodes[topology.edges[e].from];
        const Point2& b = nodes[topology.edges[e].to];
        if ((a.y > p.y) == (b.y > p.y)) continue;
        if (p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    }
    return inside;
}

/// Distance from p to the nearest of the `near` edges that belong to `block`.
double nearest_edge_distance(Point2 p, const std::vector<Point2>& nodes, const MeshTopology& topology,
                             const std::vector<int>& near, int block) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int e : near)
        if (topology.edges[e].block == block)
            nearest =
                std::min(nearest, distance_to_segment(p, nodes[topology.edges[e].from], nodes[topology.edges[e].to]));
    return nearest;
}

/// What the search of one node knows of one neighbouring block.
struct NeighbourBlock {
    int block = -1;
    int best_edge = -1;                              ///< nearest, then least penetrated (−1: none yet)
    std::pair<double, double> best_score{0.0, 0.0};  ///< its (distance, −gap)
    int inside = -1;                                 ///< whether the node lies inside the block (−1: not yet known)
    double nearest = -1.0;                           ///< distance to the block's nearest edge (negative: not yet known)
};

/// A new contact deeper than this share of the search distance must be with the vertex's nearest
/// edges of the block (see detect_contacts).
constexpr double deep_share = 0.01;

}  // namespace

std::vector<Contact> detect_contacts(const std::vector<Point2>& nodes, const Mesh& mesh, const MeshTopology& topology,
                                     double search_distance, const std::vector<Contact>& previous,
                                     const Eigen::VectorXd& expected_increment, double tolerance) {
    if (topology.edges.empty()) return {};
    double mean_edge = 0.0;
    for (const BoundaryEdge& e : topology.edges)
        mean_edge += std::hypot(nodes[e.to].x - nodes[e.from].x, nodes[e.to].y - nodes[e.from].y);
    mean_edge /= static_cast<double>(topology.edges.size());
    const EdgeGrid grid(nodes, topology, std::max(2.0 * mean_edge, 2.0 * search_distance), search_distance);

    // Outward normal of every boundary node: the mean of its two edges' normals (the block lies
    // left of its edges, so (dy, −dx) points out).
    std::vector<Point2> node_normal(nodes.size(), Point2{0.0, 0.0});
    for (const BoundaryEdge& e : topology.edges) {
        const double dx = nodes[e.to].x - nodes[e.from].x, dy = nodes[e.to].y - nodes[e.from].y;
        const double l = std::hypot(dx, dy);
        if (l == 0.0) continue;
        for (int n : {e.from, e.to}) {
            node_normal[n].x += dy / l;
            node_normal[n].y -= dx / l;
        }
    }

    // Nodes on a crack face may touch the crack's other face, in their own block.
    std::vector<char> on_crack(nodes.size(), 0);
    for (const BoundaryEdge& e : topology.edges)
        if (e.crack) on_crack[e.from] = on_crack[e.to] = 1;

    std::map<std::pair<int, int>, const Contact*> before;  // (node, edge block) → contact
    for (const Contact& c : previous) before[{c.node, c.edge_block}] = &c;

    const double touching = 1e-9 * topology.model_size;  // a vertex this near an edge lies on it

    // Boundary nodes are searched on the worker threads in contiguous ranges; the ranges' contacts
    // are joined in node order, the order of a serial search.
    std::vector<std::pair<int, std::vector<Contact>>> ranges;
    std::mutex ranges_mutex;
    const int boundary_nodes = static_cast<int>(topology.boundary_nodes.size());
    parallel_for(boundary_nodes, [&](int first, int last) {
        std::vector<Contact> contacts;
        std::vector<NeighbourBlock> neighbours;  // of the node in hand; reused, so as not to allocate per node
        for (int index = first; index < last; ++index) {
            const int node = topology.boundary_nodes[index];
            const std::vector<int>* near = grid.edges_near(nodes[node]);
            if (!near) continue;
            const int block = mesh.node_block[node];
            neighbours.clear();
            auto neighbour = [&neighbours](int b) -> NeighbourBlock& {
                for (NeighbourBlock& n : neighbours)
                    if (n.block == b) return n;
                neighbours.push_back(NeighbourBlock{b});
                return neighbours.back();
            };
            for (int e : *near) {
                const BoundaryEdge& edge = topology.edges[e];
                const Point2& a = nodes[edge.from];
                const Point2& b = nodes[edge.to];
                // Only a vertex that projects onto the edge can touch it: beyond its ends the edge's
                // line is no surface (a node of the same plane just past a block's corner would
                // otherwise lock against the block's extended face). The cheapest test, and the
                // one that turns most of a cell's edges away, comes first: every test here only
                // turns an edge away, so their order changes nothing else.
                const double len2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
                const double xi = len2 > 0.0 ? ((nodes[node].x - a.x) * (b.x - a.x) + (nodes[node].y - a.y) * (b.y - a.y)) / len2 : 0.0;
                if (xi < -1e-6 || xi > 1.0 + 1e-6) continue;
                if (edge.block == block) {
                    // Within a block only the faces of its cracks touch: a node of one face against
                    // an edge of the other (or of a crossing crack), never an edge of the node's
                    // own, and never from a crack's tip, whose two edges face opposite ways.
                    if (!edge.crack || !on_crack[node] || edge.from == node || edge.to == node) continue;
                    const Point2 vn = node_normal[node];
                    if (std::hypot(vn.x, vn.y) < 0.5) continue;
                }
                const double distance = distance_to_segment(nodes[node], a, b);
                if (distance > search_distance) continue;
                const double gap = signed_gap(nodes[node], a, b);
                if (gap < -search_distance) continue;  // deep behind the edge: another edge is meant
                // Blocks never start a step overlapping: a vertex well behind an edge it did not touch
                // before is on the far side of a thin block (a sliver where a joint meets a
                // boundary), not touching it. (Such vertices, locked at 0.17–0.25 m penetration, put
                // GPa stresses into the jointed-tunnel example.)
                // Nor does a vertex behind an edge penetrate its block unless it is inside the block:
                // behind a short edge of a sliver, below the sliver's tip, it is outside (a 1 cm
                // sliver where a joint meets a boundary locked a vertex at 2.2 cm, and every try of
                // the step failed), and at a joint junction a vertex just outside a block's acute
                // corner is behind the edge beside the corner by µm. Such a vertex takes the edge
                // it is nearest to from outside, if any.
                if (gap < -touching) {
                    const auto held = before.find({node, edge.block});
                    if (held == before.end() || held->second->edge != e) {  // not the edge it had
                        if (gap < -0.1 * search_distance) continue;
                        if (edge.block != block) {
                            NeighbourBlock& n = neighbour(edge.block);
                            if (n.inside < 0) n.inside = inside_block(nodes[node], nodes, topology, edge.block) ? 1 : 0;
                            if (n.inside == 0) continue;
                            // Inside by a centimetre or more, it is nearer to some edge of the block than
                            // to this one, at a tip of the block where the nearer edges do not face it: a
                            // vertex of the 500-vertex zigzag joint of a fuzzed jointed tunnel, at a
                            // 2.75° tooth of a neighbouring block, lay "inside" it by parity and took an
                            // edge 2 cm off (3 such contacts; every try of the step failed, past 240 s).
                            if (gap < -deep_share * search_distance) {
                                if (n.nearest < 0.0)
                                    n.nearest = nearest_edge_distance(nodes[node], nodes, topology, *near, edge.block);
                                if (n.nearest < -0.5 * gap) continue;
                            }
                        }
                    }
                }
                // Shi's entrance rule, simplified: a vertex can only enter an edge it faces. A vertex
                // on a flat stretch of boundary next to another block's corner must not take that
                // block's side face (it would resist sliding along the joint): their normals are
                // perpendicular. The threshold −0.05 still lets the tip of a wedge as sharp as 6°
                // (normal · edge normal = −sin(θ/2)) touch the faces beside it.
                const double l = std::hypot(b.x - a.x, b.y - a.y);
                const Point2 vn = node_normal[node];
                const double vl = std::hypot(vn.x, vn.y);
                if (l > 0.0 && vl > 0.0 && ((b.y - a.y) * vn.x - (b.x - a.x) * vn.y) / (l * vl) > -0.05) continue;
                const auto score = std::make_pair(distance, -gap);
                NeighbourBlock& n = neighbour(edge.block);
                if (n.best_edge < 0 || score < n.best_score) {
                    n.best_score = score;
                    n.best_edge = e;
                }
            }
            // Contacts in the order of the neighbouring blocks (a few per node).
            std::sort(neighbours.begin(), neighbours.end(),
                      [](const NeighbourBlock& x, const NeighbourBlock& y) { return x.block < y.block; });
            for (const NeighbourBlock& n : neighbours) {
                if (n.best_edge < 0) continue;
                const int edge_block = n.block;
                // A block behind another cannot be touched through it: the segment from the node
                // to its nearest point on the edge must not cross a third block's edge. Without
                // this rule every node of a thin wedge or sliver (joints fanned or crossing at a
                // small angle) took contacts with all blocks within the search distance, coupling
                // them into a nearly dense matrix (10 joints fanned 0.38° apart across the Kirsch
                // plate: 1 s per factorisation of 13,000 elements).
                const BoundaryEdge& chosen = topology.edges[n.best_edge];
                const Point2 a = nodes[chosen.from], b = nodes[chosen.to], p = nodes[node];
                const double len2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
                const double t = len2 > 0.0 ? std::clamp(((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / len2, 0.0, 1.0) : 0.0;
                const Point2 q{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
                bool hidden = false;
                for (int e : *near) {
                    const BoundaryEdge& other = topology.edges[e];
                    if (other.block == block || other.block == edge_block) continue;
                    if (crosses_between(p, q, nodes[other.from], nodes[other.to], 0.1 * search_distance)) {
                        hidden = true;
                        break;
                    }
                }
                if (hidden) continue;
                Contact c;
                c.node = node;
                c.edge = n.best_edge;
                c.edge_block = edge_block;
                const auto it = before.find({node, edge_block});
                if (it != before.end()) {
                    const Contact& old = *it->second;
                    c.state = old.state;
                    c.slip = old.slip;
                    c.intact = old.intact;
                    c.shear_spring = old.shear_spring;
                    c.slip_total = old.slip_total;
                    c.gap_found = old.gap_found;
                    c.normal_force = old.normal_force;
                    c.shear_force = old.shear_force;
                } else {
                    const BoundaryEdge& edge = topology.edges[c.edge];
                    const Point2 a = nodes[edge.from], b = nodes[edge.to], p = nodes[node];
                    const double gap = signed_gap(p, a, b);
                    c.state = gap <= 1e-9 * topology.model_size ? ContactState::Locked : ContactState::Open;
                    c.gap_found = std::max(0.0, gap);
                    if (c.state == ContactState::Locked && expected_increment.size() > 0) {
                        const double l = std::hypot(b.x - a.x, b.y - a.y);
                        const double tx = (b.x - a.x) / l, ty = (b.y - a.y) / l;
                        const double xi = std::clamp(((p.x - a.x) * tx + (p.y - a.y) * ty) / l, 0.0, 1.0);
                        const auto& u = expected_increment;
                        const double slip = (u[2 * node] - (1 - xi) * u[2 * edge.from] - xi * u[2 * edge.to]) * tx +
                                            (u[2 * node + 1] - (1 - xi) * u[2 * edge.from + 1] - xi * u[2 * edge.to + 1]) * ty;
                        if (std::fabs(slip) > tolerance) {
                            c.state = ContactState::Sliding;
                            c.slip = slip > 0 ? 1 : -1;
                            c.intact = false;
                        }
                    }
                }
                contacts.push_back(c);
            }
        }
        const std::lock_guard<std::mutex> lock(ranges_mutex);
        ranges.emplace_back(first, std::move(contacts));
    });
    std::sort(ranges.begin(), ranges.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<Contact> contacts;
    for (auto& [first, part] : ranges) contacts.insert(contacts.end(), part.begin(), part.end());
    return contacts;
}

}  // namespace mcdda

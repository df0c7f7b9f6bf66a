#include "fem/MeshTopology.hpp"

#include "mesh/QuadraticMesh.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

namespace {

/// What a boundary edge of the mesh lies on.
struct EdgeSource {
    int joint = -1;
    bool crack = false;
};

/// The block ring edge or crack that contains the mesh edge (a, b): its joint tag, and whether
/// it is a crack face.
EdgeSource source_of(const Block& block, Point2 a, Point2 b, double tolerance) {
    const Point2 mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
    double best = 1e300;
    EdgeSource source;
    auto search = [&](const Ring& ring, const std::vector<EdgeTag>& tags) {
        for (std::size_t k = 0; k < ring.size(); ++k) {
            const double d = distance_to_segment(mid, ring[k], ring[(k + 1) % ring.size()]);
            if (d < best) {
                best = d;
                source = {tags[k].joint, false};
            }
        }
    };
    search(block.outer, block.tags[0]);
    for (std::size_t h = 0; h < block.holes.size(); ++h) search(block.holes[h], block.tags[h + 1]);
    for (const Block::Crack& c : block.cracks) {
        const double d = distance_to_segment(mid, c.from, c.to);
        if (d < best) {
            best = d;
            source = {c.joint, true};
        }
    }
    return best <= tolerance ? source : EdgeSource{};
}

}  // namespace

MeshTopology build_topology(const Mesh& mesh, const std::vector<Block>& blocks) {
    MeshTopology t;
    const std::size_t n = mesh.nodes.size();
    t.edge_into.assign(n, -1);
    t.edge_out_of.assign(n, -1);
    t.midside_node.assign(n, 0);
    double box[4] = {1e300, 1e300, -1e300, -1e300};
    for (const Point2& p : mesh.nodes) {
        box[0] = std::min(box[0], p.x); box[1] = std::min(box[1], p.y);
        box[2] = std::max(box[2], p.x); box[3] = std::max(box[3], p.y);
    }
    t.model_size = n ? std::hypot(box[2] - box[0], box[3] - box[1]) : 1.0;
    const double tolerance = 1e-6 * t.model_size;

    // An edge used by one triangle is on its block's boundary (blocks share no nodes, so no edge
    // is used by two blocks). On a six-node mesh the midside node identifies the edge.
    std::vector<int> uses;
    std::vector<int> edge_id;
    if (mesh.quadratic()) {
        uses.assign(n, 0);
        for (const auto& m : mesh.midside)
            for (int node : m) {
                ++uses[node];
                t.midside_node[node] = 1;
            }
    } else {
        int edge_count = 0;
        edge_id = number_edges(mesh, edge_count);
        uses.assign(edge_count, 0);
        for (int id : edge_id) ++uses[id];
    }
    auto link = [&](int from, int to, int block, EdgeSource source) {
        t.edge_out_of[from] = static_cast<int>(t.edges.size());
        t.edge_into[to] = static_cast<int>(t.edges.size());
        t.edges.push_back({from, to, block, source.joint, source.crack});
    };
    t.block_edge_begin.assign(static_cast<std::size_t>(mesh.block_count()) + 1, 0);
    for (int b = 0; b < mesh.block_count(); ++b) {
        t.block_edge_begin[b] = static_cast<int>(t.edges.size());
        for (int e = mesh.block_triangle_begin[b]; e < mesh.block_triangle_begin[b + 1]; ++e)
            for (int k = 0; k < 3; ++k) {
                const int m = mesh.quadratic() ? mesh.midside[e][k] : -1;
                if (uses[m >= 0 ? m : edge_id[3 * e + k]] != 1) continue;
                // Counter-clockwise triangles give the edge the direction with the block on the left.
                const int i = mesh.triangles[e][k], j = mesh.triangles[e][(k + 1) % 3];
                const EdgeSource source = b < static_cast<int>(blocks.size())
                                              ? source_of(blocks[b], mesh.nodes[i], mesh.nodes[j], tolerance)
                                              : EdgeSource{};
                if (m < 0) {
                    link(i, j, b, source);
                } else {
                    link(i, m, b, source);
                    link(m, j, b, source);
                }
            }
    }
    t.block_edge_begin[mesh.block_count()] = static_cast<int>(t.edges.size());
    for (std::size_t i = 0; i < n; ++i)
        if (t.edge_out_of[i] >= 0) t.boundary_nodes.push_back(static_cast<int>(i));
    return t;
}

int nearest_node(const Mesh& mesh, Point2 p) {
    int best = -1;
    double best_d = 1e300;
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
        const double d = std::hypot(mesh.nodes[i].x - p.x, mesh.nodes[i].y - p.y);
        if (d < best_d) {
            best_d = d;
            best = static_cast<int>(i);
        }
    }
    return best;
}

}  // namespace mcdda

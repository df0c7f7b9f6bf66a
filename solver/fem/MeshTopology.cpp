#include "fem/MeshTopology.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace mcdda {

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    const double t = len2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

namespace {

/// The joint tag of the block ring edge that contains the mesh edge (a, b).
int joint_of(const Block& block, Point2 a, Point2 b, double tolerance) {
    const Point2 mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
    auto search = [&](const Ring& ring, const std::vector<EdgeTag>& tags) -> std::pair<double, int> {
        std::pair<double, int> best{1e300, -1};
        for (std::size_t k = 0; k < ring.size(); ++k) {
            const double d = distance_to_segment(mid, ring[k], ring[(k + 1) % ring.size()]);
            if (d < best.first) best = {d, tags[k].joint};
        }
        return best;
    };
    auto best = search(block.outer, block.tags[0]);
    for (std::size_t h = 0; h < block.holes.size(); ++h) {
        const auto candidate = search(block.holes[h], block.tags[h + 1]);
        if (candidate.first < best.first) best = candidate;
    }
    return best.first <= tolerance ? best.second : -1;
}

}  // namespace

MeshTopology build_topology(const Mesh& mesh, const std::vector<Block>& blocks) {
    MeshTopology t;
    const std::size_t n = mesh.nodes.size();
    t.edge_into.assign(n, -1);
    t.edge_out_of.assign(n, -1);
    double box[4] = {1e300, 1e300, -1e300, -1e300};
    for (const Point2& p : mesh.nodes) {
        box[0] = std::min(box[0], p.x); box[1] = std::min(box[1], p.y);
        box[2] = std::max(box[2], p.x); box[3] = std::max(box[3], p.y);
    }
    t.model_size = n ? std::hypot(box[2] - box[0], box[3] - box[1]) : 1.0;
    const double tolerance = 1e-6 * t.model_size;

    for (int b = 0; b < mesh.block_count(); ++b) {
        // An edge used by one triangle of the block is on its boundary; counter-clockwise
        // triangles give it the direction with the block on the left.
        std::map<std::pair<int, int>, int> count;
        for (int e = mesh.block_triangle_begin[b]; e < mesh.block_triangle_begin[b + 1]; ++e)
            for (int k = 0; k < 3; ++k) {
                const int i = mesh.triangles[e][k], j = mesh.triangles[e][(k + 1) % 3];
                count[{std::min(i, j), std::max(i, j)}]++;
            }
        for (int e = mesh.block_triangle_begin[b]; e < mesh.block_triangle_begin[b + 1]; ++e)
            for (int k = 0; k < 3; ++k) {
                const int i = mesh.triangles[e][k], j = mesh.triangles[e][(k + 1) % 3];
                if (count[{std::min(i, j), std::max(i, j)}] != 1) continue;
                BoundaryEdge edge{i, j, b, -1};
                if (b < static_cast<int>(blocks.size()))
                    edge.joint = joint_of(blocks[b], mesh.nodes[i], mesh.nodes[j], tolerance);
                t.edge_out_of[i] = static_cast<int>(t.edges.size());
                t.edge_into[j] = static_cast<int>(t.edges.size());
                t.edges.push_back(edge);
            }
    }
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

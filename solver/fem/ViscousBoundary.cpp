#include "fem/ViscousBoundary.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace mcdda {

ViscousBoundary::ViscousBoundary(const Model& model, const Mesh& mesh, const MeshTopology& topology,
                                 const std::vector<char>& active) {
    std::vector<std::pair<std::array<Point2, 2>, bool>> segments;
    for (const AbsorbingBoundary& a : model.absorbing_boundaries) segments.push_back({{a.from, a.to}, false});
    if (model.base_motion.kind == BaseMotion::Kind::Compliant)
        segments.push_back({{model.base_motion.from, model.base_motion.to}, true});
    if (segments.empty()) return;
    // The element beside each boundary half-edge gives the material (its corner or midside nodes).
    std::vector<std::vector<int>> elements_of(mesh.nodes.size());
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        if (!active.empty() && !active[e]) continue;
        for (int n : mesh.triangles[e]) elements_of[n].push_back(static_cast<int>(e));
        if (mesh.quadratic())
            for (int n : mesh.midside[e]) elements_of[n].push_back(static_cast<int>(e));
    }
    auto element_of = [&](int a, int b) {
        for (int e : elements_of[a])
            for (int f : elements_of[b])
                if (e == f) return e;
        return -1;
    };
    const double tolerance = 1e-6 * topology.model_size;
    std::map<int, Dashpot> at_node;
    for (const BoundaryEdge& edge : topology.edges) {
        if (edge.crack) continue;
        const Point2 p = mesh.nodes[edge.from], q = mesh.nodes[edge.to];
        for (const auto& [segment, input] : segments) {
            if (distance_to_segment(p, segment[0], segment[1]) > tolerance ||
                distance_to_segment(q, segment[0], segment[1]) > tolerance)
                continue;
            const int e = element_of(edge.from, edge.to);
            if (e < 0) continue;  // an absent block's edge
            const Material& m = model.materials[mesh.triangle_material[e]];
            const double length = std::hypot(q.x - p.x, q.y - p.y);
            const Eigen::Vector2d s((q.x - p.x) / length, (q.y - p.y) / length), n(s.y(), -s.x());
            const Eigen::Matrix2d c = m.density * (pressure_wave_speed(m) * n * n.transpose() +
                                                   shear_wave_speed(m) * s * s.transpose());
            const bool half = !topology.midside_node.empty() &&
                              (topology.midside_node[edge.from] || topology.midside_node[edge.to]);
            for (int node : {edge.from, edge.to}) {
                const double share = !half ? 0.5 : topology.midside_node[node] ? 2.0 / 3.0 : 1.0 / 3.0;
                Dashpot& d = at_node[node];
                d.node = node;
                d.c += share * length * c;
                if (input) d.input_c += share * length * c;
                d.input = d.input || input;
            }
            break;  // one segment's dashpots per edge
        }
    }
    for (auto& [node, d] : at_node) dashpots_.push_back(d);
}

void ViscousBoundary::add_forces(const Eigen::VectorXd& d, double rate, const Eigen::VectorXd& v_rest,
                                 const Eigen::Vector2d& incident, Eigen::VectorXd& r) const {
    for (const Dashpot& p : dashpots_) {
        const Eigen::Index x = 2 * p.node;
        const Eigen::Vector2d v(rate * d[x] + v_rest[x], rate * d[x + 1] + v_rest[x + 1]);
        Eigen::Vector2d f = p.c * v;
        if (p.input) f -= 2.0 * p.input_c * incident;
        r[x] -= f.x();
        r[x + 1] -= f.y();
    }
}

}  // namespace mcdda

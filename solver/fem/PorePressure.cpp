#include "fem/PorePressure.hpp"

#include "fem/TriangleElement.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

namespace {

/// ∫Bᵀ m u dV of one element with the element's own integration rule (exact for the linear u
/// of a straight line: B is constant (T3) or linear (T6), u linear).
template <int N>
void add_element_forces(const Water& water, const Mesh& mesh, const std::vector<Point2>& nodes, int e, double factor,
                        Eigen::VectorXd& f) {
    using Element = TriangleElement<N>;
    const auto& t = mesh.triangles[e];
    const typename Element::Geometry g = Element::geometry(nodes[t[0]], nodes[t[1]], nodes[t[2]]);
    typename Element::Forces fe = Element::Forces::Zero();
    bool wet = false;
    for (int q = 0; q < Element::points; ++q) {
        const double u = water.pore_pressure(integration_point(mesh, nodes, e, q));
        if (u == 0.0) continue;
        wet = true;
        fe += g.weight(q) * u * (g.B[q].row(0) + g.B[q].row(1)).transpose();
    }
    if (!wet) return;
    for (int a = 0; a < N; ++a) {
        const int node = a < 3 ? t[a] : mesh.midside[e][a - 3];
        f[2 * node] += factor * fe[2 * a];
        f[2 * node + 1] += factor * fe[2 * a + 1];
    }
}

/// The parameters t in (0, 1) of the segment a + t(b − a) where the pore pressure's formula
/// changes (a vertex of the line, the line itself), in order, with 0 and 1 around them.
std::vector<double> pieces(const Water& water, Point2 a, Point2 b) {
    std::vector<double> t{0.0, 1.0};
    const double dx = b.x - a.x;
    if (dx != 0.0) {
        // Only the line's vertices over the edge (x increasing: found by bisection, so a line of
        // many thousand points costs no more per edge than one of three).
        const std::vector<Point2>& line = water.piezometric_line;
        const auto by_x = [](const Point2& p, double x) { return p.x < x; };
        const auto first = std::lower_bound(line.begin(), line.end(), std::min(a.x, b.x), by_x);
        for (auto v = first; v != line.end() && v->x <= std::max(a.x, b.x); ++v) {
            const double s = (v->x - a.x) / dx;
            if (s > 0.0 && s < 1.0) t.push_back(s);
        }
    }
    std::sort(t.begin(), t.end());
    // Within each piece the height of the line above the segment is linear: where it changes
    // sign, the water surface crosses the edge.
    const std::size_t n = t.size();
    for (std::size_t k = 0; k + 1 < n; ++k) {
        auto head = [&](double s) { return water.level(a.x + s * dx) - (a.y + s * (b.y - a.y)); };
        const double h0 = head(t[k]), h1 = head(t[k + 1]);
        if ((h0 < 0.0) != (h1 < 0.0) && h0 != h1) t.push_back(t[k] + (t[k + 1] - t[k]) * h0 / (h0 - h1));
    }
    std::sort(t.begin(), t.end());
    return t;
}

/// Adds the forces of the water pressure on a straight block edge from a to b (block on the
/// left) to nodes whose shape functions along it are `shape(s)`, s ∈ [0, 1].
template <int K, class Shape>
void add_edge_forces(const Water& water, Point2 a, Point2 b, const std::array<int, K>& node, Shape shape,
                     double factor, Eigen::VectorXd& f) {
    // Gauss–Legendre, 3 points on [0, 1]: exact for the cubic N·u of a quadratic edge.
    static constexpr double r = 0.3872983346207417;  // √(3/5)/2
    static constexpr double gauss[3][2] = {{0.5 - r, 5.0 / 18.0}, {0.5, 8.0 / 18.0}, {0.5 + r, 5.0 / 18.0}};
    const double dx = b.x - a.x, dy = b.y - a.y;
    std::array<double, K> integral{};
    const std::vector<double> t = pieces(water, a, b);
    for (std::size_t k = 0; k + 1 < t.size(); ++k) {
        const double length = t[k + 1] - t[k];
        if (length <= 0.0) continue;
        for (const auto& [x, w] : gauss) {
            const double s = t[k] + x * length;
            const double u = water.pore_pressure({a.x + s * dx, a.y + s * dy});
            if (u == 0.0) continue;
            const std::array<double, K> n = shape(s);
            for (int i = 0; i < K; ++i) integral[i] += w * length * n[i] * u;
        }
    }
    // The outward normal times the length is (dy, −dx); the water pushes against it.
    for (int i = 0; i < K; ++i) {
        f[2 * node[i]] -= factor * integral[i] * dy;
        f[2 * node[i] + 1] += factor * integral[i] * dx;
    }
}

}  // namespace

int integration_points(const Mesh& mesh) { return mesh.quadratic() ? Triangle6::points : Triangle3::points; }

Point2 integration_point(const Mesh& mesh, const std::vector<Point2>& nodes, int e, int q) {
    const auto& t = mesh.triangles[e];
    const std::array<double, 3> l = mesh.quadratic() ? Triangle6::point(q) : Triangle3::point(q);
    Point2 p{0.0, 0.0};
    for (int i = 0; i < 3; ++i) {
        p.x += l[i] * nodes[t[i]].x;
        p.y += l[i] * nodes[t[i]].y;
    }
    return p;
}

void add_water_forces(const Water& water, const Mesh& mesh, const std::vector<Point2>& nodes,
                      const MeshTopology& topology, const std::vector<char>& active_elements, double factor,
                      Eigen::VectorXd& f) {
    if (!water.present() || factor == 0.0) return;
    const int elements = static_cast<int>(mesh.triangles.size());
    std::vector<char> block_present(static_cast<std::size_t>(mesh.block_count()), active_elements.empty() ? 1 : 0);
    for (int e = 0; e < elements; ++e) {
        if (!active_elements.empty() && !active_elements[e]) continue;
        block_present[mesh.triangle_block[e]] = 1;
        if (mesh.quadratic()) add_element_forces<6>(water, mesh, nodes, e, factor, f);
        else add_element_forces<3>(water, mesh, nodes, e, factor, f);
    }
    const bool quadratic = mesh.quadratic();
    for (const BoundaryEdge& edge : topology.edges) {
        if (!block_present[edge.block]) continue;
        if (!quadratic) {
            add_edge_forces<2>(water, nodes[edge.from], nodes[edge.to], {edge.from, edge.to},
                               [](double s) { return std::array<double, 2>{1.0 - s, s}; }, factor, f);
            continue;
        }
        // A six-node edge is two half-edges, corner → midside → corner: taken whole from its
        // first half, with the quadratic shape functions of the whole edge.
        if (!topology.midside_node[edge.to] || topology.midside_node[edge.from]) continue;
        const int second = topology.edge_out_of[edge.to];
        if (second < 0) continue;
        const int c0 = edge.from, m = edge.to, c1 = topology.edges[second].to;
        add_edge_forces<3>(water, nodes[c0], nodes[c1], {c0, m, c1},
                           [](double s) {
                               return std::array<double, 3>{(1.0 - s) * (1.0 - 2.0 * s), 4.0 * s * (1.0 - s),
                                                            s * (2.0 * s - 1.0)};
                           },
                           factor, f);
    }
}

std::vector<double> element_pore_pressures(const Water& water, const Mesh& mesh, const std::vector<Point2>& nodes) {
    std::vector<double> u(mesh.triangles.size(), 0.0);
    if (!water.present()) return u;
    const int points = integration_points(mesh);
    for (std::size_t e = 0; e < u.size(); ++e) {
        for (int q = 0; q < points; ++q)
            u[e] += water.pore_pressure(integration_point(mesh, nodes, static_cast<int>(e), q)) / points;
    }
    return u;
}

}  // namespace mcdda

#include "fem/BoundaryConditions.hpp"

#include "fem/PorePressure.hpp"

#include <cmath>
#include <sstream>

namespace mcdda {

namespace {

bool on_segment(Point2 p, Point2 a, Point2 b, double tolerance) { return distance_to_segment(p, a, b) <= tolerance; }

/// True when some block boundary runs along [a, b]: a ring edge collinear with it over a
/// positive length, or (`vertex_enough`) a ring vertex on it.
bool along_block_boundary(const std::vector<Block>& blocks, Point2 a, Point2 b, double tolerance, bool vertex_enough) {
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    if (length == 0.0) return false;
    const double tx = (b.x - a.x) / length, ty = (b.y - a.y) / length;
    auto along = [&](Point2 p) { return (p.x - a.x) * tx + (p.y - a.y) * ty; };
    auto off_line = [&](Point2 p) { return std::fabs((p.x - a.x) * ty - (p.y - a.y) * tx); };
    auto check_ring = [&](const Ring& ring) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
            const Point2 p = ring[i], q = ring[(i + 1) % ring.size()];
            if (vertex_enough && on_segment(p, a, b, tolerance)) return true;
            if (off_line(p) > tolerance || off_line(q) > tolerance) continue;
            const double lo = std::max(0.0, std::min(along(p), along(q)));
            const double hi = std::min(length, std::max(along(p), along(q)));
            if (hi - lo > tolerance) return true;
        }
        return false;
    };
    for (const Block& block : blocks) {
        if (check_ring(block.outer)) return true;
        for (const Ring& hole : block.holes)
            if (check_ring(hole)) return true;
    }
    return false;
}

/// True when `p` lies in a block or within `tolerance` of a block's boundary.
bool on_some_block(const std::vector<Block>& blocks, Point2 p, double tolerance) {
    auto inside = [&](const Ring& ring) {  // crossing number
        bool in = false;
        for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
            const Point2 a = ring[i], b = ring[j];
            if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
        }
        return in;
    };
    auto near = [&](const Ring& ring) {
        for (std::size_t i = 0; i < ring.size(); ++i)
            if (on_segment(p, ring[i], ring[(i + 1) % ring.size()], tolerance)) return true;
        return false;
    };
    for (const Block& block : blocks) {
        if (block.outer.size() < 3) continue;
        if (near(block.outer)) return true;
        bool in = inside(block.outer);
        for (const Ring& hole : block.holes) {
            if (near(hole)) return true;
            if (in && inside(hole)) in = false;
        }
        if (in) return true;
    }
    return false;
}

}  // namespace

void check_supports_on_blocks(const Model& model, const std::vector<Block>& blocks, std::vector<Diagnostic>& diagnostics) {
    const auto box = model.bounds();
    const double tolerance = 1e-6 * std::hypot(box[2] - box[0], box[3] - box[1]);
    for (std::size_t i = 0; i < model.rollers.size(); ++i) {
        const Roller& r = model.rollers[i];
        if (!along_block_boundary(blocks, r.from, r.to, tolerance, true))
            diagnostics.push_back({Diagnostic::Severity::Error, "/rollers/" + std::to_string(i),
                                   "roller \"" + r.name + "\" lies along no block boundary"});
    }
    for (std::size_t i = 0; i < model.edge_pressures.size(); ++i) {
        const EdgePressure& e = model.edge_pressures[i];
        if (!along_block_boundary(blocks, e.from, e.to, tolerance, false))
            diagnostics.push_back({Diagnostic::Severity::Error, "/edge_pressures/" + std::to_string(i),
                                   "pressure \"" + e.name + "\" lies along no block boundary"});
    }
    for (std::size_t i = 0; i < model.absorbing_boundaries.size(); ++i) {
        const AbsorbingBoundary& a = model.absorbing_boundaries[i];
        if (!along_block_boundary(blocks, a.from, a.to, tolerance, false))
            diagnostics.push_back({Diagnostic::Severity::Error, "/absorbing_boundaries/" + std::to_string(i),
                                   "absorbing boundary \"" + a.name + "\" lies along no block boundary"});
    }
    if (model.base_motion.kind == BaseMotion::Kind::Compliant &&
        !along_block_boundary(blocks, model.base_motion.from, model.base_motion.to, tolerance, false))
        diagnostics.push_back({Diagnostic::Severity::Error, "/base_motion", "the compliant base lies along no block boundary"});
    // Points go to the nearest node, wherever they are: one outside every block is a mistake
    // (a typo in a coordinate) that would otherwise load, fix or measure some corner silently.
    auto check_point = [&](Point2 p, const std::string& path, const std::string& what) {
        if (on_some_block(blocks, p, 1e3 * tolerance)) return;
        std::ostringstream text;
        text << what << " at (" << p.x << ", " << p.y << ") lies outside every block";
        diagnostics.push_back({Diagnostic::Severity::Error, path, text.str()});
    };
    for (std::size_t i = 0; i < model.point_loads.size(); ++i)
        check_point(model.point_loads[i].point, "/point_loads/" + std::to_string(i) + "/point",
                    "point load \"" + model.point_loads[i].name + "\"");
    for (std::size_t i = 0; i < model.fixed_points.size(); ++i)
        check_point(model.fixed_points[i].point, "/fixed_points/" + std::to_string(i) + "/point",
                    "fixed point \"" + model.fixed_points[i].name + "\"");
    for (std::size_t i = 0; i < model.measurement_points.size(); ++i)
        check_point(model.measurement_points[i].point, "/measurement_points/" + std::to_string(i) + "/point",
                    "measurement point \"" + model.measurement_points[i].name + "\"");
}

BoundaryConditions locate_boundary_conditions(const Model& model, const Mesh& mesh, const MeshTopology& topology,
                                              std::vector<Diagnostic>& diagnostics) {
    BoundaryConditions bc;
    const std::size_t n = mesh.nodes.size();
    std::vector<char> fixed(2 * n, 0);
    const double tolerance = 1e-6 * topology.model_size;
    auto error = [&](const std::string& path, const std::string& message) {
        diagnostics.push_back({Diagnostic::Severity::Error, path, message});
    };

    for (std::size_t i = 0; i < model.fixed_points.size(); ++i) {
        const Point2 p = model.fixed_points[i].point;
        const int nearest = nearest_node(mesh, p);
        if (nearest < 0) continue;
        const Point2 q = mesh.nodes[nearest];
        const double distance = std::hypot(q.x - p.x, q.y - p.y);
        if (distance > 0.02 * topology.model_size)
            diagnostics.push_back({Diagnostic::Severity::Warning, "/fixed_points/" + std::to_string(i),
                                   "the nearest node is " + std::to_string(distance) + " m away"});
        // Nodes of neighbouring blocks at the same place are all fixed: the user fixed a point.
        for (std::size_t k = 0; k < n; ++k)
            if (std::hypot(mesh.nodes[k].x - q.x, mesh.nodes[k].y - q.y) <= tolerance) fixed[2 * k] = fixed[2 * k + 1] = 1;
    }
    bc.roller_nodes.assign(model.rollers.size(), {});
    for (std::size_t i = 0; i < model.rollers.size(); ++i) {
        const Roller& r = model.rollers[i];
        int caught = 0;
        for (int node : topology.boundary_nodes) {
            if (!on_segment(mesh.nodes[node], r.from, r.to, tolerance)) continue;
            if (r.fix_x) fixed[2 * node] = 1;
            if (r.fix_y) fixed[2 * node + 1] = 1;
            bc.roller_nodes[i].push_back(node);
            ++caught;
        }
        if (caught == 0)
            error("/rollers/" + std::to_string(i), "roller \"" + r.name + "\" lies along no block boundary");
    }
    bc.equation.assign(2 * n, -1);
    for (std::size_t d = 0; d < 2 * n; ++d)
        if (!fixed[d]) bc.equation[d] = bc.equation_count++;

    for (std::size_t i = 0; i < model.point_loads.size(); ++i)
        bc.point_loads.push_back({nearest_node(mesh, model.point_loads[i].point), static_cast<int>(i)});
    for (std::size_t i = 0; i < model.edge_pressures.size(); ++i) {
        const EdgePressure& e = model.edge_pressures[i];
        int caught = 0;
        for (std::size_t k = 0; k < topology.edges.size(); ++k) {
            const BoundaryEdge& edge = topology.edges[k];
            if (on_segment(mesh.nodes[edge.from], e.from, e.to, tolerance) &&
                on_segment(mesh.nodes[edge.to], e.from, e.to, tolerance)) {
                bc.pressure_edges.push_back({static_cast<int>(k), static_cast<int>(i)});
                ++caught;
            }
        }
        if (caught == 0)
            error("/edge_pressures/" + std::to_string(i), "pressure \"" + e.name + "\" lies along no block boundary");
    }
    for (const MeasurementPoint& m : model.measurement_points) bc.measurement_nodes.push_back(nearest_node(mesh, m.point));
    return bc;
}

double load_factor(const Model& model, int table, double step, double time) {
    if (table < 0) return 1.0;
    const LoadTable& t = model.load_tables[table];
    return t.factor(t.variable == LoadTable::Variable::Step ? step : time);
}

Eigen::VectorXd external_forces(const Model& model, const Mesh& mesh, const std::vector<Point2>& nodes,
                                const MeshTopology& topology, const BoundaryConditions& bc, double step, double time,
                                const std::vector<char>& active_elements) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(nodes.size()));
    for (const auto& l : bc.point_loads) {
        const PointLoad& load = model.point_loads[l.load];
        const double factor = load_factor(model, load.table, step, time);
        f[2 * l.node] += factor * load.force.x;
        f[2 * l.node + 1] += factor * load.force.y;
    }
    for (const auto& p : bc.pressure_edges) {
        const EdgePressure& load = model.edge_pressures[p.load];
        const BoundaryEdge& e = topology.edges[p.edge];
        const double pressure = load.pressure * load_factor(model, load.table, step, time);
        // The block lies left of the edge: its outward normal times the length is (dy, −dx);
        // a pressure pushes against it. A six-node edge is two boundary halves, each giving a
        // third to its corner and two thirds to its midside node (1/6, 4/6, 1/6 of the edge).
        const double dx = nodes[e.to].x - nodes[e.from].x, dy = nodes[e.to].y - nodes[e.from].y;
        for (int node : {e.from, e.to}) {
            const bool half = topology.midside_node.size() > 0 &&
                              (topology.midside_node[e.from] || topology.midside_node[e.to]);
            const double share = !half ? 0.5 : topology.midside_node[node] ? 2.0 / 3.0 : 1.0 / 3.0;
            f[2 * node] -= share * pressure * dy;
            f[2 * node + 1] += share * pressure * dx;
        }
    }
    const double gravity_factor = load_factor(model, model.gravity_table, step, time);
    if (model.gravity.x != 0.0 || model.gravity.y != 0.0) {
        // A pseudo-static earthquake load (seismic coefficients) is a fraction of the weight.
        const double g = std::hypot(model.gravity.x, model.gravity.y);
        const Point2 acceleration{model.gravity.x + model.seismic_coefficient.kh * g,
                                  model.gravity.y + model.seismic_coefficient.kv * g};
        const Water& water = model.water;
        const int points = integration_points(mesh);
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            if (!active_elements.empty() && !active_elements[t]) continue;
            const auto& tri = mesh.triangles[t];
            const Point2 &a = nodes[tri[0]], &b = nodes[tri[1]], &c = nodes[tri[2]];
            const double area = 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
            const Material& material = model.materials[mesh.triangle_material[t]];
            // Saturated below the piezometric line: each integration point weighs as wet or dry.
            double density = material.density;
            if (water.present() && material.saturated_density > 0.0) {
                density = 0.0;
                for (int q = 0; q < points; ++q) {
                    const bool wet = water.pore_pressure(integration_point(mesh, nodes, static_cast<int>(t), q)) > 0.0;
                    density += material.density_at(wet) / points;
                }
            }
            const double mass = density * area / 3.0;
            for (int node : mesh.quadratic() ? mesh.midside[t] : tri) {
                f[2 * node] += gravity_factor * mass * acceleration.x;
                f[2 * node + 1] += gravity_factor * mass * acceleration.y;
            }
        }
    }
    // Water weighs with gravity: a gravity ramp fills the ground water with it.
    add_water_forces(model.water, mesh, nodes, topology, active_elements, gravity_factor, f);
    return f;
}

}  // namespace mcdda

#include "run/RunOutput.hpp"

#include "io/AtomicFile.hpp"
#include "contact/ContactLaw.hpp"
#include "io/VtuWriter.hpp"
#include "linalg/BlasInfo.hpp"
#include "parallel/ParallelFor.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace mcdda {

namespace fs = std::filesystem;

const char* status_name(RunStatus s) {
    switch (s) {
        case RunStatus::Running: return "running";
        case RunStatus::Completed: return "completed";
        case RunStatus::Unbalanced: return "unbalanced";
        case RunStatus::Collapsed: return "collapsed";
        case RunStatus::Failed: return "failed";
        case RunStatus::Cancelled: return "cancelled";
    }
    return "unknown";
}

int exit_status(RunStatus s) {
    switch (s) {
        case RunStatus::Completed: return 0;
        case RunStatus::Unbalanced: return 3;
        case RunStatus::Collapsed: return 5;
        case RunStatus::Cancelled: return 130;
        default: return 4;
    }
}

namespace {

/// Did the run whose summary.json is in `directory` end with results (completed or collapsed)?
bool ended_with_results(const fs::path& directory) {
    std::ifstream in(directory / "summary.json");
    if (!in) return false;  // killed: no summary was written
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("status") || !j["status"].is_string()) return false;
    const std::string status = j["status"].get<std::string>();
    return status == status_name(RunStatus::Completed) || status == status_name(RunStatus::Unbalanced) ||
           status == status_name(RunStatus::Collapsed);
}

}  // namespace

namespace {

/// A ParaView collection (.pvd) of `files` (time, name), rewritten atomically.
void write_collection(const std::string& path, const std::vector<std::pair<double, std::string>>& files) {
    write_file_atomically(path, [&](std::ostream& out) {
        out << std::setprecision(12) << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
        for (const auto& [time, file] : files)
            out << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
        out << "  </Collection>\n</VTKFile>\n";
    });
}

}  // namespace

RunOutput::RunOutput(std::string directory, std::string model_stem)
    : directory_(std::move(directory)), stem_(std::move(model_stem)) {
    std::error_code ec;
    fs::create_directories(directory_, ec);
    if (!fs::is_directory(directory_))
        throw std::runtime_error("cannot create the output directory " + directory_ + ": " + ec.message());
    // An earlier run's files: collections and steps, the history and the summary.
    const fs::path dir(directory_);
    std::vector<fs::path> earlier;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        std::error_code type_error;
        if (!entry.is_regular_file(type_error)) continue;
        // Step files of any model: <stem>_NNNNNN.vtu (the mesh command's <stem>.vtu stays).
        const bool step_file = name.size() > 11 && name.compare(name.size() - 4, 4, ".vtu") == 0 &&
                               name[name.size() - 11] == '_' &&
                               std::all_of(name.end() - 10, name.end() - 4, [](char c) { return c >= '0' && c <= '9'; });
        const bool contacts_file = entry.path().extension() == ".vtp" && name.find("_contacts_") != std::string::npos;
        if (name == "history.csv" || name == "summary.json" || entry.path().extension() == ".pvd" || step_file ||
            contacts_file)
            earlier.push_back(entry.path());
    }
    if (ec) throw std::runtime_error("cannot read the output directory " + directory_ + ": " + ec.message());
    // Nothing may be lost if this run is killed or fails: the earlier results move aside, and
    // the ones kept from a run before stay when the earlier run left none of its own.
    const fs::path keep = dir / "previous";
    const bool keep_earlier = !earlier.empty() && (ended_with_results(dir) || !fs::exists(keep));
    if (keep_earlier) {
        fs::remove_all(keep, ec);
        if (!ec) fs::create_directory(keep, ec);
        if (ec) throw std::runtime_error("cannot write into the output directory " + directory_ + ": " + ec.message());
        for (const fs::path& p : earlier) {
            fs::rename(p, keep / p.filename(), ec);
            if (ec) throw std::runtime_error("cannot move the earlier results into " + keep.string() + ": " + ec.message());
        }
    } else {
        for (const fs::path& p : earlier) {
            fs::remove(p, ec);
            if (ec) throw std::runtime_error("cannot write into the output directory " + directory_ + ": " + ec.message());
        }
    }
    const std::string history = (dir / "history.csv").string();
    history_.open(history, std::ios::trunc);
    if (!history_) throw std::runtime_error("cannot write " + history);
    history_ << std::setprecision(10);
}

std::string RunOutput::kept_results() const {
    std::error_code ec;
    const fs::path keep = fs::path(directory_) / "previous";
    return fs::is_directory(keep, ec) ? keep.string() : std::string();
}

void RunOutput::save_step(const Simulation& sim) { save_state(sim, sim.state(), sim.state().step, sim.state().time); }

void RunOutput::save_state(const Simulation& sim, const SimulationState& s, int number, double time,
                           const VtuFields& extra) {
    const Mesh& mesh = sim.mesh();
    VtuFields fields;
    VtuField displacement{"displacement", 3, {}}, velocity{"velocity", 3, {}};
    displacement.values.reserve(3 * mesh.nodes.size());
    velocity.values.reserve(3 * mesh.nodes.size());
    const Eigen::VectorXd u = s.reported_displacement();
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
        displacement.values.insert(displacement.values.end(), {u[2 * i], u[2 * i + 1], 0.0});
        velocity.values.insert(velocity.values.end(), {s.velocity[2 * i], s.velocity[2 * i + 1], 0.0});
    }
    // VTK's symmetric tensor order: xx, yy, zz, xy, yz, xz. The solver's stresses are effective;
    // "stress" is the total stress σ = σ′ − u (the same without water).
    const bool water = has_water(sim.full_model());
    const std::vector<double> pore = water ? sim.pore_pressures() : std::vector<double>(s.stress.size(), 0.0);
    VtuField stress{"stress", 6, {}}, effective{"effective_stress", 6, {}}, pore_pressure{"pore_pressure", 1, pore};
    stress.values.reserve(6 * s.stress.size());
    for (std::size_t e = 0; e < s.stress.size(); ++e) {
        const double u = pore[e];
        stress.values.insert(stress.values.end(),
                             {s.stress[e][0] - u, s.stress[e][1] - u, s.stress_zz[e] - u, s.stress[e][2], 0.0, 0.0});
        if (water)
            effective.values.insert(effective.values.end(),
                                    {s.stress[e][0], s.stress[e][1], s.stress_zz[e], s.stress[e][2], 0.0, 0.0});
    }
    VtuField state{"plastic_state", 1, std::vector<double>(s.plastic_state.begin(), s.plastic_state.end())};
    VtuField strain{"plastic_strain", 1, s.plastic_strain};
    fields.point_data = {std::move(displacement), std::move(velocity)};
    fields.cell_data = {std::move(stress), std::move(state), std::move(strain)};
    if (water) {
        fields.cell_data.push_back(std::move(effective));
        fields.cell_data.push_back(std::move(pore_pressure));
    }
    fields.field_data = {{"step", 1, {static_cast<double>(s.step)}},
                         {"stage", 1, {static_cast<double>(s.stage + 1)}},
                         {"time", 1, {s.time}}};

    for (const VtuField& f : extra.point_data) fields.point_data.push_back(f);
    for (const VtuField& f : extra.cell_data) fields.cell_data.push_back(f);
    for (const VtuField& f : extra.field_data) fields.field_data.push_back(f);
    std::ostringstream name;
    name << stem_ << "_" << std::setw(6) << std::setfill('0') << number << ".vtu";
    const std::string path = (fs::path(directory_) / name.str()).string();
    // Staged runs: whether each element is present (excavated and not yet built ones are not);
    // ParaView's Threshold on it, and the desktop program, leave the absent ones out.
    if (!sim.full_model().stages.empty()) {
        const std::vector<char>& active = sim.active_elements();
        VtuField present{"present", 1, std::vector<double>(mesh.triangles.size(), 1.0)};
        for (std::size_t e = 0; e < active.size(); ++e) present.values[e] = active[e] ? 1.0 : 0.0;
        fields.cell_data.push_back(std::move(present));
    }
    write_vtu(path, mesh, fields);
    saved_.emplace_back(time, name.str());

    write_collection((fs::path(directory_) / (stem_ + ".pvd")).string(), saved_);
    save_contacts(sim, s, number, time);
}

namespace {

/// The point data of the contacts file, one value per point (contact vertex or bolt end).
struct ContactFields {
    bool water = false;  ///< with water: its pressure and the effective normal force too
    VtuField normal_force{"normal_force", 1, {}}, shear_force{"shear_force", 1, {}}, force{"force", 3, {}},
        normal{"normal", 3, {}}, opening{"opening", 1, {}}, slip{"slip", 1, {}}, state{"state", 1, {}},
        vertex_block{"vertex_block", 1, {}}, edge_block{"edge_block", 1, {}}, joint{"joint", 1, {}},
        water_pressure{"water_pressure", 1, {}}, effective_normal_force{"effective_normal_force", 1, {}};

    void add(double n, double t, Point2 f, Point2 dir, double open, double slid, int st, int vb, int eb, int j,
             double u) {
        if (water) {
            water_pressure.values.push_back(u);
            effective_normal_force.values.push_back(n);
        }
        normal_force.values.push_back(n);
        shear_force.values.push_back(t);
        force.values.insert(force.values.end(), {f.x, f.y, 0.0});
        normal.values.insert(normal.values.end(), {dir.x, dir.y, 0.0});
        opening.values.push_back(open);
        slip.values.push_back(slid);
        state.values.push_back(st);
        vertex_block.values.push_back(vb);
        edge_block.values.push_back(eb);
        joint.values.push_back(j);
    }

    std::vector<VtuField> take() {
        std::vector<VtuField> fields{std::move(normal_force), std::move(shear_force), std::move(force),
                                     std::move(normal),       std::move(opening),     std::move(slip),
                                     std::move(state),        std::move(vertex_block), std::move(edge_block),
                                     std::move(joint)};
        if (water) {
            fields.push_back(std::move(water_pressure));
            fields.push_back(std::move(effective_normal_force));
        }
        return fields;
    }
};

}  // namespace

void RunOutput::save_contacts(const Simulation& sim, const SimulationState& s, int number, double time) {
    const MeshTopology& topology = sim.topology();
    PolyData data;
    ContactFields fields;
    // The contact springs carry the effective normal force: the water pressure acts on the
    // joint's faces besides (fem/PorePressure.hpp).
    fields.water = has_water(sim.full_model());
    const double water_factor =
        fields.water ? load_factor(sim.model(), sim.model().gravity_table, s.step, s.time) : 0.0;
    for (const Contact& c : s.contacts) {
        const ContactKinematics k = contact_kinematics(c, s.nodes, topology);
        const Point2 n{k.normal[0], k.normal[1]}, t{k.shear[0], k.shear[1]};
        // On the vertex: the normal force pushes it out of the edge's block, the shear spring
        // (or friction) holds it back along the edge.
        const bool closed = c.state != ContactState::Open;
        const double fn = closed ? c.normal_force : 0.0, ft = closed ? c.shear_force : 0.0;
        data.vertices.push_back(static_cast<int>(data.points.size()));
        data.points.push_back(s.nodes[c.node]);
        fields.add(fn, ft, {fn * n.x - ft * t.x, fn * n.y - ft * t.y}, n, closed ? 0.0 : std::max(0.0, k.gap - c.gap_found),
                   c.slip_total, c.state == ContactState::Open ? 0 : c.state == ContactState::Sliding ? 1 : 2,
                   sim.mesh().node_block[c.node], c.edge_block, topology.edges[c.edge].joint,
                   fields.water ? water_factor * sim.model().water.pore_pressure(s.nodes[c.node]) : 0.0);
    }
    // Bolts: a line between their anchors, each end a point with no contact values.
    const Model& model = sim.full_model();
    VtuField bolt_force{"bolt_force", 1, std::vector<double>(data.vertices.size(), 0.0)};
    for (std::size_t i = 0; i < model.bolts.size(); ++i) {
        const int first = static_cast<int>(data.points.size());
        for (const Point2 p : sim.bolt_ends(static_cast<int>(i))) {
            data.points.push_back(p);
            fields.add(0.0, 0.0, {0.0, 0.0}, {0.0, 0.0}, 0.0, 0.0, 0, -1, -1, -1, 0.0);
        }
        data.lines.push_back({first, first + 1});
        bolt_force.values.push_back(s.bolt_force[i]);
    }
    data.fields.point_data = fields.take();
    data.fields.cell_data = {std::move(bolt_force)};
    data.fields.field_data = {{"step", 1, {static_cast<double>(s.step)}},
                              {"stage", 1, {static_cast<double>(s.stage + 1)}},
                              {"time", 1, {s.time}}};
    std::ostringstream name;
    name << stem_ << "_contacts_" << std::setw(6) << std::setfill('0') << number << ".vtp";
    write_vtp((fs::path(directory_) / name.str()).string(), data);
    saved_contacts_.emplace_back(time, name.str());
    write_collection((fs::path(directory_) / (stem_ + "_contacts.pvd")).string(), saved_contacts_);
}

void RunOutput::record_history(const Simulation& sim) {
    if (!step_history_) return;
    const SimulationState& s = sim.state();
    const auto loads = sim.load_magnitudes();
    const Model& model = sim.model();
    std::ostringstream row;
    row << std::setprecision(10);
    if (!header_written_) {
        row << "step,time,stage,unbalanced_ratio";
        for (const auto& [name, value] : loads) row << ",load:" << name;
        for (const MeasurementPoint& m : model.measurement_points) row << "," << m.name << ":ux," << m.name << ":uy";
        // Moving supports (displacement control): their displacement and the force they exert.
        for (const Roller& r : model.rollers)
            if (r.moves()) row << "," << r.name << ":ux," << r.name << ":uy," << r.name << ":fx," << r.name << ":fy";
        for (const Bolt& b : sim.full_model().bolts) row << "," << b.name << ":force";
        if (has_dynamic_stage(sim.full_model()))
            for (const MeasurementPoint& m : model.measurement_points)
                row << "," << m.name << ":vx," << m.name << ":vy," << m.name << ":ax," << m.name << ":ay";
        if (sim.full_model().base_motion.present()) row << ",base:ax,base:ay,base:vx,base:vy,base:ux,base:uy";
        row << "\n";
        header_written_ = true;
    }
    row << s.step + s.step_fraction << "," << s.time << "," << s.stage + 1 << "," << s.unbalanced_ratio;
    for (const auto& [name, value] : loads) row << "," << value;
    const Eigen::VectorXd u = s.reported_displacement();
    for (int node : sim.boundary_conditions().measurement_nodes) row << "," << u[2 * node] << "," << u[2 * node + 1];
    for (std::size_t i = 0; i < model.rollers.size(); ++i) {
        const Roller& r = model.rollers[i];
        if (!r.moves()) continue;
        const double factor = load_factor(model, r.table, s.step + s.step_fraction, s.time);
        const Point2 f = i < s.roller_reactions.size() ? s.roller_reactions[i] : Point2{0.0, 0.0};
        row << "," << (r.fix_x ? r.displacement.x * factor : 0.0) << "," << (r.fix_y ? r.displacement.y * factor : 0.0)
            << "," << f.x << "," << f.y;
    }
    for (double force : s.bolt_force) row << "," << force;
    // Shaking: velocities (relative to a rigid base, like the displacements) and absolute
    // accelerations (what an accelerometer records), then the base's own motion.
    const Simulation::BaseState base = sim.base_state(s.time);
    if (has_dynamic_stage(sim.full_model())) {
        const Eigen::Vector2d frame = sim.relative_to_base() ? base.acceleration : Eigen::Vector2d::Zero();
        for (int node : sim.boundary_conditions().measurement_nodes)
            row << "," << s.velocity[2 * node] << "," << s.velocity[2 * node + 1] << ","
                << s.acceleration[2 * node] + frame.x() << "," << s.acceleration[2 * node + 1] + frame.y();
    }
    if (sim.full_model().base_motion.present())
        row << "," << base.acceleration.x() << "," << base.acceleration.y() << "," << base.velocity.x() << ","
            << base.velocity.y() << "," << base.displacement.x() << "," << base.displacement.y();
    row << "\n";
    // One write and a flush per row: a run that stops leaves whole rows only.
    history_ << row.str() << std::flush;
}

void RunOutput::record_trial(const Simulation& sim, const StrengthTrial& t, const SimulationState& s) {
    std::ostringstream row;
    row << std::setprecision(10);
    if (!header_written_) {
        row << "trial,factor,status,stands,steps,iterations,max_displacement";
        for (const MeasurementPoint& m : sim.full_model().measurement_points) row << "," << m.name << ":ux," << m.name << ":uy";
        row << "\n";
        header_written_ = true;
    }
    row << t.number << "," << t.factor << "," << t.status << "," << (t.stands ? 1 : 0) << "," << t.steps << ","
        << t.iterations << "," << t.max_displacement;
    const Eigen::VectorXd u = s.reported_displacement();
    for (int node : sim.boundary_conditions().measurement_nodes) row << "," << u[2 * node] << "," << u[2 * node + 1];
    row << "\n";
    history_ << row.str() << std::flush;
}

namespace {

/// What the shaking left: displacements since the first dynamic stage began, relative to the
/// base (a rigid base's analysis is relative already; a compliant base's mean is taken off).
nlohmann::json permanent_displacement_of(const Simulation& sim) {
    const Eigen::VectorXd u = sim.displacement_since_shaking();
    nlohmann::json j;
    double largest = 0.0;
    std::size_t at = 0;
    for (Eigen::Index n = 0; 2 * n + 1 < u.size(); ++n) {
        const double size = std::hypot(u[2 * n], u[2 * n + 1]);
        if (size > largest) {
            largest = size;
            at = static_cast<std::size_t>(n);
        }
    }
    j["largest"] = largest;  // m
    j["at"] = u.size() ? nlohmann::json::array({sim.mesh().nodes[at].x, sim.mesh().nodes[at].y}) : nlohmann::json::array();
    nlohmann::json points = nlohmann::json::object();
    const auto& nodes = sim.boundary_conditions().measurement_nodes;
    for (std::size_t i = 0; i < nodes.size() && i < sim.full_model().measurement_points.size(); ++i)
        points[sim.full_model().measurement_points[i].name] = {u[2 * nodes[i]], u[2 * nodes[i] + 1]};
    j["points"] = std::move(points);
    j["relative_to"] = "base";
    return j;
}

nlohmann::json stages_of(const Simulation& sim) {
    nlohmann::json stages = nlohmann::json::array();
    for (const StageRecord& r : sim.stages()) {
        const char* state = !r.started ? "not run" : r.finished ? (r.reached_target ? "reached target" : "completed")
                                                                  : "stopped";
        stages.push_back({{"name", r.name}, {"status", state}, {"first_step", r.first_step},
                          {"last_step", r.last_step}, {"planned_steps", r.planned_steps},
                          {"unbalanced_ratio", r.unbalanced_ratio}});
    }
    return stages;
}

nlohmann::json bolts_of(const Simulation& sim) {
    nlohmann::json bolts = nlohmann::json::array();
    for (std::size_t i = 0; i < sim.full_model().bolts.size(); ++i)
        bolts.push_back({{"name", sim.full_model().bolts[i].name}, {"force", sim.state().bolt_force[i]},
                         {"broken", sim.state().bolt_broken[i] != 0}});
    return bolts;
}

void add_timings(const Simulation& sim, nlohmann::json& j) {
    const RunTimings& t = sim.timings();
    j["timing"] = {{"assembly", t.assembly}, {"factorization", t.factorization}, {"solve", t.solve},
                   {"contact", t.contact},   {"plasticity", t.plasticity},       {"total", t.total}};
    j["factorizations"] = t.factorizations;
    j["blas"] = blas_in_use();  // the factorisation's speed depends on it
    j["threads"] = thread_count();
    j["symbolic_analyses"] = t.symbolic_analyses;
    j["reused_factors"] = {{"matrices", t.reused_factors}, {"iterations", t.refinement_iterations}};
    const int steps = sim.state().step;
    j["iterations"] = {{"total", t.iterations},
                       {"per_step", steps > 0 ? static_cast<double>(t.iterations) / steps : 0.0},
                       {"max_per_step", t.max_iterations},
                       {"load_cuts", t.load_cuts},
                       {"steps_at_rest", t.steps_at_rest}};
}

/// The collapse load lies between the last load carried and the first not carried.
nlohmann::json collapse_of(const Simulation& sim) {
    auto loads_at = [&](double position) {
        nlohmann::json loads = nlohmann::json::object();
        for (const auto& [name, value] : sim.load_magnitudes_at(position)) loads[name] = value;
        return nlohmann::json{{"step", position}, {"loads", loads}};
    };
    return {{"carried", loads_at(sim.collapse()->carried)}, {"not_carried", loads_at(sim.collapse()->not_carried)}};
}

/// What a parameter study compares between runs (docs/study.md).
void add_study_values(const Simulation& sim, nlohmann::json& j) {
    double plastic_area = 0.0, largest = 0.0;
    const Mesh& mesh = sim.mesh();
    const std::vector<unsigned char>& plastic = sim.state().plastic_state;
    for (std::size_t e = 0; e < mesh.triangles.size() && e < plastic.size(); ++e) {
        if (plastic[e] == 0) continue;
        const auto& t = mesh.triangles[e];
        const Point2 &a = mesh.nodes[static_cast<std::size_t>(t[0])], &b = mesh.nodes[static_cast<std::size_t>(t[1])],
                     &c = mesh.nodes[static_cast<std::size_t>(t[2])];
        plastic_area += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    }
    const Eigen::VectorXd u = sim.state().reported_displacement();
    for (Eigen::Index i = 0; i + 1 < u.size(); i += 2) largest = std::max(largest, std::hypot(u[i], u[i + 1]));
    j["plastic_area"] = plastic_area;  // m², elements that have yielded at some time
    j["max_displacement"] = largest;   // m
    j["element"] = mesh.quadratic() ? "t6" : "t3";
    j["model"] = {{"name", sim.model().name}, {"nodes", mesh.nodes.size()},
                  {"elements", mesh.triangles.size()}, {"blocks", mesh.block_count()}};
}

/// Names read by scripts outside the program: docs/running.md.
nlohmann::json factor_of_safety_of(const FactorOfSafety& factor) {
    nlohmann::json f{{"value", factor.value}, {"converged", factor.converged},
                     {"not_converged", factor.not_converged}, {"trials", factor.trials}, {"found", factor.found},
                     {"non_associated_flow", factor.non_associated_flow}};
    nlohmann::json trials = nlohmann::json::array();
    for (const StrengthTrial& t : factor.table)
        trials.push_back({{"trial", t.number}, {"factor", t.factor}, {"status", t.status}, {"stands", t.stands},
                          {"steps", t.steps}, {"iterations", t.iterations},
                          {"max_displacement", t.max_displacement}, {"message", t.message}});
    f["table"] = trials;
    return f;
}

}  // namespace

void RunOutput::write_summary(const Simulation* sim, RunStatus status, const std::string& message,
                              const FactorOfSafety* factor) {
    nlohmann::json j;
    j["status"] = status_name(status);
    j["message"] = message;
    j["steps"] = sim ? sim->state().step : 0;
    j["time"] = sim ? sim->state().time : 0.0;
    j["saved_steps"] = saved_steps();
    if (sim) {
        j["unbalanced_ratio"] = sim->state().unbalanced_ratio;
        j["equilibrium_ratio"] = sim->analysis().equilibrium_ratio;
        j["stages"] = stages_of(*sim);
        if (!sim->full_model().bolts.empty()) j["bolts"] = bolts_of(*sim);
        add_timings(*sim, j);
        if (sim->collapse()) j["collapse"] = collapse_of(*sim);
        if (sim->full_model().base_motion.present()) j["permanent_displacement"] = permanent_displacement_of(*sim);
        add_study_values(*sim, j);
    }
    if (factor) j["factor_of_safety"] = factor_of_safety_of(*factor);
    write_file_atomically((fs::path(directory_) / "summary.json").string(),
                          [&](std::ostream& out) { out << j.dump(2) << "\n"; });
    // This run's results replace the kept ones.
    if (status == RunStatus::Completed || status == RunStatus::Unbalanced || status == RunStatus::Collapsed) {
        std::error_code ec;
        fs::remove_all(fs::path(directory_) / "previous", ec);
    }
}

}  // namespace mcdda

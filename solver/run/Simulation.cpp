#include "run/Simulation.hpp"
#include "run/Stopwatch.hpp"

#include "fem/PorePressure.hpp"
#include "material/StrengthReduction.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mcdda {

void initial_stresses(const Model& model, const Mesh& mesh, const ElementAssembly& elements, PointStates& points) {
    const int per_element = elements.points_per_element();
    const std::size_t n = mesh.triangles.size() * per_element;
    points.resize(n);
    const InitialStress& s = model.initial_stress;
    const double g = std::hypot(model.gravity.x, model.gravity.y);
    const Water& water = water_of_stage(model, 0);
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const Material& m = model.materials[mesh.triangle_material[e]];
        for (int q = 0; q < per_element; ++q) {
            const std::size_t p = e * per_element + q;
            Eigen::Vector3d sigma = Eigen::Vector3d::Zero();
            if (s.kind == InitialStress::Kind::Uniform) {
                sigma = Eigen::Vector3d(s.stress[0], s.stress[1], s.stress[2]);
            } else if (s.kind == InitialStress::Kind::Gravity) {
                // At the integration point: a six-node element carries the linear gravity field exactly.
                const Point2 at = elements.point_position(mesh.nodes, static_cast<int>(e), q);
                const double depth = std::max(0.0, s.surface_y - at.y);
                // Effective vertical stress (compressive magnitude): the weight above, dry above the
                // water and saturated below, plus a lake's on the surface, less the pore pressure.
                const double level = water.present() ? water.level(at.x) : -std::numeric_limits<double>::infinity();
                const double wet = std::clamp(level - at.y, 0.0, depth);
                const double lake = std::max(0.0, level - std::max(at.y, s.surface_y));  // water above the ground
                const double vertical = m.density_at(false) * g * (depth - wet) + m.density_at(true) * g * wet +
                                        water.unit_weight * lake - water.pore_pressure(at);
                sigma = Eigen::Vector3d(-s.k0 * vertical, -vertical, 0.0);
            }
            points.stress[p] = sigma;
            // Plane strain: unless given, the out-of-plane stress that an elastic loading from
            // zero in plane strain would give (εzz = 0).
            points.stress_zz[p] = s.kind == InitialStress::Kind::Uniform && s.stress_zz
                                      ? *s.stress_zz
                                      : m.poisson_ratio * (sigma[0] + sigma[1]);
        }
    }
}

void element_averages(const PointStates& points, int per_element, SimulationState& state) {
    const std::size_t elements = points.stress.size() / per_element;
    state.stress.assign(elements, Eigen::Vector3d::Zero());
    state.stress_zz.assign(elements, 0.0);
    state.plastic_strain.assign(elements, 0.0);
    state.plastic_state.assign(elements, 0);
    for (std::size_t e = 0; e < elements; ++e) {
        for (int q = 0; q < per_element; ++q) {
            const std::size_t p = e * per_element + q;
            state.stress[e] += points.stress[p] / per_element;
            state.stress_zz[e] += points.stress_zz[p] / per_element;
            state.plastic_strain[e] += points.plastic_strain[p] / per_element;
            state.plastic_state[e] = std::max(state.plastic_state[e], points.plastic_state[p]);
        }
    }
}

Simulation::Simulation(const Preprocessed& p, double strength_factor)
    : model_(p.model), mesh_(p.mesh), base_model_(p.model), strength_factor_(strength_factor) {
    if (mesh_.triangles.empty()) throw std::runtime_error("the model has no mesh");
    if (base_model_.stages.empty() && model_.analysis.strength_reduction) {
        // A strength reduction trial: reduced strengths, a small-strain equilibrium problem.
        reduce_strength(model_, strength_factor_);
        model_.analysis.geometry = AnalysisSettings::Geometry::Initial;
    }
    topology_ = build_topology(mesh_, p.blocks);
    for (const Block& b : p.blocks) block_region_.push_back(b.region);
    locate_supports();
    elements_ = ElementAssembly(model_, mesh_);
    std::vector<int> all(model_.materials.size());
    for (std::size_t m = 0; m < all.size(); ++m) all[m] = static_cast<int>(m);
    set_material_scales(all);
    initial_state();
    anchor_bolts();
    set_up_shaking();
    if (base_model_.stages.empty()) {
        set_stage_dashpots();
        stages_.push_back({model_.name.empty() ? std::string("analysis") : model_.name, model_.analysis.steps});
        stages_.front().started = true;
        for (std::size_t i = 0; i < model_.bolts.size(); ++i) state_.bolt_force[i] = model_.bolts[i].pretension;
    } else {
        for (const Stage& st : base_model_.stages) stages_.push_back({st.name, st.analysis.steps});
        begin_stage(0);
    }
}

void Simulation::locate_supports() {
    std::vector<Diagnostic> diagnostics;
    bc_ = locate_boundary_conditions(model_, mesh_, topology_, diagnostics);
    if (!has_errors(diagnostics)) return;
    std::string text;
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Diagnostic::Severity::Error)  // the caller says "error: " once
            text += (text.empty() ? "" : "; ") + (d.path.empty() ? d.message : d.path + ": " + d.message);
    throw std::runtime_error(text);
}

void Simulation::set_material_scales(const std::vector<int>& materials) {
    may_yield_ = false;
    double stiffest = 0.0;
    for (int i : materials) {
        const Material& m = model_.materials[i];
        may_yield_ = may_yield_ || (model_.analysis.plasticity && m.may_yield());
        stiffest = std::max(stiffest, m.young_modulus);
    }
    // Automatic penalty: four times the stiffest Young's modulus (N/m per m thickness). The
    // sliding and resting-block benchmarks are right from 1× to 10×; stiffer springs make the
    // contact iteration unstable (docs/penalty-and-time-step.md).
    penalty_ = model_.analysis.penalty > 0.0 ? model_.analysis.penalty : 4.0 * stiffest;
    displacement_limit_ = model_.analysis.max_displacement_ratio * topology_.model_size;
    // A new touching contact starts sliding when the expected slip over the step exceeds this.
    contact_tolerance_ = 1e-6 * displacement_limit_;
}

void Simulation::initial_state() {
    const Eigen::Index dofs = 2 * static_cast<Eigen::Index>(mesh_.nodes.size());
    state_.nodes = mesh_.nodes;
    state_.displacement = Eigen::VectorXd::Zero(dofs);
    state_.velocity = Eigen::VectorXd::Zero(dofs);
    state_.acceleration = Eigen::VectorXd::Zero(dofs);
    state_.time_step = model_.analysis.time_step;
    initial_stresses(model_, mesh_, elements_, state_.points);
    element_averages(state_.points, elements_.points_per_element(), state_);
}

void Simulation::anchor_bolts() {
    const std::size_t bolts = model_.bolts.size();
    state_.bolt_force.assign(bolts, 0.0);
    state_.bolt_broken.assign(bolts, 0);
    bolt_present_.assign(bolts, 1);
    for (std::size_t i = 0; i < bolts; ++i) {
        const Bolt& b = model_.bolts[i];
        for (int end = 0; end < 2; ++end) {
            const Point2 at = end == 0 ? b.from : b.to;
            bolt_anchors_[end].push_back(locate_anchor(mesh_, mesh_.nodes, at));
            if (!bolt_anchors_[end].back())
                throw std::runtime_error("bolt \"" + b.name + "\": its end (" + std::to_string(at.x) + ", " +
                                         std::to_string(at.y) + ") lies in no block");
        }
    }
}

std::vector<double> Simulation::pore_pressures() const {
    std::vector<double> u = element_pore_pressures(model_.water, mesh_, element_nodes());
    const double factor = load_factor(model_, model_.gravity_table, state_.step + state_.step_fraction, state_.time);
    for (double& v : u) v *= factor;
    return u;
}

std::vector<std::pair<std::string, double>> Simulation::load_magnitudes_at(double position) const {
    const double time = state_.time + (position - state_.step - state_.step_fraction) * model_.analysis.time_step;
    std::vector<std::pair<std::string, double>> out;
    for (const PointLoad& l : model_.point_loads)
        out.emplace_back(l.name, std::hypot(l.force.x, l.force.y) * load_factor(model_, l.table, position, time));
    for (const EdgePressure& l : model_.edge_pressures)
        out.emplace_back(l.name, l.pressure * load_factor(model_, l.table, position, time));
    return out;
}

std::vector<std::pair<std::string, double>> Simulation::load_magnitudes() const {
    return load_magnitudes_at(state_.step + state_.step_fraction);
}

CouplingGroup Simulation::coupling(std::initializer_list<int> nodes) const {
    CouplingGroup g;
    for (int node : nodes)
        for (int dir = 0; dir < 2; ++dir) g.equation[g.size++] = bc_.equation[2 * node + dir];
    return g;
}

CouplingGroup Simulation::element_coupling(int e) const {
    CouplingGroup g;
    for (int a = 0; a < elements_.nodes_per_element(); ++a)
        for (int dir = 0; dir < 2; ++dir) g.equation[g.size++] = bc_.equation[2 * elements_.node(e, a) + dir];
    return g;
}

void Simulation::rebuild_pattern_if_needed(const std::vector<Contact>& contacts, const std::vector<BoltLink>& bolts) {
    const int elements = static_cast<int>(mesh_.triangles.size());
    std::vector<CouplingGroup> contact_groups;
    contact_groups.reserve(contacts.size() + bolts.size());
    for (const Contact& c : contacts) {
        const BoundaryEdge& e = topology_.edges[c.edge];
        contact_groups.push_back(coupling({c.node, e.from, e.to}));
    }
    // Bolts come after the contacts (group elements + contacts + i), dashpots after the bolts.
    for (const BoltLink& b : bolts)
        contact_groups.push_back(
            coupling({b.nodes[0], b.nodes[1], b.nodes[2], b.nodes[3], b.nodes[4], b.nodes[5]}));
    for (const ViscousBoundary::Dashpot& d : dashpots_.dashpots()) contact_groups.push_back(coupling({d.node}));
    // Contacts come and go and move between neighbouring edges; as long as the pattern already
    // holds their couplings only the slots change and CHOLMOD's symbolic analysis is kept.
    if (!pattern_stale_ && system_.group_count() >= elements && system_.equations() == bc_.equation_count &&
        system_.set_groups_if_in_pattern(contact_groups, elements))
        return;
    std::vector<CouplingGroup> groups;
    groups.reserve(elements + contacts.size());
    for (int e = 0; e < elements; ++e) groups.push_back(element_coupling(e));
    groups.insert(groups.end(), contact_groups.begin(), contact_groups.end());
    // Reserve the couplings with the neighbouring edges too, where a sliding vertex goes next.
    std::vector<CouplingGroup> reserve;
    for (const Contact& c : contacts) {
        const BoundaryEdge& e = topology_.edges[c.edge];
        if (topology_.edge_into[e.from] >= 0)
            reserve.push_back(coupling({c.node, topology_.edges[topology_.edge_into[e.from]].from, e.from}));
        if (topology_.edge_out_of[e.to] >= 0)
            reserve.push_back(coupling({c.node, e.to, topology_.edges[topology_.edge_out_of[e.to]].to}));
    }
    system_.set_pattern(bc_.equation_count, groups, reserve);
    pattern_stale_ = false;
}

Eigen::VectorXd Simulation::prescribed_increments(double position, double time) const {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(state_.displacement.size());
    for (std::size_t i = 0; i < model_.rollers.size(); ++i) {
        const Roller& r = model_.rollers[i];
        if (!r.moves()) continue;
        const double factor = load_factor(model_, r.table, position, time);
        for (int node : bc_.roller_nodes[i]) {
            if (r.fix_x) d[2 * node] = r.displacement.x * factor - state_.displacement[2 * node];
            if (r.fix_y) d[2 * node + 1] = r.displacement.y * factor - state_.displacement[2 * node + 1];
        }
    }
    return d;
}

void Simulation::record_reactions(const Eigen::VectorXd& residual) {
    state_.roller_reactions.assign(model_.rollers.size(), Point2{0.0, 0.0});
    if (residual.size() != state_.displacement.size()) return;
    for (std::size_t i = 0; i < model_.rollers.size(); ++i)
        for (int node : bc_.roller_nodes[i]) {
            if (model_.rollers[i].fix_x) state_.roller_reactions[i].x -= residual[2 * node];
            if (model_.rollers[i].fix_y) state_.roller_reactions[i].y -= residual[2 * node + 1];
        }
}

std::vector<long long> Simulation::closed_signature(const std::vector<Contact>& contacts,
                                                   const std::vector<BoltLink>& bolts) const {
    std::vector<long long> closed;
    const long long edges = static_cast<long long>(topology_.edges.size()) + 1;
    for (const Contact& c : contacts)
        if (c.state != ContactState::Open)
            closed.push_back((static_cast<long long>(c.node) * edges + c.edge) * 4 + static_cast<int>(c.state));
    for (const BoltLink& b : bolts) closed.push_back(-1 - b.bolt);
    return closed;
}

ContactKinematics Simulation::kinematics_of(const Contact& c) const {
    if (model_.analysis.geometry == AnalysisSettings::Geometry::Updated)
        return contact_kinematics(c, state_.nodes, topology_);
    // Small displacements: the pairing, normal and shear directions of the undeformed shape; the
    // gap moves with the relative displacement along that normal (linear in the displacements).
    ContactKinematics k = contact_kinematics(c, mesh_.nodes, topology_);
    for (int a = 0; a < 3; ++a)
        for (int dir = 0; dir < 2; ++dir) k.gap += k.normal[2 * a + dir] * state_.displacement[2 * k.nodes[a] + dir];
    return k;
}

void Simulation::commit(const Eigen::VectorXd& d, double dt, const std::vector<Contact>& contacts,
                        const std::vector<BoltLink>& bolts) {
    for (const BoltLink& b : bolts) state_.bolt_force[b.bolt] = b.force_after(d);
    for (std::size_t i = 0; i < bolt_broken_try_.size(); ++i)
        if (bolt_broken_try_[i] && !state_.bolt_broken[i]) {
            state_.bolt_broken[i] = 1;
            state_.bolt_force[i] = 0.0;
            pending_events_.push_back("bolt \"" + base_model_.bolts[i].name + "\" broke in step " +
                                      std::to_string(state_.step + 1) + " (strength " +
                                      std::to_string(base_model_.bolts[i].strength) + " N/m)");
        }
    bolt_broken_try_.clear();
    // Stresses as returned for the accepted increments.
    PointStates& points = state_.points;
    for (std::size_t p = 0; p < points.stress.size(); ++p) {
        const ReturnResult& r = returned_[p];
        points.stress[p] = Eigen::Vector3d(r.stress.xx, r.stress.yy, r.stress.xy);
        points.stress_zz[p] = r.stress.zz;
        points.plastic_strain[p] += r.equivalent_plastic_strain;
        if (r.plastic) points.plastic_state[p] = 2;
        else if (points.plastic_state[p] == 2) points.plastic_state[p] = 1;
    }
    element_averages(points, elements_.points_per_element(), state_);
    state_.contacts = contacts;
    for (Contact& c : state_.contacts) {
        const ContactKinematics k = kinematics_of(c);
        Vector6 local;
        for (int a = 0; a < 3; ++a)
            for (int dir = 0; dir < 2; ++dir) local[2 * a + dir] = d[2 * k.nodes[a] + dir];
        commit_contact(c, k, local, model_.analysis.strength_reduction);
    }
    for (std::size_t i = 0; i < state_.nodes.size(); ++i) {
        state_.nodes[i].x += d[2 * i];
        state_.nodes[i].y += d[2 * i + 1];
    }
    state_.displacement += d;
    if (model_.analysis.kind == AnalysisSettings::Kind::Dynamic) {
        // Newmark: a1 from the increment, then v1; Shi's scheme is the case β = ½, γ = 1.
        const auto [beta, gamma] = newmark_for(state_.step, model_.analysis.newmark_gamma);
        const Eigen::VectorXd a1 = (d - dt * state_.velocity - dt * dt * (0.5 - beta) * state_.acceleration) /
                                   (beta * dt * dt);
        state_.velocity = model_.analysis.dynamic_ratio *
                          (state_.velocity + dt * ((1.0 - gamma) * state_.acceleration + gamma * a1));
        state_.acceleration = model_.analysis.dynamic_ratio * a1;
    } else {
        state_.velocity.setZero();  // static: kinetic damping, velocities reset every step
        state_.acceleration.setZero();
    }
}

void Simulation::finish_report(StepReport& report, double largest, const Eigen::VectorXd& residual,
                               std::optional<double> ratio) {
    // A small-strain static step's converged residual is the out-of-balance force of the state
    // reached already (no mass term, loads and elements on the undeformed shape), as the
    // iterations judged it; otherwise the state is evaluated once more without the inertia that
    // balanced it.
    const bool converged = is_equilibrium_only() && residual.size() == state_.displacement.size();
    state_.unbalanced_ratio = ratio ? *ratio : unbalanced_ratio(converged ? &residual : nullptr);
    report.unbalanced_ratio = state_.unbalanced_ratio;
    report.stage = stage_;
    StageRecord& record = stages_[stage_];
    record.last_step = state_.step;
    record.unbalanced_ratio = state_.unbalanced_ratio;
    const double target = base_model_.stages.empty() ? 0.0 : base_model_.stages[stage_].target_ratio;
    // (Only once the stage's release is complete: until then every step is in equilibrium with
    // the part still held.)
    const bool released = base_model_.stages.empty() ||
                          base_model_.stages[stage_].released(state_.step - stage_start_step_, base_model_.load_tables) >= 1.0;
    record.reached_target = target > 0.0 && released && model_.analysis.kind == AnalysisSettings::Kind::Static &&
                            state_.unbalanced_ratio <= target;
    record.finished = stage_complete();
    if (record.reached_target && state_.step - stage_start_step_ < model_.analysis.steps)
        pending_events_.push_back("stage \"" + record.name + "\" reached its target ratio at step " +
                                  std::to_string(state_.step));
    report.events = std::move(pending_events_);
    pending_events_.clear();
    report.step = state_.step;
    report.time = state_.time;
    report.max_increment = std::max(report.max_increment, largest);
    report.yielding = 0;
    for (unsigned char p : state_.plastic_state) report.yielding += p == 2;
    report.open = report.sliding = report.locked = 0;
    for (const Contact& c : state_.contacts) {
        report.open += c.state == ContactState::Open;
        report.sliding += c.state == ContactState::Sliding;
        report.locked += c.state == ContactState::Locked;
    }
    timings_.iterations += report.plastic_iterations;
    timings_.max_iterations = std::max(timings_.max_iterations, report.plastic_iterations);
    record_solver_counts();
}

double Simulation::largest_increment(const Eigen::VectorXd& d) {
    double largest = 0.0;
    for (Eigen::Index i = 0; i + 1 < d.size(); i += 2) largest = std::max(largest, std::hypot(d[i], d[i + 1]));
    return largest;
}

int Simulation::inverted_element(const Eigen::VectorXd& d) const {
    if (model_.analysis.geometry == AnalysisSettings::Geometry::Initial) return -1;
    const std::vector<Point2>& nodes = element_nodes();
    auto twice_area = [](const Point2& p, const Point2& q, const Point2& r) {
        return (q.x - p.x) * (r.y - p.y) - (r.x - p.x) * (q.y - p.y);
    };
    for (int e = 0; e < static_cast<int>(mesh_.triangles.size()); ++e) {
        if (!elements_.active(e)) continue;
        Point2 before[3], after[3];
        for (int a = 0; a < 3; ++a) {
            const int n = mesh_.triangles[e][a];
            before[a] = nodes[n];
            after[a] = {nodes[n].x + d[2 * n], nodes[n].y + d[2 * n + 1]};
        }
        // (the sign of the area before, not its orientation by convention, is the reference)
        if (!(twice_area(before[0], before[1], before[2]) * twice_area(after[0], after[1], after[2]) > 0.0)) return e;
    }
    return -1;
}

void Simulation::record_solver_counts() {
    timings_.factorization = system_.factorization_seconds();
    timings_.factorizations = system_.factorizations();
    timings_.symbolic_analyses = system_.symbolic_analyses();
    timings_.reused_factors = system_.reused_factors();
    timings_.refinement_iterations = system_.refinement_iterations();
    timings_.ordering = system_.ordering();
    timings_.factorization_flops = system_.factorization_flops();
}

std::vector<BoltLink> Simulation::bolt_links() const {
    std::vector<BoltLink> links;
    for (std::size_t i = 0; i < base_model_.bolts.size(); ++i) {
        if (!bolt_present_[i] || state_.bolt_broken[i] || (i < bolt_broken_try_.size() && bolt_broken_try_[i])) continue;
        const Bolt& b = base_model_.bolts[i];
        const double length = std::hypot(b.to.x - b.from.x, b.to.y - b.from.y);
        links.push_back(make_bolt_link(*bolt_anchors_[0][i], *bolt_anchors_[1][i], element_nodes(), b.stiffness, length,
                                       state_.bolt_force[i],
                                       model_.analysis.geometry == AnalysisSettings::Geometry::Updated));
        links.back().bolt = static_cast<int>(i);
    }
    return links;
}

Simulation::ForceBalance Simulation::out_of_balance() {
    const Eigen::Index dofs = state_.displacement.size();
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dofs);
    ForceBalance balance;
    balance.applied = applied_forces(state_.step + state_.step_fraction, state_.time);
    elements_.prepare(element_nodes(), 0.0);  // the next try prepares its own
    std::vector<ReturnResult> returned;
    balance.residual = residual(zero, balance.applied, contact_set(state_.contacts), bolt_links(), returned,
                                ElementMatrix::None, nullptr, &balance.internal);
    return balance;
}

// Per block, so that a loose block in a large model is not lost in the model's total (a block
// sliding down an incline is out of balance by a quarter of its weight, a thousandth of the
// slope's); sums within the block, so that the ratio does not depend on the element size. A
// block whose forces are below a thousandth of the largest block's is measured against that
// thousandth: a sliver's round-off must not decide the verdict.
double Simulation::unbalanced_ratio(const Eigen::VectorXd* residual) {
    ForceBalance balance = out_of_balance();
    if (residual) balance.residual = *residual;
    const int blocks = mesh_.block_count();
    std::vector<double> unbalanced(blocks, 0.0), in_play(blocks, 0.0);
    for (std::size_t node = 0; node < mesh_.nodes.size(); ++node) {
        const int b = mesh_.node_block[node];
        if (!block_active_.empty() && !block_active_[b]) continue;
        const Eigen::Index x = 2 * static_cast<Eigen::Index>(node), y = x + 1;
        unbalanced[b] += std::hypot(bc_.equation[x] >= 0 ? balance.residual[x] : 0.0,
                                    bc_.equation[y] >= 0 ? balance.residual[y] : 0.0);
        in_play[b] += std::max(std::hypot(balance.applied[x], balance.applied[y]),
                               std::hypot(balance.internal[x], balance.internal[y]));
    }
    const double floor = 1e-3 * *std::max_element(in_play.begin(), in_play.end());
    double ratio = 0.0;
    for (int b = 0; b < blocks; ++b)
        if (in_play[b] > 0.0 || unbalanced[b] > 0.0) ratio = std::max(ratio, unbalanced[b] / std::max({in_play[b], floor, 1e-300}));
    return ratio;
}

std::array<Point2, 2> Simulation::bolt_ends(int i) const {
    return {anchor_position(*bolt_anchors_[0][i], state_.nodes), anchor_position(*bolt_anchors_[1][i], state_.nodes)};
}

bool Simulation::stage_complete() const {
    const StageRecord& r = stages_[stage_];
    return r.reached_target || state_.step - stage_start_step_ >= model_.analysis.steps;
}

SimulationCheckpoint Simulation::checkpoint() const {
    return {state_, model_, element_active_, block_active_, bolt_present_, mesh_.triangle_material, stages_, stage_,
            stage_start_step_};
}

void Simulation::restore(const SimulationCheckpoint& c) {
    state_ = c.state;
    model_ = c.model;
    element_active_ = c.element_active;
    block_active_ = c.block_active;
    bolt_present_ = c.bolt_present;
    mesh_.triangle_material = c.triangle_material;
    stages_ = c.stages;
    stage_ = c.stage;
    stage_start_step_ = c.stage_start_step;
    collapse_.reset();
    held_ = HeldFactor{};
    pattern_stale_ = true;
    pending_events_.clear();
    elements_ = ElementAssembly(model_, mesh_);
    elements_.set_active(element_active_);
}

bool Simulation::finished() const { return stage_ + 1 >= static_cast<int>(stages_.size()) && stage_complete(); }

int Simulation::planned_steps() const {
    int steps = 0;
    for (const StageRecord& r : stages_) steps += r.finished ? r.last_step - r.first_step : r.planned_steps;
    return steps;
}

StepReport Simulation::advance() {
    const auto start = Clock::now();
    StepReport report;
    if (finished()) throw std::runtime_error("the analysis has run all its steps");
    iterating_ = IterationInfo{};
    iterating_.step = state_.step + 1;
    step_contraction_ = 0.0;  // measured anew in every step (ConvergenceMonitor::settled)
    try {
        if (stage_complete()) begin_stage(stage_ + 1);
        report = model_.analysis.kind == AnalysisSettings::Kind::Static ? advance_static() : advance_dynamic();
    } catch (const PlasticCollapse& e) {
        collapse_ = CollapseBracket{e.carried, e.not_carried, e.motion};
        timings_.total += seconds_since(start);
        record_solver_counts();
        throw;
    } catch (...) {
        timings_.total += seconds_since(start);
        record_solver_counts();
        throw;
    }
    timings_.total += seconds_since(start);
    return report;
}

}  // namespace mcdda

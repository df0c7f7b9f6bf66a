#include "run/Simulation.hpp"

#include "contact/ContactDetection.hpp"
#include "contact/ContactLaw.hpp"
#include "fem/PlaneStrain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mcdda {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr int max_time_step_cuts = 30;
/// A plastic step of a model with contacts is a collapse only below this fraction of the set Δt.
constexpr double plastic_collapse_time_step = 1e-4;

// Time integration: Newmark with γ = 0.7, β = (γ + ½)²/4. Shi's DDA scheme (β = ½, γ = 1) does
// not damp the highest frequencies at all: the velocity of a stiff contact spring flips sign every
// step for ever, and in a sliding block that chatter reverses the slip and locks contacts. This
// member damps those frequencies (spectral radius about 0.67 at ωΔt → ∞) and, like every Newmark
// member, integrates a constant acceleration exactly (the sliding-block solution).
// The first dynamic step knows no acceleration yet (a0 = 0 would be wrong by the whole load and
// that error would ring for many steps), so it uses Shi's member, which does not involve a0.
constexpr double newmark_gamma = 0.7;
constexpr double newmark_beta = (newmark_gamma + 0.5) * (newmark_gamma + 0.5) / 4.0;

struct NewmarkParameters {
    double beta, gamma;
};

NewmarkParameters newmark_for(int step) {
    return step == 0 ? NewmarkParameters{0.5, 1.0} : NewmarkParameters{newmark_beta, newmark_gamma};
}

}  // namespace

void initial_stresses(const Model& model, const Mesh& mesh, std::vector<Eigen::Vector3d>& stress,
                      std::vector<double>& stress_zz) {
    const std::size_t n = mesh.triangles.size();
    stress.assign(n, Eigen::Vector3d::Zero());
    stress_zz.assign(n, 0.0);
    const InitialStress& s = model.initial_stress;
    const double g = std::hypot(model.gravity.x, model.gravity.y);
    for (std::size_t e = 0; e < n; ++e) {
        const Material& m = model.materials[mesh.triangle_material[e]];
        Eigen::Vector3d sigma = Eigen::Vector3d::Zero();
        if (s.kind == InitialStress::Kind::Uniform) {
            sigma = Eigen::Vector3d(s.stress[0], s.stress[1], s.stress[2]);
        } else if (s.kind == InitialStress::Kind::Gravity) {
            const auto& t = mesh.triangles[e];
            const double y = (mesh.nodes[t[0]].y + mesh.nodes[t[1]].y + mesh.nodes[t[2]].y) / 3.0;
            const double vertical = m.density * g * std::max(0.0, s.surface_y - y);  // compressive magnitude
            sigma = Eigen::Vector3d(-s.k0 * vertical, -vertical, 0.0);
        }
        stress[e] = sigma;
        // Plane strain: unless given, the out-of-plane stress that an elastic loading from zero
        // in plane strain would give (εzz = 0).
        stress_zz[e] = s.kind == InitialStress::Kind::Uniform && s.stress_zz ? *s.stress_zz
                                                                              : m.poisson_ratio * (sigma[0] + sigma[1]);
    }
}

Simulation::Simulation(const Preprocessed& p) : model_(p.model), mesh_(p.mesh) {
    if (mesh_.triangles.empty()) throw std::runtime_error("the model has no mesh");
    topology_ = build_topology(mesh_, p.blocks);
    std::vector<Diagnostic> diagnostics;
    bc_ = locate_boundary_conditions(model_, mesh_, topology_, diagnostics);
    if (has_errors(diagnostics)) {
        std::string text;
        for (const Diagnostic& d : diagnostics)
            if (d.severity == Diagnostic::Severity::Error) text += (text.empty() ? "" : "; ") + format_diagnostic(d);
        throw std::runtime_error(text);
    }
    double stiffest = 0.0;
    for (const Material& m : model_.materials) {
        elasticity_.push_back(plane_strain_elasticity(m.young_modulus, m.poisson_ratio));
        yield_criteria_.emplace_back(m);
        plastic_material_.push_back(model_.analysis.plasticity && m.plastic);
        stiffest = std::max(stiffest, m.young_modulus);
    }
    // Automatic penalty: four times the stiffest Young's modulus (N/m per m thickness). The
    // sliding and resting-block benchmarks are right from 1× to 10×; stiffer springs make the
    // contact iteration unstable (docs/penalty-and-time-step.md).
    penalty_ = model_.analysis.penalty > 0.0 ? model_.analysis.penalty : 4.0 * stiffest;
    displacement_limit_ = model_.analysis.max_displacement_ratio * topology_.model_size;
    // A new touching contact starts sliding when the expected slip over the step exceeds this.
    contact_tolerance_ = 1e-6 * displacement_limit_;

    const std::size_t n = mesh_.nodes.size();
    state_.nodes = mesh_.nodes;
    state_.displacement = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(n));
    state_.velocity = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(n));
    state_.acceleration = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(n));
    state_.time_step = model_.analysis.time_step;
    initial_stresses(model_, mesh_, state_.stress, state_.stress_zz);
    state_.plastic_strain.assign(mesh_.triangles.size(), 0.0);
    state_.plastic_state.assign(mesh_.triangles.size(), 0);
}

std::vector<std::pair<std::string, double>> Simulation::load_magnitudes() const {
    std::vector<std::pair<std::string, double>> out;
    for (const PointLoad& l : model_.point_loads)
        out.emplace_back(l.name, std::hypot(l.force.x, l.force.y) * load_factor(model_, l.table, state_.step, state_.time));
    for (const EdgePressure& l : model_.edge_pressures)
        out.emplace_back(l.name, l.pressure * load_factor(model_, l.table, state_.step, state_.time));
    return out;
}

CouplingGroup Simulation::coupling(std::initializer_list<int> nodes) const {
    CouplingGroup g;
    for (int node : nodes)
        for (int dir = 0; dir < 2; ++dir) g.equation[g.size++] = bc_.equation[2 * node + dir];
    return g;
}

void Simulation::rebuild_pattern_if_needed(const std::vector<Contact>& contacts) {
    const int elements = static_cast<int>(mesh_.triangles.size());
    std::vector<CouplingGroup> contact_groups;
    contact_groups.reserve(contacts.size());
    for (const Contact& c : contacts) {
        const BoundaryEdge& e = topology_.edges[c.edge];
        contact_groups.push_back(coupling({c.node, e.from, e.to}));
    }
    // Contacts come and go and move between neighbouring edges; as long as the pattern already
    // holds their couplings only the slots change and CHOLMOD's symbolic analysis is kept.
    if (system_.group_count() >= elements && system_.equations() == bc_.equation_count &&
        system_.pattern_contains(contact_groups)) {
        system_.set_groups(contact_groups, elements);
        return;
    }
    std::vector<CouplingGroup> groups;
    groups.reserve(elements + contacts.size());
    for (const auto& t : mesh_.triangles) groups.push_back(coupling({t[0], t[1], t[2]}));
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
}

Eigen::VectorXd Simulation::solve_increments(const Eigen::VectorXd& external, double dt, std::vector<Contact>& contacts,
                                             int& iterations) {
    const auto start_assembly = Clock::now();
    plastic_iterations_ = 0;
    rebuild_pattern_if_needed(contacts);
    const int elements = static_cast<int>(mesh_.triangles.size());
    const Eigen::Index dofs = state_.displacement.size();

    // Element part: stiffness, inertia and the out-of-balance force of the accumulated stress.
    // It does not change during the open–close iterations, so it is assembled once per step.
    system_.clear_values();
    Eigen::VectorXd base_force = external;
    const double beta = newmark_for(state_.step).beta;
    const double inertia = 1.0 / (beta * dt * dt);
    const bool carry_velocity = model_.analysis.kind == AnalysisSettings::Kind::Dynamic;
    shapes_.resize(elements);
    for (int e = 0; e < elements; ++e) {
        const auto& t = mesh_.triangles[e];
        const TriangleShape& s = shapes_[e] = triangle_shape(state_.nodes[t[0]], state_.nodes[t[1]], state_.nodes[t[2]]);
        const Material& m = model_.materials[mesh_.triangle_material[e]];
        Matrix6 k = s.area * s.B.transpose() * elasticity_[mesh_.triangle_material[e]] * s.B;
        const Vector6 internal = s.area * s.B.transpose() * state_.stress[e];
        const double mass = m.density * s.area;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                for (int dir = 0; dir < 2; ++dir) k(2 * a + dir, 2 * b + dir) += inertia * mass * consistent_mass_factor(a, b);
        system_.add(e, k.data());
        for (int a = 0; a < 3; ++a)
            for (int dir = 0; dir < 2; ++dir) {
                double f = -internal[2 * a + dir];
                if (carry_velocity)
                    for (int b = 0; b < 3; ++b) {
                        const int dof = 2 * t[b] + dir;
                        f += mass * consistent_mass_factor(a, b) *
                             (state_.velocity[dof] / (beta * dt) + (0.5 - beta) / beta * state_.acceleration[dof]);
                    }
                base_force[2 * t[a] + dir] += f;
            }
    }
    system_.save_values(element_values_);
    timings_.assembly += seconds_since(start_assembly);

    const auto start_contact = Clock::now();
    std::vector<ContactKinematics> kinematics;
    std::vector<ContactProperties> properties;
    kinematics.reserve(contacts.size());
    properties.reserve(contacts.size());
    for (const Contact& c : contacts) {
        kinematics.push_back(contact_kinematics(c, state_.nodes, topology_));
        properties.push_back(contact_properties(c, kinematics.back(), model_, topology_, penalty_));
    }
    timings_.contact += seconds_since(start_contact);

    Eigen::VectorXd d = Eigen::VectorXd::Zero(dofs);
    Eigen::VectorXd rhs(bc_.equation_count);
    const int max_iterations = model_.analysis.max_open_close_iterations;
    constexpr int max_friction_rounds = 10;
    bool factor_valid = false;
    int friction_rounds = 0;
    std::vector<int> flips(contacts.size(), 0);
    iterations = 1;
    while (iterations <= max_iterations) {
        // K changes only when a contact changes state: then assemble and factorise again.
        if (!factor_valid) {
            const auto t0 = Clock::now();
            system_.restore_values(element_values_);
            Matrix6 kc;
            Vector6 fc;
            for (std::size_t i = 0; i < contacts.size(); ++i) {
                if (contacts[i].state == ContactState::Open) continue;
                contact_terms(contacts[i], kinematics[i], properties[i], kc, fc);
                system_.add(elements + static_cast<int>(i), kc.data());
            }
            timings_.assembly += seconds_since(t0);
            const auto t1 = Clock::now();
            system_.factorize();
            timings_.factorization += seconds_since(t1);
            factor_valid = true;
        }
        const auto t0 = Clock::now();
        Eigen::VectorXd force = base_force;
        Matrix6 kc;
        Vector6 fc;
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            if (contacts[i].state == ContactState::Open) continue;
            contact_terms(contacts[i], kinematics[i], properties[i], kc, fc);
            for (int a = 0; a < 3; ++a)
                for (int dir = 0; dir < 2; ++dir) force[2 * kinematics[i].nodes[a] + dir] += fc[2 * a + dir];
        }
        for (Eigen::Index dof = 0; dof < dofs; ++dof)
            if (bc_.equation[dof] >= 0) rhs[bc_.equation[dof]] = force[dof];
        timings_.assembly += seconds_since(t0);

        d = solve_reduced(rhs);

        // Plastic loop (initial stress method, Table 1 steps 7–16): the stress the yield surface
        // cannot carry becomes a body load, re-solved with the same factor until the
        // increments settle; every iteration costs one back-substitution.
        Eigen::VectorXd plastic_load = Eigen::VectorXd::Zero(dofs);
        int yielding = update_stresses(d, &plastic_load);
        for (int k = 1; yielding > 0; ++k) {
            if (k > model_.analysis.max_plastic_iterations)
                throw PlasticCollapse("the plastic iterations did not converge within " +
                                      std::to_string(model_.analysis.max_plastic_iterations) + " (" +
                                      std::to_string(yielding) + " elements yielding)");
            Eigen::VectorXd loaded = rhs;
            for (Eigen::Index dof = 0; dof < dofs; ++dof)
                if (bc_.equation[dof] >= 0) loaded[bc_.equation[dof]] += plastic_load[dof];
            const Eigen::VectorXd next = solve_reduced(loaded);
            const double change = (next - d).cwiseAbs().maxCoeff();
            // Relative to the increment, but not below a hundredth of the displacement so far: in
            // a step that only re-equilibrates, the increment is round-off and would never settle.
            const double size = std::max({next.cwiseAbs().maxCoeff(), 0.01 * state_.displacement.cwiseAbs().maxCoeff(),
                                          1e-12 * topology_.model_size});
            d = next;
            ++plastic_iterations_;
            plastic_load.setZero();
            yielding = update_stresses(d, &plastic_load);
            if (change <= model_.analysis.plastic_tolerance * size) break;
        }

        const auto t3 = Clock::now();
        int changes = 0;
        double friction_used = 0.0, friction_change = 0.0;
        std::vector<std::pair<std::size_t, Contact>> marginal;  // negligible changes: index, state before
        // Negligible: a thousandth of the largest contact force of the last solve.
        double largest_force = 0.0;
        for (const Contact& c : contacts) largest_force = std::max(largest_force, std::fabs(c.normal_force));
        const double force_tolerance = 1e-3 * largest_force;
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            Vector6 local;
            for (int a = 0; a < 3; ++a)
                for (int dir = 0; dir < 2; ++dir) local[2 * a + dir] = d[2 * kinematics[i].nodes[a] + dir];
            const Contact before = contacts[i];
            const double normal_used = std::max(0.0, before.normal_force);
            StateChange change =
                update_contact_state(contacts[i], kinematics[i], properties[i], local, force_tolerance);
            // A contact that already changed twice in this step is cycling (stick–slip or
            // open–close at its limit): it no longer holds the iteration open; its last change
            // is kept only if the step ends without other changes.
            if (change == StateChange::Significant && ++flips[i] > 2) change = StateChange::Marginal;
            if (change == StateChange::Significant) ++changes;
            if (change == StateChange::Marginal) marginal.emplace_back(i, before);
            if (before.state == ContactState::Sliding && contacts[i].state == ContactState::Sliding) {
                friction_used += normal_used * properties[i].tan_friction;
                friction_change +=
                    std::fabs(std::max(0.0, contacts[i].normal_force) - normal_used) * properties[i].tan_friction;
            }
        }
        // Marginal changes are undone while the iteration goes on: a solution that made
        // significant changes is not trusted for them (acting on them lets one wrong guess
        // cascade through a block), and the friction rounds below must use the states K was
        // factorised with. They are kept when the step ends here.
        auto undo_marginal = [&] {
            for (const auto& [i, before] : marginal) {
                contacts[i].state = before.state;
                contacts[i].slip = before.slip;
                contacts[i].shear_spring = before.shear_spring;
            }
        };
        if (changes > 0) undo_marginal();
        timings_.contact += seconds_since(t3);
        if (changes > 0) {
            // At the iteration limit a handful of changes among many contacts is accepted (they
            // take effect next step); more means the step is too large: Δt is cut (Shi).
            if (iterations == max_iterations && changes <= std::max(2, static_cast<int>(contacts.size() / 500))) return d;
            factor_valid = false;
            ++iterations;
            continue;
        }
        // Friction of sliding contacts was taken from the normal forces of the previous solve;
        // repeat with the same factor until they agree (a back-substitution each).
        if (friction_change <= 1e-3 * friction_used || ++friction_rounds > max_friction_rounds) return d;
        undo_marginal();
    }
    iterations = max_iterations + 1;  // not settled
    return d;
}

Eigen::VectorXd Simulation::solve_reduced(const Eigen::VectorXd& rhs) {
    const auto start = Clock::now();
    const Eigen::VectorXd solution = system_.solve(rhs);
    Eigen::VectorXd d(state_.displacement.size());
    for (Eigen::Index dof = 0; dof < d.size(); ++dof)
        d[dof] = bc_.equation[dof] >= 0 ? solution[bc_.equation[dof]] : 0.0;
    timings_.solve += seconds_since(start);
    return d;
}

int Simulation::update_stresses(const Eigen::VectorXd& d, Eigen::VectorXd* plastic_load) {
    const auto start = Clock::now();
    const int elements = static_cast<int>(mesh_.triangles.size());
    returned_.resize(elements);
    int yielding = 0;
    for (int e = 0; e < elements; ++e) {
        const auto& t = mesh_.triangles[e];
        const int material = mesh_.triangle_material[e];
        const TriangleShape& shape = shapes_[e];
        Vector6 de;
        for (int a = 0; a < 3; ++a)
            for (int dir = 0; dir < 2; ++dir) de[2 * a + dir] = d[2 * t[a] + dir];
        // Elastic trial on the start-of-step geometry (updated Lagrangian, small increments).
        const Eigen::Vector3d increment = elasticity_[material] * (shape.B * de);
        const Eigen::Vector3d& old = state_.stress[e];
        const PlaneStress trial{old[0] + increment[0], old[1] + increment[1], old[2] + increment[2],
                                state_.stress_zz[e] + model_.materials[material].poisson_ratio * (increment[0] + increment[1])};
        ReturnResult& r = returned_[e];
        if (plastic_material_[material]) {
            r = yield_criteria_[material].return_map(trial);
        } else {
            r = ReturnResult{};
            r.stress = trial;
        }
        if (!r.plastic) continue;
        ++yielding;
        if (plastic_load) {
            const Eigen::Vector3d excess(trial.xx - r.stress.xx, trial.yy - r.stress.yy, trial.xy - r.stress.xy);
            const Vector6 f = shape.area * shape.B.transpose() * excess;
            for (int a = 0; a < 3; ++a)
                for (int dir = 0; dir < 2; ++dir) (*plastic_load)[2 * t[a] + dir] += f[2 * a + dir];
        }
    }
    timings_.plasticity += seconds_since(start);
    return yielding;
}

void Simulation::commit(const Eigen::VectorXd& d, double dt, const std::vector<Contact>& contacts) {
    // Stresses as returned for the accepted increments.
    for (std::size_t e = 0; e < mesh_.triangles.size(); ++e) {
        const ReturnResult& r = returned_[e];
        state_.stress[e] = Eigen::Vector3d(r.stress.xx, r.stress.yy, r.stress.xy);
        state_.stress_zz[e] = r.stress.zz;
        state_.plastic_strain[e] += r.equivalent_plastic_strain;
        if (r.plastic) state_.plastic_state[e] = 2;
        else if (state_.plastic_state[e] == 2) state_.plastic_state[e] = 1;
    }
    state_.contacts = contacts;
    for (Contact& c : state_.contacts) {
        const ContactKinematics k = contact_kinematics(c, state_.nodes, topology_);
        Vector6 local;
        for (int a = 0; a < 3; ++a)
            for (int dir = 0; dir < 2; ++dir) local[2 * a + dir] = d[2 * k.nodes[a] + dir];
        commit_contact(c, k, local);
    }
    for (std::size_t i = 0; i < state_.nodes.size(); ++i) {
        state_.nodes[i].x += d[2 * i];
        state_.nodes[i].y += d[2 * i + 1];
    }
    state_.displacement += d;
    if (model_.analysis.kind == AnalysisSettings::Kind::Dynamic)
    {
        // Newmark: a1 from the increment, then v1; Shi's scheme is the case β = ½, γ = 1.
        const auto [beta, gamma] = newmark_for(state_.step);
        const Eigen::VectorXd a1 = (d - dt * state_.velocity - dt * dt * (0.5 - beta) * state_.acceleration) /
                                   (beta * dt * dt);
        state_.velocity = model_.analysis.dynamic_ratio *
                          (state_.velocity + dt * ((1.0 - gamma) * state_.acceleration + gamma * a1));
        state_.acceleration = model_.analysis.dynamic_ratio * a1;
    }
    else
    {
        state_.velocity.setZero();  // static: kinetic damping, velocities reset every step
        state_.acceleration.setZero();
    }
    state_.step += 1;
    state_.time += dt;
}

StepReport Simulation::advance() {
    const auto start = Clock::now();
    StepReport report;
    const double largest_step = model_.analysis.time_step;
    for (int cut = 0; cut <= max_time_step_cuts; ++cut) {
        const double dt = state_.time_step;
        const auto t0 = Clock::now();
        std::vector<Contact> contacts =
            detect_contacts(state_.nodes, mesh_, topology_, 2.5 * displacement_limit_, state_.contacts,
                            model_.analysis.kind == AnalysisSettings::Kind::Dynamic ? state_.velocity * dt
                                                                                     : Eigen::VectorXd(),
                            contact_tolerance_);
        timings_.contact += seconds_since(t0);
        const Eigen::VectorXd external =
            external_forces(model_, mesh_, state_.nodes, topology_, bc_, state_.step + 1, state_.time + dt);
        int iterations = 0;
        Eigen::VectorXd d;
        try {
            d = solve_increments(external, dt, contacts, iterations);
        } catch (const PlasticCollapse&) {
            // Between blocks, rock asked to carry too much is often a wrong contact guess at this
            // Δt (a joint that should open or slide); a smaller Δt adds inertia and lets the
            // contacts sort themselves out, as for unsettled contacts. Without contacts, or once
            // Δt is tiny, it is a collapse.
            const bool any_contact = std::any_of(contacts.begin(), contacts.end(),
                                                 [](const Contact& c) { return c.state != ContactState::Open; });
            if (!any_contact || dt < plastic_collapse_time_step * largest_step) throw;
            d = Eigen::VectorXd::Zero(state_.displacement.size());
            iterations = 0;  // not settled: Δt is halved below
        } catch (const SingularSystem& e) {
            // A block that lost its contacts is free: only inertia holds it, and at this Δt too
            // little of it. A smaller Δt adds inertia (M/βΔt²); give up only when Δt is tiny.
            last_singular_ = e.what();
            d = Eigen::VectorXd::Constant(state_.displacement.size(), std::numeric_limits<double>::infinity());
            iterations = 0;
        }
        timings_.factorizations = system_.factorizations();
        timings_.symbolic_analyses = system_.symbolic_analyses();
        if (!d.allFinite() && last_singular_.empty())
            throw std::runtime_error("the solution diverged (non-finite displacements)");
        double largest = 0.0;
        for (Eigen::Index i = 0; i + 1 < d.size(); i += 2) largest = std::max(largest, std::hypot(d[i], d[i + 1]));
        const bool settled = iterations > 0 && iterations <= model_.analysis.max_open_close_iterations;
        if (largest > displacement_limit_ || !settled) {
            // Too large a step, or contacts that do not settle: a smaller Δt (Shi).
            const double factor = !d.allFinite() ? 0.1
                                  : settled      ? std::clamp(0.9 * std::sqrt(displacement_limit_ / largest), 0.1, 0.5)
                                                 : 0.5;
            state_.time_step = dt * factor;
            report.time_step_cuts++;
            if (state_.time_step < 1e-9 * largest_step)
                throw std::runtime_error("the time step fell below 1e-9 of its set value at step " +
                                         std::to_string(state_.step + 1) +
                                         (last_singular_.empty() ? " (contacts do not settle)" : ": " + last_singular_));
            last_singular_.clear();
            continue;
        }
        commit(d, dt, contacts);
        report.step = state_.step;
        report.time = state_.time;
        report.time_step = dt;
        report.open_close_iterations = iterations;
        report.max_increment = largest;
        report.plastic_iterations = plastic_iterations_;
        for (unsigned char p : state_.plastic_state) report.yielding += p == 2;
        for (const Contact& c : state_.contacts) {
            report.open += c.state == ContactState::Open;
            report.sliding += c.state == ContactState::Sliding;
            report.locked += c.state == ContactState::Locked;
        }
        // Grow Δt back towards its set value while steps are comfortably small.
        if (largest < 0.5 * displacement_limit_ && iterations <= 2)
            state_.time_step = std::min(largest_step, dt * 1.25);
        timings_.total += seconds_since(start);
        return report;
    }
    throw std::runtime_error("step " + std::to_string(state_.step + 1) + " could not be completed after " +
                             std::to_string(max_time_step_cuts) + " cuts of the time step");
}

}  // namespace mcdda

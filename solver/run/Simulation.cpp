#include "run/Simulation.hpp"

#include "contact/ContactDetection.hpp"
#include "contact/ContactLaw.hpp"
#include "fem/PlaneStrain.hpp"
#include "linalg/AndersonMixing.hpp"
#include "model/StrengthReduction.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
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

void initial_stresses(const Model& model, const Mesh& mesh, const ElementAssembly& elements, PointStates& points) {
    const int per_element = elements.points_per_element();
    const std::size_t n = mesh.triangles.size() * per_element;
    points.resize(n);
    const InitialStress& s = model.initial_stress;
    const double g = std::hypot(model.gravity.x, model.gravity.y);
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const Material& m = model.materials[mesh.triangle_material[e]];
        for (int q = 0; q < per_element; ++q) {
            const std::size_t p = e * per_element + q;
            Eigen::Vector3d sigma = Eigen::Vector3d::Zero();
            if (s.kind == InitialStress::Kind::Uniform) {
                sigma = Eigen::Vector3d(s.stress[0], s.stress[1], s.stress[2]);
            } else if (s.kind == InitialStress::Kind::Gravity) {
                // At the integration point: a six-node element carries the linear gravity field exactly.
                const double y = elements.point_position(mesh.nodes, static_cast<int>(e), q).y;
                const double vertical = m.density * g * std::max(0.0, s.surface_y - y);  // compressive magnitude
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

namespace {

/// Element values for output: the mean of the element's points, the highest plastic state.
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

}  // namespace

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
    std::vector<Diagnostic> diagnostics;
    bc_ = locate_boundary_conditions(model_, mesh_, topology_, diagnostics);
    if (has_errors(diagnostics)) {
        std::string text;
        for (const Diagnostic& d : diagnostics)
            if (d.severity == Diagnostic::Severity::Error)  // the caller says "error: " once
                text += (text.empty() ? "" : "; ") + (d.path.empty() ? d.message : d.path + ": " + d.message);
        throw std::runtime_error(text);
    }
    double stiffest = 0.0;
    for (const Material& m : model_.materials) {
        may_yield_ = may_yield_ || (model_.analysis.plasticity && m.plastic);
        stiffest = std::max(stiffest, m.young_modulus);
    }
    elements_ = ElementAssembly(model_, mesh_);
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
    initial_stresses(model_, mesh_, elements_, state_.points);
    element_averages(state_.points, elements_.points_per_element(), state_);

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
    if (base_model_.stages.empty()) {
        stages_.push_back({model_.name.empty() ? std::string("analysis") : model_.name, model_.analysis.steps});
        stages_.front().started = true;
        for (std::size_t i = 0; i < bolts; ++i) state_.bolt_force[i] = model_.bolts[i].pretension;
    } else {
        for (const Stage& st : base_model_.stages) stages_.push_back({st.name, st.analysis.steps});
        begin_stage(0);
    }
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
    // Bolts come after the contacts (group elements + contacts + i).
    for (const BoltLink& b : bolts)
        contact_groups.push_back(
            coupling({b.nodes[0], b.nodes[1], b.nodes[2], b.nodes[3], b.nodes[4], b.nodes[5]}));
    // Contacts come and go and move between neighbouring edges; as long as the pattern already
    // holds their couplings only the slots change and CHOLMOD's symbolic analysis is kept.
    if (!pattern_stale_ && system_.group_count() >= elements && system_.equations() == bc_.equation_count &&
        system_.pattern_contains(contact_groups)) {
        system_.set_groups(contact_groups, elements);
        return;
    }
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

namespace {

/// Contact forces f − K·d of the closed contacts at increments d, added to `force`.
void add_contact_forces(const std::vector<Contact>& contacts, const std::vector<ContactKinematics>& kinematics,
                        const std::vector<ContactProperties>& properties, const Eigen::VectorXd& d,
                        Eigen::VectorXd& force) {
    Matrix6 kc;
    Vector6 fc, local;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        if (contacts[i].state == ContactState::Open) continue;
        contact_terms(contacts[i], kinematics[i], properties[i], kc, fc);
        for (int a = 0; a < 3; ++a)
            for (int dir = 0; dir < 2; ++dir) local[2 * a + dir] = d[2 * kinematics[i].nodes[a] + dir];
        fc.noalias() -= kc * local;
        for (int a = 0; a < 3; ++a)
            for (int dir = 0; dir < 2; ++dir) force[2 * kinematics[i].nodes[a] + dir] += fc[2 * a + dir];
    }
}

/// Below this contraction of the out-of-balance force per iteration the factor in use is kept
/// (a back-substitution is much cheaper than a factorisation); above it the tangent is
/// refactorised. Measured on the Prandtl footing and Salençon tunnel (docs/plasticity.md).
constexpr double keep_factor_contraction = 0.25;
/// Equilibrium iterations without halving the out-of-balance force before a try counts as not
/// converging (see equilibrate): the fixed-point iteration with the elastic matrix, and Newton
/// (which halves it every iteration or two while converging; past the load a perfectly plastic
/// model can carry, its line search creeps along the mechanism).
constexpr int stall_window = 30;
/// A contact that keeps opening and closing in a static equilibrium step with more than this share
/// of the largest contact force in play holds a block that cannot be held (the wedge's crest
/// contact: about the largest contact force; a chattering corner contact in the jointed tunnel:
/// 0.4 % of it, not a mechanism).
constexpr double cycling_limit = 0.05;
constexpr int newton_stall_window = 10;
/// Newton iterations with the unsymmetric tangent after the elastic iteration of a non-associated
/// model stalled or reached its cap (see equilibrate).
constexpr int polish_iterations = 30;
/// Corrections Anderson acceleration mixes (see equilibrate).
constexpr int anderson_depth = 5;
/// A displacement increment this many times the per-step limit, with material yielding, is a
/// mechanism (see equilibrate).
constexpr double mechanism_displacements = 20.0;

}  // namespace

bool Simulation::equilibrate(Eigen::VectorXd& d, const Eigen::VectorXd& base, const std::vector<Contact>& contacts,
                             const std::vector<ContactKinematics>& kinematics,
                             const std::vector<ContactProperties>& properties, const std::vector<BoltLink>& bolts,
                             bool& factor_valid, Attempt& attempt) {
    const int elements = static_cast<int>(mesh_.triangles.size());
    const Eigen::Index dofs = d.size();
    const double tolerance = model_.analysis.plastic_tolerance;
    const double load_scale = base.cwiseAbs().maxCoeff();
    Eigen::VectorXd internal, residual(dofs), rhs(bc_.equation_count);
    double previous = std::numeric_limits<double>::infinity(), first_norm = 0.0, last_correction = 0.0;
    AndersonMixing anderson(anderson_depth);
    double best_norm = std::numeric_limits<double>::infinity(), best_correction = best_norm;
    int best_at = 0, best_correction_at = 0;
    bool tangent_usable = uses_newton();
    bool polishing = false;  // Newton with the unsymmetric tangent after the elastic iteration (below)
    int polish_from = 0;
    // The matrix in force is the elastic one (a tangent where nothing yields is one too); a held
    // tangent factor is not.
    bool elastic_matrix = factor_valid && !held_.tangent;
    bool first_linear = false;  // nothing yielded at the first iteration
    const bool any_closed = std::any_of(contacts.begin(), contacts.end(),
                                        [](const Contact& c) { return c.state != ContactState::Open; });
    for (int k = 0;; ++k) {
        // Refactorise when K is stale: contacts changed, or the last iteration contracted slowly.
        const bool refactor = !factor_valid;
        const ElementMatrix matrix =
            refactor ? (tangent_usable ? ElementMatrix::Tangent : ElementMatrix::Elastic) : ElementMatrix::None;
        auto t0 = Clock::now();
        if (refactor) {
            // Non-associated flow: the exact tangent is unsymmetric (LU); everything else is symmetric.
            system_.set_unsymmetric(matrix == ElementMatrix::Tangent && !elements_.symmetric_tangent());
            system_.clear_values();
        }
        const ElementAssembly::Evaluation eval = elements_.evaluate(d, state_.points, returned_, internal, matrix, &system_);
        timings_.plasticity += seconds_since(t0);
        attempt.yielding = eval.yielding;
        t0 = Clock::now();
        residual = base - internal;
        add_contact_forces(contacts, kinematics, properties, d, residual);
        for (const BoltLink& b : bolts) b.add_forces(d, residual);
        double norm = 0.0, norm2 = 0.0;
        for (Eigen::Index dof = 0; dof < dofs; ++dof)
            if (bc_.equation[dof] >= 0) {
                rhs[bc_.equation[dof]] = residual[dof];
                norm = std::max(norm, std::fabs(residual[dof]));
                norm2 += residual[dof] * residual[dof];
            }
        timings_.assembly += seconds_since(t0);
        const double scale = std::max({eval.force_scale, load_scale, 1e-30});
        // Converged: the out-of-balance force is small against the forces in play, and so is the
        // last correction against the increment (a slow iteration leaves a small force but a
        // large remaining displacement). The displacement yardstick is not below a hundredth of
        // the displacement so far: in a step that only re-equilibrates, the increment is
        // round-off and would never settle.
        const double yardstick = std::max({d.cwiseAbs().maxCoeff(), 0.01 * state_.displacement.cwiseAbs().maxCoeff(),
                                           1e-12 * topology_.model_size});
        // A linear iteration (nothing yields, the matrix is the elastic one of the current contact
        // states) has converged after one solve: its correction solved the problem exactly.
        const bool linear = eval.yielding == 0 && elastic_matrix && k == 1 && first_linear;
        if (k > 0 && norm <= tolerance * scale && (last_correction <= tolerance * yardstick || linear)) {
            attempt.residual = residual;
            return true;
        }
        if (k == 0) first_linear = eval.yielding == 0;
        if (iteration_observer_) {
            ++iterating_.iteration;
            iterating_.out_of_balance = norm / scale;
            iterating_.tolerance = tolerance;
            iterating_.yielding = eval.yielding;
            iteration_observer_(iterating_);
        }
        // Diverging: non-finite, or growing far beyond the start once the tangent has had a few
        // corrections (a contact change alone may start from a large out-of-balance force).
        if (k == 0) first_norm = norm;
        const bool diverging = !std::isfinite(norm) || (k >= 3 && norm > 1e6 * std::max(first_norm, tolerance * scale));
        // Stalled: Newton's force or correction, or the elastic iteration's force, has not halved
        // for the window's iterations. Converging iterations halve them every few iterations; at
        // a load beyond the model's capacity they creep for ever. The elastic iteration's mixed
        // corrections rise and fall as Anderson's history turns over, so a new smallest one is
        // no sign of progress there (counting it let Salençon's excavation at 53k elements run
        // two tries of 66 iterations each before its load was halved: 180 iterations in the step
        // against 116 with this rule alone, with the same result).
        if (norm < 0.5 * best_norm) {
            best_norm = norm;
            best_at = k;
        }
        if (k > 0 && last_correction < 0.5 * best_correction) {
            best_correction = last_correction;
            best_correction_at = k;
        }
        // (Once the force is within tolerance only the correction lags: the iteration is settling,
        // not stalled, and the iteration cap bounds it.)
        const bool stalled = norm > tolerance * scale &&
                             (tangent_usable ? k - std::max(best_at, best_correction_at) >= newton_stall_window
                                             : k - best_at >= stall_window);
        // A mechanism: yielding material and a displacement increment many times the largest a
        // step may take. The load increment is past what the material can carry.
        const double largest = d.cwiseAbs().maxCoeff();
        const bool mechanism = eval.yielding > 0 && largest > mechanism_displacements * displacement_limit_;
        const bool capped = polishing ? k - polish_from >= polish_iterations
                                      : k >= model_.analysis.max_plastic_iterations;
        if ((stalled || capped) && !diverging && !mechanism && !polishing && eval.yielding > 0 &&
            uses_unsymmetric_newton()) {
            // Non-associated flow: the elastic iteration has done what it can. Newton with the
            // exact (unsymmetric) tangent from here: close to equilibrium, where the active
            // yield planes no longer change, it converges quadratically, so an increment that
            // can be carried is not declared uncarried for a force just above the tolerance.
            polishing = true;
            polish_from = k;
            tangent_usable = true;
            factor_valid = false;
            anderson.reset();
            best_norm = norm;
            best_at = best_correction_at = k;
            best_correction = std::numeric_limits<double>::infinity();
            --k;
            continue;
        }
        if (diverging || stalled || mechanism || capped) {
            const std::string where = " (" + std::to_string(eval.yielding) + " integration points yielding)";
            char numbers[200];
            std::snprintf(numbers, sizeof numbers, "the out-of-balance force, %.3g of the force scale, ", norm / scale);
            if (diverging) attempt.why = "the equilibrium iterations diverged: " + std::string(numbers) + "grew without bound";
            else if (mechanism)
                attempt.why = "a mechanism formed: the displacement increment reached " + std::to_string(largest) +
                              " m (limit " + std::to_string(mechanism_displacements * displacement_limit_) +
                              " m) with material yielding";
            else if (stalled) {
                std::snprintf(numbers, sizeof numbers,
                              "the out-of-balance force, %.3g of the force scale, stayed above the tolerance %.3g "
                              "and stopped decreasing (not halved in %d iterations) after %d iterations",
                              norm / scale, tolerance, tangent_usable ? newton_stall_window : stall_window, k);
                attempt.why = "the equilibrium iterations stalled: " + std::string(numbers) + where;
            } else {
                std::snprintf(numbers, sizeof numbers,
                              "after %d iterations the out-of-balance force was %.3g of the force scale, above the "
                              "tolerance %.3g",
                              k, norm / scale, tolerance);
                attempt.why = "the equilibrium iterations reached their limit: " + std::string(numbers) + where;
            }
            return false;
        }
        if (refactor) {
            t0 = Clock::now();
            Matrix6 kc;
            Vector6 fc;
            for (std::size_t i = 0; i < contacts.size(); ++i) {
                if (contacts[i].state == ContactState::Open) continue;
                contact_terms(contacts[i], kinematics[i], properties[i], kc, fc);
                system_.add(elements + static_cast<int>(i), kc.data());
            }
            for (std::size_t i = 0; i < bolts.size(); ++i) {
                const Eigen::Matrix<double, 12, 12> kb = bolts[i].matrix();
                system_.add(elements + static_cast<int>(contacts.size() + i), kb.data());
            }
            timings_.assembly += seconds_since(t0);
            // An elastic matrix may keep a held elastic factor (of the last step's geometry, or of
            // other contact states) while iterating against the new matrix costs less than a
            // factorisation (SymmetricSystem::factorize); a tangent changes too much for that.
            const bool may_reuse = matrix == ElementMatrix::Elastic && !held_.tangent;
            try {
                system_.factorize(may_reuse);
            } catch (const SingularSystem&) {
                if (matrix != ElementMatrix::Tangent) throw;
                // A tangent that is not positive definite (a mechanism forming): go on with the
                // elastic matrix.
                tangent_usable = false;
                factor_valid = false;
                --k;
                continue;
            }
            factor_valid = true;
            elastic_matrix = matrix == ElementMatrix::Elastic || eval.yielding == 0;
            held_.tangent = matrix == ElementMatrix::Tangent;
            held_.closed = closed_signature(contacts, bolts);
        }
        Eigen::VectorXd delta = solve_reduced(rhs);
        ++attempt.iterations;
        // With the elastic matrix (non-associated flow, or a tangent that is not positive
        // definite) the iteration is a fixed point d ← d + K⁻¹R(d) that contracts slowly once
        // much of the model yields: Anderson acceleration (Walker & Ni 2011) mixes the last
        // corrections; it costs a small least-squares problem per iteration. Once the force is
        // within tolerance only the displacement is settling: plain corrections then where
        // contacts are closed (mixed ones wander along directions the force hardly sees, such as
        // a loosened block); without closed contacts mixing goes on (plain corrections of a
        // non-associated plastic zone can drift for hundreds of iterations when no mass term
        // damps them, as in a small-strain static analysis: Salençon's tunnel).
        if (!tangent_usable && eval.yielding > 0 && (norm > tolerance * scale || !any_closed))
            delta = anderson.next(d, delta);
        else anderson.reset();
        // Backtracking on the out-of-balance force: a full Newton correction through a softening
        // (perfectly plastic) tangent overshoots and can spread yield over the whole model.
        double step = 1.0;
        // Not with the elastic matrix (the initial-stress iteration): its full steps converge
        // while the largest nodal force may rise on the way.
        if (tangent_usable && (eval.yielding > 0 || matrix == ElementMatrix::Tangent)) {
            for (int cut = 0; cut < 6; ++cut) {
                const Eigen::VectorXd trial = d + step * delta;
                t0 = Clock::now();
                elements_.evaluate(trial, state_.points, returned_, internal, ElementMatrix::None, nullptr);
                timings_.plasticity += seconds_since(t0);
                Eigen::VectorXd r = base - internal;
                add_contact_forces(contacts, kinematics, properties, trial, r);
                for (const BoltLink& b : bolts) b.add_forces(trial, r);
                double trial_norm = 0.0, trial_norm2 = 0.0;
                for (Eigen::Index dof = 0; dof < dofs; ++dof)
                    if (bc_.equation[dof] >= 0) {
                        trial_norm = std::max(trial_norm, std::fabs(r[dof]));
                        trial_norm2 += r[dof] * r[dof];
                    }
                if (trial_norm <= tolerance * scale) break;
                if (polishing ? trial_norm2 <= norm2 : trial_norm <= norm) break;
                step *= 0.5;
            }
        }
        d += step * delta;
        last_correction = step * delta.cwiseAbs().maxCoeff();
        // The factor is kept while it contracts the out-of-balance force well enough.
        if (k > 0 && tangent_usable && norm > keep_factor_contraction * previous) factor_valid = false;
        previous = norm;
    }
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

Simulation::Attempt Simulation::solve_increments(const Eigen::VectorXd& external, const Eigen::VectorXd* start_external,
                                                 double lambda, double dt, std::vector<Contact>& contacts,
                                                 const Eigen::VectorXd& prescribed) {
    Attempt attempt;
    const auto start_assembly = Clock::now();
    bolt_broken_try_.assign(base_model_.bolts.size(), 0);
    attempt.bolts = bolt_links();
    std::vector<BoltLink>& bolts = attempt.bolts;
    rebuild_pattern_if_needed(contacts, bolts);
    const Eigen::Index dofs = state_.displacement.size();
    const double beta = newmark_for(state_.step).beta;
    // Shi's static DDA keeps the mass term M/(βΔt²) (velocities reset every step): it holds
    // blocks that only contacts restrain while they settle. A small-strain static analysis is a
    // pure equilibrium problem: no load may be carried by inertia there.
    const bool equilibrium_only = is_equilibrium_only();
    elements_.prepare(element_nodes(), equilibrium_only ? 0.0 : 1.0 / (beta * dt * dt));
    Eigen::VectorXd base = external;
    if (model_.analysis.kind == AnalysisSettings::Kind::Dynamic)
        elements_.add_inertia_load(state_.velocity, state_.acceleration, beta, dt, base);
    timings_.assembly += seconds_since(start_assembly);

    const auto start_contact = Clock::now();
    std::vector<ContactKinematics> kinematics;
    std::vector<ContactProperties> properties;
    kinematics.reserve(contacts.size());
    properties.reserve(contacts.size());
    for (const Contact& c : contacts) {
        kinematics.push_back(kinematics_of(c));
        properties.push_back(contact_properties(c, kinematics.back(), model_, topology_, penalty_));
    }
    timings_.contact += seconds_since(start_contact);

    // Supports that move (displacement control) take their increments from the start; the
    // corrections never change them (they are not equations).
    Eigen::VectorXd d = prescribed;
    Eigen::VectorXd shift = Eigen::VectorXd::Zero(dofs);  // the part of the start's unbalance left for later
    if (start_external && lambda < 1.0) {
        // Only the share λ of the out-of-balance force at the start of the increment is applied
        // (an excavation's release, the rest of an unconverged step): the remainder stays as a
        // load that the next increment removes.
        Eigen::VectorXd internal;
        const auto t0 = Clock::now();
        elements_.evaluate(Eigen::VectorXd::Zero(dofs), state_.points, returned_, internal, ElementMatrix::None, nullptr);
        timings_.plasticity += seconds_since(t0);
        Eigen::VectorXd unbalance = *start_external - internal;
        add_contact_forces(contacts, kinematics, properties, Eigen::VectorXd::Zero(dofs), unbalance);
        shift = -(1.0 - lambda) * unbalance;
        base += shift;
    }

    const int max_iterations = model_.analysis.max_open_close_iterations;
    constexpr int max_friction_rounds = 10;
    // The factor of the last converged increment, when nothing it depends on has changed: the
    // element matrices of a small-strain static analysis stay on the undeformed shape with no
    // mass term, so only the closed contacts and (for Newton) the tangent differ. The elastic
    // iteration needs the exact elastic matrix; Newton takes the last tangent as its first
    // matrix and refactorises when it contracts slowly (equilibrate).
    // A held elastic matrix depends on nothing a try changes, so it also survives a try that
    // failed (the smaller load increment after it starts with it); a tangent only after a
    // converged try.
    bool factor_valid = equilibrium_only && system_.has_factor() && held_.closed == closed_signature(contacts, bolts) &&
                        (held_.tangent ? held_.usable && uses_newton() : true);
    held_.usable = false;  // until this try converges
    int friction_rounds = 0;
    std::vector<int> flips(contacts.size(), 0);
    int& iterations = attempt.open_close_iterations;
    iterations = 1;
    while (iterations <= max_iterations) {
        try {
            if (!equilibrate(d, base, contacts, kinematics, properties, bolts, factor_valid, attempt)) {
                attempt.outcome = Outcome::NotConverged;
                attempt.d = d;
                return attempt;
            }
        } catch (const SingularSystem& e) {
            attempt.outcome = Outcome::Singular;
            attempt.why = e.what();
            // Without a mass term, a block held only by sliding contacts is a mechanism: the load
            // is not carried (a smaller Δt would change nothing).
            const auto sliding = std::count_if(contacts.begin(), contacts.end(), [](const Contact& c) {
                return c.state == ContactState::Sliding;
            });
            if (equilibrium_only && sliding > 0) {
                attempt.outcome = Outcome::NotConverged;
                attempt.why = "blocks slide freely: friction and cohesion of the " + std::to_string(sliding) +
                              " sliding contacts cannot hold them (the stiffness matrix is singular)";
            }
            return attempt;
        }
        attempt.d = d;
        attempt.residual -= shift;  // reactions balance the loads actually applied

        // A bolt pulled beyond its strength breaks, and the try goes on without it.
        bool broke = false;
        for (const BoltLink& b : bolts) {
            const double strength = base_model_.bolts[b.bolt].strength;
            if (strength > 0.0 && b.force_after(d) > strength) {
                bolt_broken_try_[b.bolt] = 1;
                broke = true;
            }
        }
        if (broke) {
            bolts = bolt_links();
            rebuild_pattern_if_needed(contacts, bolts);
            factor_valid = false;
            ++iterations;
            continue;
        }

        const auto t3 = Clock::now();
        int changes = 0;
        double friction_used = 0.0, friction_change = 0.0;
        double cycling_force = 0.0;  // the largest change of a cycling contact that was let pass
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
            double change_force = 0.0;
            StateChange change =
                update_contact_state(contacts[i], kinematics[i], properties[i], local, force_tolerance, &change_force);
            // A contact that already changed twice in this step is cycling (stick–slip or
            // open–close at its limit): it no longer holds the iteration open; its last change
            // is kept only if the step ends without other changes. In a static equilibrium
            // analysis a contact cycling between sticking and sliding rests at its strength
            // (sliding, the friction force at its limit): that state is statically admissible,
            // while one held locked would carry more shear than friction can (a wedge that must
            // slide would stand on such contacts).
            if (change == StateChange::Significant && ++flips[i] > 2) {
                const bool stick_slip = before.state != ContactState::Open && contacts[i].state != ContactState::Open;
                if (equilibrium_only && stick_slip && contacts[i].state == ContactState::Locked) {
                    contacts[i].state = ContactState::Sliding;
                    contacts[i].slip = before.slip;
                    contacts[i].shear_spring = before.shear_spring;
                    change = StateChange::None;
                } else if (!(equilibrium_only && stick_slip)) {
                    change = StateChange::Marginal;
                    cycling_force = std::max(cycling_force, change_force);
                }
            }
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
            if (iterations == max_iterations && changes <= std::max(2, static_cast<int>(contacts.size() / 500)))
                return attempt;  // the factor is of states that changed: not held
            factor_valid = false;
            ++iterations;
            continue;
        }
        // Friction of sliding contacts was taken from the normal forces of the previous solve;
        // repeat until they agree (with the same factor).
        if (friction_change <= 1e-3 * friction_used || ++friction_rounds > max_friction_rounds) {
            // With no mass term nothing but the contacts' states can hold a block: a contact let
            // pass while it keeps opening and closing with a large force in play (one that opens
            // while it holds a block) means no consistent set of states balances the load here.
            if (equilibrium_only && cycling_force > cycling_limit * largest_force) {
                attempt.outcome = Outcome::NotConverged;
                std::ostringstream why;
                why << "no equilibrium of the contacts: contacts keep opening and closing with up to "
                    << cycling_force / 1e3 << " kN/m in play against a limit of " << cycling_limit * largest_force / 1e3
                    << " kN/m (blocks move apart: friction and cohesion cannot hold them)";
                attempt.why = why.str();
                return attempt;
            }
            held_.usable = true;
            return attempt;
        }
        undo_marginal();
    }
    attempt.outcome = Outcome::Unsettled;
    attempt.why = "contacts do not settle";
    return attempt;
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

Eigen::VectorXd Simulation::solve_reduced(const Eigen::VectorXd& rhs) {
    const auto start = Clock::now();
    const double factorizing = system_.factorization_seconds();
    const Eigen::VectorXd solution = system_.solve(rhs);
    Eigen::VectorXd d(state_.displacement.size());
    for (Eigen::Index dof = 0; dof < d.size(); ++dof)
        d[dof] = bc_.equation[dof] >= 0 ? solution[bc_.equation[dof]] : 0.0;
    // (less a factorisation the solve fell back to: it counts as one)
    timings_.solve += seconds_since(start) - (system_.factorization_seconds() - factorizing);
    return d;
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
        commit_contact(c, k, local);
    }
    for (std::size_t i = 0; i < state_.nodes.size(); ++i) {
        state_.nodes[i].x += d[2 * i];
        state_.nodes[i].y += d[2 * i + 1];
    }
    state_.displacement += d;
    if (model_.analysis.kind == AnalysisSettings::Kind::Dynamic) {
        // Newmark: a1 from the increment, then v1; Shi's scheme is the case β = ½, γ = 1.
        const auto [beta, gamma] = newmark_for(state_.step);
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

void Simulation::finish_report(StepReport& report, double largest, const Eigen::VectorXd& residual) {
    // The out-of-balance force of the state reached. A small-strain static step's converged
    // residual is that force already (no mass term, loads and elements on the undeformed
    // shape); otherwise the state is evaluated once more without the inertia that balanced it.
    double scale = 0.0;
    Eigen::VectorXd r;
    if (is_equilibrium_only() && residual.size() == state_.displacement.size()) {
        r = residual;
        scale = applied_forces(state_.step, state_.time).cwiseAbs().maxCoeff();
        if (scale == 0.0) scale = std::max(1e-30, residual.cwiseAbs().maxCoeff());
    } else {
        r = out_of_balance(scale);
    }
    double largest_free = 0.0;
    for (Eigen::Index dof = 0; dof < r.size(); ++dof)
        if (bc_.equation[dof] >= 0) largest_free = std::max(largest_free, std::fabs(r[dof]));
    state_.unbalanced_ratio = scale > 0.0 ? largest_free / scale : 0.0;
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

namespace {

double largest_increment(const Eigen::VectorXd& d) {
    double largest = 0.0;
    for (Eigen::Index i = 0; i + 1 < d.size(); i += 2) largest = std::max(largest, std::hypot(d[i], d[i + 1]));
    return largest;
}

std::string describe_position(double position) {
    const int step = static_cast<int>(std::floor(position + 1e-12));
    const double fraction = position - step;
    if (fraction < 1e-9) return "step " + std::to_string(step);
    return "step " + std::to_string(step + 1) + " at " + std::to_string(static_cast<int>(std::round(100 * fraction))) +
           " % of its load increment";
}

}  // namespace

void Simulation::record_solver_counts() {
    timings_.factorization = system_.factorization_seconds();
    timings_.factorizations = system_.factorizations();
    timings_.symbolic_analyses = system_.symbolic_analyses();
    timings_.reused_factors = system_.reused_factors();
    timings_.refinement_iterations = system_.refinement_iterations();
}

namespace {

/// Names of the supports, loads and bolts a stage installs or removes, present at stage `s`:
/// an item some stage installs is absent before it.
bool item_present(const Model& model, const std::string& name, int s) {
    bool present = true;
    for (const Stage& st : model.stages)
        if (std::find(st.install.begin(), st.install.end(), name) != st.install.end()) present = false;
    for (int t = 0; t <= s; ++t) {
        const Stage& st = model.stages[t];
        if (std::find(st.install.begin(), st.install.end(), name) != st.install.end()) present = true;
        if (std::find(st.remove.begin(), st.remove.end(), name) != st.remove.end()) present = false;
    }
    return present;
}

}  // namespace

void Simulation::begin_stage(int s) {
    const Stage& stage = base_model_.stages[s];
    stage_ = s;
    stage_start_step_ = state_.step;
    state_.stage = s;
    StageRecord& record = stages_[s];
    record.started = true;
    record.first_step = record.last_step = state_.step;
    if (s > 0) pending_events_.push_back("stage " + std::to_string(s + 1) + " \"" + stage.name + "\" begins at step " +
                                         std::to_string(state_.step));

    // Regions present and their materials: those some stage activates are absent before it.
    const std::size_t regions = base_model_.regions.size();
    std::vector<char> region_present(regions, 1);
    std::vector<int> material(regions);
    for (std::size_t r = 0; r < regions; ++r) material[r] = base_model_.regions[r].material;
    for (const Stage& st : base_model_.stages)
        for (int r : st.activate) region_present[r] = 0;
    for (int t = 0; t <= s; ++t) {
        const Stage& st = base_model_.stages[t];
        for (int r : st.excavate) region_present[r] = 0;
        for (int r : st.activate) region_present[r] = 1;
        for (const auto& [r, m] : st.materials) material[r] = m;
    }

    // The stage's view of the model: its settings and materials; absent supports and loads
    // cleared in place, so that indices (history columns, reactions) stay those of the file.
    model_ = base_model_;
    model_.analysis = stage.analysis;
    if (stage.analysis.strength_reduction) {
        // A safety stage: reduced strengths, solved as a small-strain equilibrium problem.
        reduce_strength(model_, strength_factor_);
        model_.analysis.geometry = AnalysisSettings::Geometry::Initial;
    }
    if (stage.reset_displacements || stage.analysis.strength_reduction) state_.displacement_reference = state_.displacement;
    for (std::size_t r = 0; r < regions; ++r) model_.regions[r].material = material[r];
    model_.fixed_points.clear();
    for (const FixedPoint& f : base_model_.fixed_points)
        if (item_present(base_model_, f.name, s)) model_.fixed_points.push_back(f);
    for (Roller& r : model_.rollers)
        if (!item_present(base_model_, r.name, s)) r.fix_x = r.fix_y = false;
    for (PointLoad& l : model_.point_loads)
        if (!item_present(base_model_, l.name, s)) l.force = {0.0, 0.0};
    for (EdgePressure& l : model_.edge_pressures)
        if (!item_present(base_model_, l.name, s)) l.pressure = 0.0;

    const int blocks = mesh_.block_count();
    std::vector<char> was_active = element_active_;
    block_active_.assign(blocks, 1);
    for (int b = 0; b < blocks; ++b) block_active_[b] = region_present[block_region_[b]];
    const std::size_t elements = mesh_.triangles.size();
    element_active_.assign(elements, 1);
    const int per_element = elements_.points_per_element();
    for (std::size_t e = 0; e < elements; ++e) {
        mesh_.triangle_material[e] = material[block_region_[mesh_.triangle_block[e]]];
        element_active_[e] = block_active_[mesh_.triangle_block[e]];
        // Material built in this stage (backfill, a liner) starts free of stress.
        if (element_active_[e] && !was_active.empty() && !was_active[e])
            for (int q = 0; q < per_element; ++q) {
                const std::size_t p = e * per_element + q;
                state_.points.stress[p].setZero();
                state_.points.stress_zz[p] = 0.0;
                state_.points.plastic_strain[p] = 0.0;
                state_.points.plastic_state[p] = 0;
            }
    }
    element_averages(state_.points, per_element, state_);
    elements_ = ElementAssembly(model_, mesh_);
    elements_.set_active(element_active_);
    may_yield_ = false;
    double stiffest = 0.0;
    for (std::size_t r = 0; r < regions; ++r) {
        if (!region_present[r]) continue;
        const Material& m = model_.materials[material[r]];
        may_yield_ = may_yield_ || (model_.analysis.plasticity && m.plastic);
        stiffest = std::max(stiffest, m.young_modulus);
    }
    penalty_ = model_.analysis.penalty > 0.0 ? model_.analysis.penalty : 4.0 * stiffest;
    displacement_limit_ = model_.analysis.max_displacement_ratio * topology_.model_size;
    contact_tolerance_ = 1e-6 * displacement_limit_;
    state_.time_step = model_.analysis.time_step;

    // Supports on the stage's blocks; the nodes of absent blocks are held where they are.
    std::vector<Diagnostic> diagnostics;
    bc_ = locate_boundary_conditions(model_, mesh_, topology_, diagnostics);
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Diagnostic::Severity::Error)
            throw std::runtime_error("stage \"" + stage.name + "\": " + (d.path.empty() ? "" : d.path + ": ") + d.message);
    const std::size_t n = mesh_.nodes.size();
    auto node_active = [&](int node) { return block_active_[mesh_.node_block[node]] != 0; };
    bc_.equation_count = 0;
    for (std::size_t dof = 0; dof < 2 * n; ++dof) {
        const bool free = bc_.equation[dof] >= 0 && node_active(static_cast<int>(dof / 2));
        bc_.equation[dof] = free ? bc_.equation_count++ : -1;
    }
    for (auto& nodes : bc_.roller_nodes)
        nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [&](int node) { return !node_active(node); }), nodes.end());
    bc_.pressure_edges.erase(std::remove_if(bc_.pressure_edges.begin(), bc_.pressure_edges.end(),
                                            [&](const BoundaryConditions::PressureEdge& p) {
                                                return !block_active_[topology_.edges[p.edge].block];
                                            }),
                             bc_.pressure_edges.end());
    // A measurement point on removed material follows the nearest node still present.
    for (std::size_t i = 0; i < bc_.measurement_nodes.size(); ++i) {
        int& node = bc_.measurement_nodes[i];
        if (node < 0 || node_active(node)) continue;
        const Point2 p = model_.measurement_points[i].point;
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < n; ++k)
            if (node_active(static_cast<int>(k))) {
                const double dist = std::hypot(mesh_.nodes[k].x - p.x, mesh_.nodes[k].y - p.y);
                if (dist < best) {
                    best = dist;
                    node = static_cast<int>(k);
                }
            }
    }
    state_.roller_reactions.assign(model_.rollers.size(), Point2{0.0, 0.0});
    drop_absent(state_.contacts);

    // Bolts: installed ones start with their pretension, removed ones carry nothing.
    for (std::size_t i = 0; i < base_model_.bolts.size(); ++i) {
        const bool present = item_present(base_model_, base_model_.bolts[i].name, s);
        if (present && !bolt_present_[i]) state_.bolt_force[i] = base_model_.bolts[i].pretension;
        if (!present) state_.bolt_force[i] = 0.0;
        bolt_present_[i] = present;
    }
    if (s == 0)
        for (std::size_t i = 0; i < base_model_.bolts.size(); ++i)
            if (bolt_present_[i]) state_.bolt_force[i] = base_model_.bolts[i].pretension;

    // The new numbering needs a new pattern and factor.
    pattern_stale_ = true;
    held_ = HeldFactor{};
    // What the stage's changes leave out of balance is held, then released over its steps.
    holding_.resize(0);
    double scale = 0.0;
    holding_ = -out_of_balance(scale);
}

void Simulation::drop_absent(std::vector<Contact>& contacts) const {
    if (block_active_.empty()) return;
    contacts.erase(std::remove_if(contacts.begin(), contacts.end(),
                                  [&](const Contact& c) {
                                      return !block_active_[mesh_.node_block[c.node]] || !block_active_[c.edge_block];
                                  }),
                   contacts.end());
}

Eigen::VectorXd Simulation::applied_forces(double position, double time) const {
    Eigen::VectorXd f = external_forces(model_, mesh_, element_nodes(), topology_, bc_, position, time, element_active_);
    if (holding_.size() == f.size()) {
        const double released = base_model_.stages[stage_].released(position - stage_start_step_, base_model_.load_tables);
        if (released < 1.0) f += (1.0 - released) * holding_;
    }
    return f;
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

Eigen::VectorXd Simulation::out_of_balance(double& applied_scale) {
    const Eigen::Index dofs = state_.displacement.size();
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dofs);
    const Eigen::VectorXd applied = applied_forces(state_.step + state_.step_fraction, state_.time);
    elements_.prepare(element_nodes(), 0.0);  // the next try prepares its own
    std::vector<ReturnResult> returned;
    Eigen::VectorXd internal;
    const auto t0 = Clock::now();
    elements_.evaluate(zero, state_.points, returned, internal, ElementMatrix::None, nullptr);
    timings_.plasticity += seconds_since(t0);
    Eigen::VectorXd r = applied - internal;
    std::vector<ContactKinematics> kinematics;
    std::vector<ContactProperties> properties;
    for (const Contact& c : state_.contacts) {
        kinematics.push_back(kinematics_of(c));
        properties.push_back(contact_properties(c, kinematics.back(), model_, topology_, penalty_));
    }
    add_contact_forces(state_.contacts, kinematics, properties, zero, r);
    for (const BoltLink& b : bolt_links()) b.add_forces(zero, r);
    applied_scale = applied.cwiseAbs().maxCoeff();
    if (applied_scale == 0.0) applied_scale = internal.cwiseAbs().maxCoeff();
    return r;
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
    try {
        if (stage_complete()) begin_stage(stage_ + 1);
        report = model_.analysis.kind == AnalysisSettings::Kind::Static ? advance_static() : advance_dynamic();
    } catch (const PlasticCollapse& e) {
        collapse_ = CollapseBracket{e.carried, e.not_carried};
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

StepReport Simulation::advance_static() {
    StepReport report;
    report.load_increments = 0;
    const double largest_step = model_.analysis.time_step;
    const double floor = model_.analysis.min_load_fraction;
    double increment = 1.0 - state_.step_fraction;  // of the step's load, this try
    int cuts = 0;
    // The end of the last try that failed (a load position), while no increment since has been
    // sized against it; negative: none.
    double failed_end = -1.0;
    while (true) {
        const double dt = state_.time_step;
        const double from = state_.step + state_.step_fraction;
        const double remaining = 1.0 - state_.step_fraction;
        increment = std::min(increment, remaining);
        const double to = from + increment;
        iterating_.load_fraction = to - state_.step;
        const auto t0 = Clock::now();
        std::vector<Contact> contacts = detect_contacts(element_nodes(), mesh_, topology_, 2.5 * displacement_limit_,
                                                        state_.contacts, Eigen::VectorXd(), contact_tolerance_);
        drop_absent(contacts);
        timings_.contact += seconds_since(t0);
        // Loads at the increment's end; the time follows the load position (Δt per whole step).
        const Eigen::VectorXd external = applied_forces(to, state_.time + increment * largest_step);
        // The loads at the increment's start matter only when it is a part of what remains.
        const double lambda = increment / remaining;
        Eigen::VectorXd start_external;
        if (lambda < 1.0)
            start_external = applied_forces(from, state_.time);
        Attempt attempt = solve_increments(external, lambda < 1.0 ? &start_external : nullptr, lambda, dt, contacts,
                                           prescribed_increments(to, state_.time + increment * largest_step));
        report.plastic_iterations += attempt.iterations;
        const double largest = attempt.outcome == Outcome::Converged ? largest_increment(attempt.d) : 0.0;
        const bool too_large = attempt.outcome == Outcome::Converged && largest > displacement_limit_;
        // A matrix that is singular while the material yields is a mechanism forming: a load
        // question too (a block without supports and yielding nothing gets a smaller Δt below).
        const bool plastic_failure = attempt.outcome == Outcome::NotConverged ||
                                     (attempt.outcome == Outcome::Singular && attempt.yielding > 0) ||
                                     (too_large && attempt.yielding > 0);
        if (plastic_failure && !(too_large && increment <= floor)) {
            // Smaller load increments, never a smaller Δt: inertia must not carry the load.
            if (increment > floor * (1.0 + 1e-9)) {
                failed_end = to;
                increment = std::max(floor, 0.5 * increment);
                ++timings_.load_cuts;
                continue;
            }
            // The iterations spent count, whether or not the step was carried.
            timings_.iterations += report.plastic_iterations;
            timings_.max_iterations = std::max(timings_.max_iterations, report.plastic_iterations);
            throw PlasticCollapse("the load could not be carried beyond " + describe_position(from) + " (" +
                                      attempt.why + " for a load increment of " + std::to_string(increment) +
                                      " of a step)",
                                  from, to);
        }
        // Small-strain static: there is no mass term, so a smaller Δt changes nothing; an increment
        // beyond the displacement limit (which guards contact detection) takes a smaller share
        // of the load instead, and is accepted at the floor.
        const bool equilibrium_only = is_equilibrium_only();
        if (too_large && attempt.yielding == 0 && equilibrium_only && increment > floor * (1.0 + 1e-9)) {
            increment = std::max(floor, std::min(0.5, 0.9 * displacement_limit_ / largest) * increment);
            ++timings_.load_cuts;
            continue;
        }
        if ((attempt.outcome == Outcome::Singular && attempt.yielding == 0) || attempt.outcome == Outcome::Unsettled ||
            (too_large && attempt.yielding == 0 && !equilibrium_only)) {
            // Contacts that do not settle, a block held by nothing but inertia, or a step too
            // large for the contact linearisation: a smaller Δt (Shi's static DDA). Plasticity
            // is not involved here.
            last_singular_ = attempt.outcome == Outcome::Singular ? attempt.why : std::string();
            const double factor = too_large ? std::clamp(0.9 * std::sqrt(displacement_limit_ / largest), 0.1, 0.5) : 0.5;
            state_.time_step = dt * factor;
            report.time_step_cuts++;
            if (++cuts > max_time_step_cuts || state_.time_step < 1e-9 * largest_step)
                throw std::runtime_error("the time step fell below its floor at step " + std::to_string(state_.step + 1) +
                                         (last_singular_.empty() ? " (contacts do not settle)" : ": " + last_singular_));
            continue;
        }
        commit(attempt.d, dt, contacts, attempt.bolts);
        record_reactions(attempt.residual);
        ++report.load_increments;
        report.open_close_iterations += attempt.open_close_iterations;
        report.max_increment = std::max(report.max_increment, largest);
        state_.time += increment * largest_step;
        state_.step_fraction += increment;
        if (largest < 0.5 * displacement_limit_ && attempt.open_close_iterations <= 2)
            state_.time_step = std::min(largest_step, dt * 1.25);
        if (state_.step_fraction >= 1.0 - 1e-9) {
            state_.step += 1;
            state_.step_fraction = 0.0;
            report.time_step = dt;
            finish_report(report, largest, attempt.residual);
            return report;
        }
        increment = std::min(2.0 * increment, 1.0 - state_.step_fraction);  // grow back after a cut
        // The load where a try failed is approached in two halves, not reached again at once from
        // the first success short of it (Salençon's excavation, elastic over its first half,
        // failed its second half just as it failed the whole).
        const double position = state_.step_fraction;
        const double failed_at = failed_end - state_.step;  // within this step
        if (failed_end >= 0.0 && position + increment >= failed_at - 1e-9 && failed_at > position) {
            increment = std::max(floor, 0.5 * (failed_at - position));
            failed_end = -1.0;
        }
    }
}

StepReport Simulation::advance_dynamic() {
    StepReport report;
    const double largest_step = model_.analysis.time_step;
    for (int cut = 0; cut <= max_time_step_cuts; ++cut) {
        const double dt = state_.time_step;
        const auto t0 = Clock::now();
        std::vector<Contact> contacts = detect_contacts(element_nodes(), mesh_, topology_, 2.5 * displacement_limit_,
                                                        state_.contacts, state_.velocity * dt, contact_tolerance_);
        drop_absent(contacts);
        timings_.contact += seconds_since(t0);
        const Eigen::VectorXd external = applied_forces(state_.step + 1, state_.time + dt);
        Attempt attempt =
            solve_increments(external, nullptr, 1.0, dt, contacts, prescribed_increments(state_.step + 1, state_.time + dt));
        report.plastic_iterations += attempt.iterations;
        if (attempt.outcome == Outcome::NotConverged) {
            // Between blocks, rock asked to carry too much is often a wrong contact guess at this
            // Δt (a joint that should open or slide); a smaller Δt lets the contacts sort
            // themselves out. Without contacts, or once Δt is tiny, it is a collapse.
            const bool any_contact = std::any_of(contacts.begin(), contacts.end(),
                                                 [](const Contact& c) { return c.state != ContactState::Open; });
            if (!any_contact || dt < plastic_collapse_time_step * largest_step)
                throw PlasticCollapse("the load could not be carried at step " + std::to_string(state_.step + 1) +
                                          " (" + attempt.why + ")",
                                      state_.step, state_.step + 1);
        }
        if (attempt.outcome == Outcome::Singular) last_singular_ = attempt.why;
        const double largest = attempt.outcome == Outcome::Converged ? largest_increment(attempt.d) : 0.0;
        if (attempt.outcome != Outcome::Converged || largest > displacement_limit_) {
            // Too large a step, or contacts that do not settle: a smaller Δt (Shi).
            const double factor = attempt.outcome == Outcome::Singular ? 0.1
                                  : attempt.outcome == Outcome::Converged
                                      ? std::clamp(0.9 * std::sqrt(displacement_limit_ / largest), 0.1, 0.5)
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
        commit(attempt.d, dt, contacts, attempt.bolts);
        record_reactions(attempt.residual);
        state_.step += 1;
        state_.time += dt;
        report.time_step = dt;
        report.open_close_iterations = attempt.open_close_iterations;
        finish_report(report, largest, attempt.residual);
        // Grow Δt back towards its set value while steps are comfortably small.
        if (largest < 0.5 * displacement_limit_ && attempt.open_close_iterations <= 2)
            state_.time_step = std::min(largest_step, dt * 1.25);
        return report;
    }
    throw std::runtime_error("step " + std::to_string(state_.step + 1) + " could not be completed after " +
                             std::to_string(max_time_step_cuts) + " cuts of the time step");
}

}  // namespace mcdda

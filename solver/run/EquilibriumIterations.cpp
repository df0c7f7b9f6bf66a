// The equilibrium iterations of one load increment for fixed contact states (Simulation.hpp's
// file comment): assemble the out-of-balance force → converged? → factorise → correct → line
// search, each a short function below.

#include "run/ConvergenceMonitor.hpp"
#include "run/Simulation.hpp"
#include "run/Stopwatch.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace mcdda {

namespace {

/// Below this contraction of the out-of-balance force per iteration the factor in use is kept
/// (a back-substitution is much cheaper than a factorisation); above it the tangent is
/// refactorised. Measured on the Prandtl footing and Salençon tunnel (docs/plasticity.md).
constexpr double keep_factor_contraction = 0.25;
/// Corrections Anderson acceleration mixes (see correction).
constexpr int anderson_depth = 5;
/// A displacement increment this many times the per-step limit, with material yielding, is a
/// mechanism (ConvergenceMonitor).
constexpr double mechanism_displacements = 20.0;
/// A Newton correction solved iteratively (a held tangent factor preconditioning conjugate
/// gradients) stops at this residual, relative to the out-of-balance force: inexact Newton
/// (Dembo, Eisenstat & Steihaug, SIAM J. Numer. Anal. 19, 1982). Near the solution the force then
/// falls about a hundredfold per iteration instead of quadratically, which a force tolerance of
/// 1e-4 hardly notices. The flexible footing's collapse load is the same at 1e-1, 1e-2 and exact
/// solves (docs/benchmarks.md).
constexpr double newton_solve_tolerance = 1e-2;
/// The elastic matrix's share in a tangent that was not positive definite (stiffen_tangent):
/// the first share, raised tenfold after each failure up to the last.
constexpr double first_elastic_share = 1e-3;
constexpr double max_elastic_share = 0.1;
/// Halvings of a Newton correction the line search may try.
constexpr int line_search_cuts = 6;
/// The energy line search stops where the slope of the energy along the correction is within
/// this share of its slope at the start (0.25–0.5 measured alike on the homogeneous slope; 0.8,
/// the customary looser value, took 10 trials against 6 to find its factor of safety), or after
/// this many shares.
constexpr double energy_line_search_slack = 0.5;
constexpr int energy_line_search_shares = 8;

}  // namespace

Eigen::VectorXd Simulation::residual(const Eigen::VectorXd& d, const Eigen::VectorXd& loads, const ContactSet& contacts,
                                     const std::vector<BoltLink>& bolts, std::vector<ReturnResult>& returned,
                                     ElementMatrix matrix, ElementAssembly::Evaluation* evaluation,
                                     Eigen::VectorXd* internal_forces) {
    Eigen::VectorXd internal;
    auto t0 = Clock::now();
    const ElementAssembly::Evaluation eval =
        elements_.evaluate(d, state_.points, returned, internal, matrix, matrix == ElementMatrix::None ? nullptr : &system_);
    timings_.plasticity += seconds_since(t0);
    if (evaluation) *evaluation = eval;
    t0 = Clock::now();
    Eigen::VectorXd r = loads - internal;
    contacts.add_forces(d, r);
    for (const BoltLink& b : bolts) b.add_forces(d, r);
    if (viscous_try_) dashpots_.add_forces(d, velocity_rate_, velocity_rest_, incident_, r);
    if (internal_forces) *internal_forces = std::move(internal);
    timings_.assembly += seconds_since(t0);
    return r;
}

Simulation::Balance Simulation::balance_at(const Eigen::VectorXd& d, const Eigen::VectorXd& loads,
                                           const ContactSet& contacts, const std::vector<BoltLink>& bolts,
                                           ElementMatrix matrix) {
    if (matrix != ElementMatrix::None) {
        // Non-associated flow: the exact tangent is unsymmetric (LU); everything else is symmetric.
        system_.set_unsymmetric(matrix == ElementMatrix::Tangent && !elements_.symmetric_tangent());
        system_.clear_values();
    }
    ElementAssembly::Evaluation evaluation;
    Eigen::VectorXd r = residual(d, loads, contacts, bolts, returned_, matrix, &evaluation);
    return balance_of(std::move(r), evaluation);
}

Simulation::Balance Simulation::balance_of(Eigen::VectorXd residual, const ElementAssembly::Evaluation& evaluation) {
    const auto t0 = Clock::now();
    Balance b;
    b.residual = std::move(residual);
    b.evaluation = evaluation;
    b.rhs.resize(bc_.equation_count);
    for (Eigen::Index dof = 0; dof < b.residual.size(); ++dof)
        if (bc_.equation[dof] >= 0) b.rhs[bc_.equation[dof]] = b.residual[dof];
    static_cast<ResidualNorms&>(b) = residual_norms(b.residual);
    timings_.assembly += seconds_since(t0);
    return b;
}

Simulation::ResidualNorms Simulation::residual_norms(const Eigen::VectorXd& r) const {
    ResidualNorms n;
    for (Eigen::Index dof = 0; dof < r.size(); ++dof) {
        if (bc_.equation[dof] < 0) continue;
        const double value = measured(r, dof);
        n.norm = std::max(n.norm, std::fabs(value));
        n.norm2 += value * value;
    }
    return n;
}

double Simulation::load_scale(const Eigen::VectorXd& loads) const {
    double scale = 0.0;
    for (Eigen::Index dof = 0; dof < loads.size(); ++dof) scale = std::max(scale, std::fabs(measured(loads, dof)));
    return scale;
}

bool Simulation::factorize(ElementMatrix matrix, const ContactSet& contacts, const std::vector<BoltLink>& bolts) {
    const auto t0 = Clock::now();
    const int elements = static_cast<int>(mesh_.triangles.size());
    contacts.add_matrices(system_, elements);
    for (std::size_t i = 0; i < bolts.size(); ++i) {
        const Eigen::Matrix<double, 12, 12> kb = bolts[i].matrix();
        system_.add(elements + static_cast<int>(contacts.size() + i), kb.data());
    }
    if (viscous_try_) {
        const int first = elements + static_cast<int>(contacts.size() + bolts.size());
        for (std::size_t i = 0; i < dashpots_.dashpots().size(); ++i) {
            const Eigen::Matrix2d c = velocity_rate_ * dashpots_.dashpots()[i].c;
            system_.add(first + static_cast<int>(i), c.data());
        }
    }
    timings_.assembly += seconds_since(t0);
    // A matrix may keep a held factor of its own kind (the elastic one of the last step's
    // geometry or of other contact states; the tangent of an earlier iterate) while iterating
    // against the new matrix costs less than a factorisation (SymmetricSystem::factorize). From
    // one Newton iterate to the next of a load-controlled analysis the tangent changes mostly
    // where points start or stop yielding, and its correction is solved inexactly
    // (newton_solve_tolerance). Not in strength reduction trials, whose plastic zone forms anew
    // in each trial's few increments: there a third of the held-factor solves of the homogeneous
    // slope's search did not converge in 40 iterations and the rest took 19 on average, and the
    // search took about a quarter more CPU (docs/benchmarks.md). An elastic factor is no
    // preconditioner for a tangent: near a collapse the tangent is far softer.
    const bool held_fits = matrix == ElementMatrix::Elastic
                               ? !held_.tangent
                               : held_.tangent && !model_.analysis.strength_reduction;
    try {
        system_.factorize(held_fits);
    } catch (const SingularSystem&) {
        // A tangent that is not positive definite (a mechanism forming): the caller goes on with
        // the elastic matrix.
        if (matrix != ElementMatrix::Tangent) throw;
        return false;
    }
    held_.tangent = matrix == ElementMatrix::Tangent;
    held_.closed = closed_signature(contacts.contacts(), bolts);
    return true;
}

Simulation::LineSearch Simulation::line_search(const Eigen::VectorXd& d, const Eigen::VectorXd& delta,
                                               const Eigen::VectorXd& loads, const ContactSet& contacts,
                                               const std::vector<BoltLink>& bolts, const Balance& at,
                                               double tolerance, double scale, Merit merit) {
    // A full Newton correction through a softening (perfectly plastic) tangent overshoots and
    // can spread yield over the whole model: a share of it is taken.
    //  - Energy (small-strain static analyses with a symmetric tangent, unless a contact slides
    //    against friction or cohesion: minimises_energy): the share that minimises the
    //    potential energy along the correction (energy_line_search). The sum of squares (and,
    //    across contacts, the largest force) stalled such increments far from any collapse: on
    //    the flexible Prandtl footing refined at the footing's edge, 12 of 48 meshes
    //    "collapsed" at 39–68 % of the collapse load when whole steps were not halved
    //    (docs/benchmarks.md, "Newton minimising the energy under a load"). Where the
    //    potential is flat, near a collapse load, an increment flows metres along the
    //    mechanism: the mechanism rule on the displacement in all ends it
    //    (ConvergenceMonitor::assess).
    //  - SumOfSquares (the unsymmetric polish, which has no potential, and a symmetric tangent
    //    along which the energy does not descend): halving until the sum of squares of the
    //    out-of-balance force does not rise, which a Newton direction always lowers at first.
    //  - LargestForce (in static DDA, and while contacts slide against friction or cohesion):
    //    halving until the largest nodal force does not rise. Coulomb friction makes the
    //    verdict depend on the path there: the sum of squares moved the rock-bridge slope's
    //    factor of safety by −1.1 % (a trial that stood stalled), and static DDA's
    //    staged-tunnel verdicts were validated with this merit.
    if (merit == Merit::Energy)
        if (const std::optional<LineSearch> s = energy_line_search(d, delta, loads, contacts, bolts, at, tolerance, scale))
            return *s;
    LineSearch search;
    for (int cut = 0; cut < line_search_cuts; ++cut) {
        ElementAssembly::Evaluation evaluation;
        Eigen::VectorXd r =
            residual(d + search.step * delta, loads, contacts, bolts, returned_, ElementMatrix::None, &evaluation);
        const ResidualNorms n = residual_norms(r);
        if (n.norm <= tolerance * scale || (merit == Merit::LargestForce ? n.norm <= at.norm : n.norm2 <= at.norm2)) {
            search.balance = balance_of(std::move(r), evaluation);
            return search;
        }
        search.step *= 0.5;
    }
    search.lowered = false;
    return search;
}

std::optional<Simulation::LineSearch> Simulation::energy_line_search(const Eigen::VectorXd& d,
                                                                     const Eigen::VectorXd& delta,
                                                                     const Eigen::VectorXd& loads,
                                                                     const ContactSet& contacts,
                                                                     const std::vector<BoltLink>& bolts,
                                                                     const Balance& at, double tolerance,
                                                                     double scale) {
    // With a symmetric tangent the flow is associated: the closest-point return is the gradient
    // of a convex function of the strain increment (Simo & Hughes, Computational Inelasticity,
    // 1998), so the increment minimises a convex potential Π whose slope along the correction δ
    // at a share s is −g(s), g(s) = δᵀR(d + sδ). g falls from g(0) = RᵀK⁻¹R > 0 through zero at
    // the minimum of Π along δ; regula falsi (Illinois) finds a share with |g(s)| ≤ η g(0), the
    // line search of Crisfield (Non-linear Finite Element Analysis of Solids and Structures,
    // vol. 1, 1991). Halving on the sum of squares instead accepted 1/16 of each correction
    // while the active yield planes settled: the homogeneous slope's factor-of-safety search
    // took 575 equilibrium iterations against about 310 (docs/benchmarks.md).
    auto slope = [&](const Eigen::VectorXd& r) {
        double g = 0.0;
        for (Eigen::Index dof = 0; dof < r.size(); ++dof)
            if (bc_.equation[dof] >= 0) g += delta[dof] * r[dof];
        return g;
    };
    const double g0 = slope(at.residual);
    if (!(g0 > 0.0)) return std::nullopt;  // not a descent direction of Π (a tangent not positive definite)
    LineSearch search;
    search.minimised_energy = true;
    ElementAssembly::Evaluation evaluation;  // of the last share tried, which is the one taken
    auto settle = [&](double s, const Eigen::VectorXd& r) {
        const ResidualNorms n = residual_norms(r);
        search.step = s;
        search.lowered = n.norm2 <= at.norm2;
        return n.norm <= tolerance * scale;
    };
    Eigen::VectorXd r = residual(d + delta, loads, contacts, bolts, returned_, ElementMatrix::None, &evaluation);
    double lo = 0.0, g_lo = g0, hi = 1.0, g_hi = slope(r);
    // Π still falling at the whole correction (or balanced there): the whole correction.
    if (settle(1.0, r) || g_hi >= -energy_line_search_slack * g0) {
        search.balance = balance_of(std::move(r), evaluation);
        return search;
    }
    int kept = 0;  // the end kept by the last two shares: + low, − high (Illinois halves its g)
    for (int k = 0; k < energy_line_search_shares; ++k) {
        const double s = lo + g_lo * (hi - lo) / (g_lo - g_hi);
        r = residual(d + s * delta, loads, contacts, bolts, returned_, ElementMatrix::None, &evaluation);
        const double g = slope(r);
        if (settle(s, r) || std::fabs(g) <= energy_line_search_slack * g0) break;
        if (g > 0.0) {
            lo = s;
            g_lo = g;
            if (kept > 0) g_hi *= 0.5;
            kept = 1;
        } else {
            hi = s;
            g_hi = g;
            if (kept < 0) g_lo *= 0.5;
            kept = -1;
        }
    }
    search.balance = balance_of(std::move(r), evaluation);
    return search;
}

ConvergenceMonitor::Iteration Simulation::iteration_of(int k, const Balance& b, const Eigen::VectorXd& d,
                                                        double load_scale, double last_correction, bool newton,
                                                        bool plain, bool flow_counts) const {
    ConvergenceMonitor::Iteration it;
    it.k = k;
    it.norm = b.norm;
    it.scale = std::max({out_of_balance_as_stress() ? b.evaluation.stress_scale : b.evaluation.force_scale, load_scale,
                         1e-30});
    it.last_correction = last_correction;
    // Not below a hundredth of the displacement so far: in a step that only re-equilibrates, the
    // increment is round-off and would never settle.
    const double increment = d.cwiseAbs().maxCoeff(), so_far = state_.displacement.cwiseAbs().maxCoeff();
    it.yardstick = std::max({increment, 0.01 * so_far, 1e-12 * topology_.model_size});
    it.displacement = std::max({increment, so_far, 1e-12 * topology_.model_size});
    it.plain = plain;
    // The mechanism rule (ConvergenceMonitor::assess) weighs the displacement in all in a
    // small-strain analysis, the increment's elsewhere.
    it.total = is_equilibrium_only();
    it.largest = it.total ? (state_.displacement + d).cwiseAbs().maxCoeff() : increment;
    it.flow = flow_counts ? increment : 0.0;
    it.yielding = b.evaluation.yielding;
    it.newton = newton;
    return it;
}

bool Simulation::equilibrate(Eigen::VectorXd& d, const Eigen::VectorXd& loads, const ContactSet& contacts,
                             const std::vector<BoltLink>& bolts, bool& factor_valid, Attempt& attempt) {
    const double tolerance = model_.analysis.plastic_tolerance;
    const double loads_in_play = load_scale(loads);
    ConvergenceMonitor monitor(tolerance, model_.analysis.max_plastic_iterations, mechanism_displacements * displacement_limit_);
    monitor.set_step_contraction(step_contraction_);
    // Whichever way the iteration ends, what it measured serves the step's next ones.
    struct KeepContraction {
        const ConvergenceMonitor& monitor;
        double& kept;
        ~KeepContraction() {
            if (monitor.contraction() > 0.0) kept = monitor.contraction();
        }
    } keep_contraction{monitor, step_contraction_};
    elements_.set_elastic_share(0.0);  // the consistent tangent until it fails (stiffen_tangent)
    AndersonMixing anderson(anderson_depth);
    double previous = std::numeric_limits<double>::infinity(), last_correction = 0.0;
    bool last_minimised_energy = false;  // the last correction's share minimised the energy
    // The next correction with the elastic matrix, once, and then a fresh tangent (see below).
    bool elastic_once = false, was_elastic_once = false;
    bool last_plain = false;  // the last correction: whole, unmixed, with the elastic matrix
    bool newton = uses_newton();
    // The matrix in force is the elastic one (a tangent where nothing yields is one too); a held
    // tangent factor is not.
    bool elastic_matrix = factor_valid && !held_.tangent;
    std::optional<Balance> searched_balance;  // the line search's, at the iterate it moved to
    ConvergenceMonitor::Verdict handed_over = ConvergenceMonitor::Verdict::Stalled;  // to the polish
    for (int k = 0;; ++k) {
        if (stop_check_ && stop_check_()) throw StepInterrupted();
        // Refactorise when K is stale: contacts changed, or the last iteration contracted slowly.
        const ElementMatrix matrix = elastic_once   ? ElementMatrix::Elastic
                                     : factor_valid ? ElementMatrix::None
                                                    : (newton ? ElementMatrix::Tangent : ElementMatrix::Elastic);
        const Balance b = matrix == ElementMatrix::None && searched_balance
                              ? std::move(*searched_balance)
                              : balance_at(d, loads, contacts, bolts, matrix);
        searched_balance.reset();
        attempt.yielding = b.evaluation.yielding;
        // The flow of a correction that minimised the energy counts as progress; not in strength
        // reduction trials: there it let trials just above the factor flow on until they
        // converged, and the homogeneous slope's search took 10 trials to 1.5538 instead of 6 to
        // 1.5469 (a trial's verdict is resolved to the search's 0.5 %).
        const ConvergenceMonitor::Iteration it =
            iteration_of(k, b, d, loads_in_play, last_correction, newton, last_plain,
                         last_minimised_energy && !model_.analysis.strength_reduction);
        const bool converged = monitor.converged(it, elastic_matrix);
        if (converged && monitor.mechanism_when_converged(it)) {
            attempt.why = monitor.why(ConvergenceMonitor::Verdict::Mechanism, it);
            attempt.mechanism = true;
            return false;
        }
        attempt.stopped_unsettled = !converged && attempt.may_stop_unsettled && monitor.balanced(it) &&
                                    contacts.would_change(d, is_equilibrium_only(), attempt.may_stop_for_friction);
        if (converged || attempt.stopped_unsettled) {
            attempt.residual = b.residual;
            return true;
        }
        observe_iteration(it.norm / it.scale, tolerance, it.yielding);
        const ConvergenceMonitor::Verdict verdict = monitor.assess(it);
        // In a small-strain static analysis only from near equilibrium (within_polish_reach). A
        // static DDA step polishes from any stall: with its mass term the polish converges from
        // much farther (in the staged tunnel released over 2 steps 12 of 42 far polishes did, from
        // up to 9,752 times the tolerance), and without them that tunnel collapsed in step 3. So
        // does a strength reduction trial, whose failure is the verdict on its factor: the Prandtl
        // footing of a Tresca-like Hoek–Brown rock mass refined at its edge stalled at 100–250
        // times the tolerance in trials that stand, and its factor came out 8 % low (1.1807
        // against 1.2854) where polishes from there carried them.
        if (uses_unsymmetric_newton() && monitor.hands_over_to_newton(verdict, it) &&
            (!is_equilibrium_only() || model_.analysis.strength_reduction || monitor.within_polish_reach(it))) {
            handed_over = verdict;
            monitor.start_polishing(it);
            newton = true;
            factor_valid = false;
            anderson.reset();
            --k;
            continue;
        }
        if (verdict != ConvergenceMonitor::Verdict::Continue) {
            attempt.why = monitor.why(verdict, it);
            attempt.mechanism = verdict == ConvergenceMonitor::Verdict::Mechanism;
            return false;
        }
        if (matrix != ElementMatrix::None) {
            if (!factorize(matrix, contacts, bolts)) {
                // The polish's tangent is singular where the elastic iteration stalled: Newton
                // cannot start, and the elastic iteration has already shown it gets no further
                // (on Salençon's excavation at 53k elements it went on 30 more iterations at
                // the same force before the load was halved anyway).
                if (monitor.polishing()) {
                    attempt.why = monitor.why(handed_over, it);
                    return false;
                }
                // A stiffened tangent, and once that is mostly elastic, on with the elastic
                // matrix, from the same iterate.
                if (!stiffen_tangent()) newton = false;
                --k;
                continue;
            }
            factor_valid = true;
            elastic_matrix = matrix == ElementMatrix::Elastic || it.yielding == 0;
        }
        Eigen::VectorXd delta;
        try {
            delta = correction(d, b, newton, tolerance * it.scale, contacts.any_closed(), anderson);
        } catch (const SingularSystem&) {
            // A held tangent factor did not fit and the tangent it fell back to factorising is
            // not positive definite: a stiffened tangent, or on with the elastic matrix, as
            // factorize() does.
            if (!newton || !held_.tangent) throw;
            factor_valid = false;
            if (!stiffen_tangent()) newton = false;
            --k;
            continue;
        }
        // A correction of a held tangent factor (the last converged increment's, or an earlier
        // iterate's) that alone would be a mechanism is no sign of one: that tangent is nearly
        // singular along it (on the rigid Prandtl footing refined at its edge, 1e9 m at 58 % of
        // the collapse load, a "collapse" when steps were not halved). The elastic matrix gives
        // this correction instead (the elastic predictor), and a fresh tangent the next.
        if (matrix == ElementMatrix::None && held_.tangent && newton &&
            delta.cwiseAbs().maxCoeff() > mechanism_displacements * displacement_limit_) {
            elastic_once = true;
            factor_valid = false;
            --k;
            continue;
        }
        was_elastic_once = elastic_once;
        elastic_once = false;
        ++attempt.iterations;
        // No line search with the elastic matrix (the initial-stress iteration): its full steps
        // converge while the largest nodal force may rise on the way.
        const bool search = newton && (it.yielding > 0 || matrix == ElementMatrix::Tangent);
        const bool plain_newton = is_equilibrium_only() && !contacts.any_closed() && !monitor.polishing();
        // (A plain Newton iteration that does not minimise the energy has no symmetric tangent,
        // so it is not Newton at all outside a polish, and searches nothing.)
        Merit merit = Merit::LargestForce;
        if (minimises_energy(contacts, monitor.polishing()))
            merit = Merit::Energy;
        else if (monitor.polishing())
            merit = Merit::SumOfSquares;
        LineSearch searched =
            search ? line_search(d, delta, loads, contacts, bolts, b, tolerance, it.scale, merit) : LineSearch{};
        if (plain_newton && monitor.beyond_improvement(it, searched.lowered)) {
            if (monitor.mechanism_when_converged(it)) {
                attempt.why = monitor.why(ConvergenceMonitor::Verdict::Mechanism, it);
                attempt.mechanism = true;
                return false;
            }
            attempt.residual = b.residual;
            return true;
        }
        const double step = searched.step;
        d += step * delta;
        searched_balance = std::move(searched.balance);
        last_correction = step * delta.cwiseAbs().maxCoeff();
        last_minimised_energy = searched.minimised_energy;
        last_plain = !newton && step == 1.0 && !anderson.mixing();
        // The factor is kept while it contracts the out-of-balance force well enough. In the
        // polish of a small-strain static analysis, also when it was factorised for this very
        // correction and no share of that correction lowered the force: the line search then
        // moved the iterate by a sliver, and the tangent there is the one just factorised (a
        // failing polish refactorised at every one of its iterations: 72 factorisations in one
        // step of Salençon's tunnel cut by a joint, 58 with this, the same iterations). Not
        // in static DDA: there the staged tunnel released over 5 steps, whose verdict hangs on
        // its polishes' paths, then ended at the time step's floor (docs/benchmarks.md, "A
        // futile polish keeps its factor").
        const bool fresh_and_futile = is_equilibrium_only() && monitor.polishing() && matrix != ElementMatrix::None &&
                                      !searched.lowered;
        if (k > 0 && newton && b.norm > keep_factor_contraction * previous && !fresh_and_futile) factor_valid = false;
        if (was_elastic_once) factor_valid = false;
        previous = b.norm;
    }
}

bool Simulation::minimises_energy(const ContactSet& contacts, bool polishing) const {
    // The increment of an associated perfectly plastic model minimises a convex potential, also
    // across closed contacts whose forces are springs: locked ones, and smooth ones sliding (a
    // normal spring alone). Not while a contact slides against friction or cohesion, a force
    // the open–close loop updates from the last normal force: with the energy line search there
    // the rock bridges of the Jennings direct shear test (four fifths persistent) never settled
    // their contacts, and the rock-bridge slope's and the jointed tunnel's factors were
    // validated with the largest force. Not in static DDA either (its verdicts were validated
    // with that too).
    return is_equilibrium_only() && !polishing && elements_.symmetric_tangent() &&
           !contacts.any_sliding_with_strength();
}

bool Simulation::stiffen_tangent() {
    // A symmetric tangent that is not positive definite: perfectly plastic points leave it
    // singular where a few elements can deform along their flow directions alone (a local
    // mechanism of the tangent, not of the model), and round-off then makes a pivot negative.
    // Falling back to the elastic iteration there stalled increments below the collapse load
    // (the rigid Prandtl footing refined at its edge stalled at 300–509 kPa, 58–99 % of it, on
    // 6 of 48 meshes when steps were not halved). A share of the elastic matrix, 10⁻³ of it and
    // tenfold after each failure up to a tenth, makes the tangent positive definite; Newton
    // with it still converges, each correction a little short along the flow directions. In
    // small-strain load steps only: static DDA keeps its elastic fallback, with which its
    // verdicts were validated, and so do strength reduction trials, where it ends failing tries
    // sooner (the homogeneous slope's search: 205 factorisations against 219, the same trials
    // and factor).
    const double share = elements_.elastic_share();
    if (!is_equilibrium_only() || model_.analysis.strength_reduction || share >= max_elastic_share) return false;
    elements_.set_elastic_share(share == 0.0 ? first_elastic_share : 10.0 * share);
    return true;
}

Eigen::VectorXd Simulation::correction(const Eigen::VectorXd& d, const Balance& b, bool newton, double force_tolerance,
                                       bool any_closed, AndersonMixing& anderson) {
    // An elastic correction is solved to the iteration's own tolerance: where a held factor of an
    // earlier matrix (another step's geometry or contact states) preconditions the solve, more
    // digits only cost conjugate-gradient iterations that the next correction undoes, and the
    // one correction of a linear iteration (ConvergenceMonitor::converged) is then as exact as
    // the tolerance asks.
    Eigen::VectorXd delta =
        solve_reduced(b.rhs, newton ? newton_solve_tolerance : model_.analysis.plastic_tolerance);
    // With the elastic matrix (non-associated flow, or a tangent that is not positive definite)
    // the iteration is a fixed point d ← d + K⁻¹R(d) that contracts slowly once much of the
    // model yields: Anderson acceleration (Walker & Ni 2011) mixes the last corrections; it
    // costs a small least-squares problem per iteration. Once the force is within tolerance only
    // the displacement is settling: plain corrections then where contacts are closed (mixed ones
    // wander along directions the force hardly sees, such as a loosened block); without closed
    // contacts mixing goes on (plain corrections of a non-associated plastic zone can drift for
    // hundreds of iterations when no mass term damps them, as in a small-strain static
    // analysis: Salençon's tunnel).
    if (!newton && b.evaluation.yielding > 0 && (b.norm > force_tolerance || !any_closed))
        return anderson.next(d, delta);
    anderson.reset();
    return delta;
}

void Simulation::observe_iteration(double out_of_balance, double tolerance, int yielding) {
    if (!iteration_observer_) return;
    ++iterating_.iteration;
    iterating_.out_of_balance = out_of_balance;
    iterating_.tolerance = tolerance;
    iterating_.yielding = yielding;
    iteration_observer_(iterating_);
}

Eigen::VectorXd Simulation::solve_reduced(const Eigen::VectorXd& rhs, double tolerance) {
    const auto start = Clock::now();
    const double factorizing = system_.factorization_seconds();
    const Eigen::VectorXd solution = system_.solve(rhs, tolerance);
    Eigen::VectorXd d(state_.displacement.size());
    for (Eigen::Index dof = 0; dof < d.size(); ++dof) d[dof] = bc_.equation[dof] >= 0 ? solution[bc_.equation[dof]] : 0.0;
    // (less a factorisation the solve fell back to: it counts as one)
    timings_.solve += seconds_since(start) - (system_.factorization_seconds() - factorizing);
    return d;
}

}  // namespace mcdda

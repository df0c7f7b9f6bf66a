#include "run/ConvergenceMonitor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mcdda {

namespace {

/// Iterations without halving the out-of-balance force before a try counts as not converging:
/// the fixed-point iteration with the elastic matrix, and Newton (which halves it every
/// iteration or two while converging; past the load a perfectly plastic model can carry, its
/// line search creeps along the mechanism). Newton minimising the energy also counts a doubling
/// of its flow as progress (see assess).
constexpr int stall_window = 30;
constexpr int newton_stall_window = 10;
/// Newton iterations with the unsymmetric tangent after the elastic iteration of a non-associated
/// model stalled or reached its cap.
constexpr int polish_iterations = 30;

}  // namespace

ConvergenceMonitor::ConvergenceMonitor(double tolerance, int max_iterations, double mechanism_displacement)
    : tolerance_(tolerance),
      max_iterations_(max_iterations),
      mechanism_displacement_(mechanism_displacement),
      best_norm_(std::numeric_limits<double>::infinity()),
      best_correction_(std::numeric_limits<double>::infinity()) {}

bool ConvergenceMonitor::converged(const Iteration& it, bool elastic_matrix) {
    // A linear iteration (nothing yields, the matrix is the elastic one of the current contact
    // states) has converged after one solve: its correction solved the problem exactly.
    const bool linear = it.yielding == 0 && elastic_matrix && it.k == 1 && first_linear_;
    if (it.k == 0) first_linear_ = it.yielding == 0;
    const bool tail_settled = settled(it);  // (it records every correction)
    return it.k > 0 && it.norm <= tolerance_ * it.scale &&
           (it.last_correction <= tolerance_ * it.yardstick || linear || tail_settled);
}

bool ConvergenceMonitor::settled(const Iteration& it) {
    // Plain elastic corrections (the initial-stress iteration, unmixed, whole) shrink
    // geometrically once the yield planes are set, by a ratio ρ that the last corrections show;
    // what is left to move is then at most c·ρ/(1 − ρ), the tail of the geometric series (the
    // larger of the last two ratios is taken: one ratio may be low by chance). Within the
    // tolerance of the displacement so far that is as settled as the force is balanced — both
    // against the state, not against the increment. Against the increment alone a load step of a
    // hundredth of the load asked the corrections of a small plastic zone in the jointed tunnel
    // to shrink to nanometres: 3 in 4 of its iterations (docs/benchmarks.md, "Settled against the
    // displacement so far").
    if (it.k == 0 || !it.plain) {
        plain_before_ = ratio_before_ = 0.0;
        return false;
    }
    const double ratio = plain_before_ > 0.0 ? it.last_correction / plain_before_ : 0.0;
    double contraction = std::max(ratio, ratio_before_);
    bool known = plain_before_ > 0.0 && ratio_before_ > 0.0;
    if (known) contraction_ = contraction;
    // Until two ratios of its own are known, the contraction measured earlier in the step: the
    // open–close rounds, friction rounds and relaxation increments of one step iterate about the
    // same plastic zone, so their plain corrections contract alike. Without it every such
    // iteration spent two or three corrections measuring it anew once its force was balanced
    // (the default example: 2,226 equilibrium iterations, 1,860 with it, the same result to
    // 10⁻⁶; docs/benchmarks.md, "The contraction a step has measured"). Not across steps: taken
    // from the step before, the default example's plastic area moved by 0.6 %.
    if (!known && step_contraction_ > 0.0 && step_contraction_ < 1.0) {
        contraction = std::max(contraction, step_contraction_);
        known = true;
    }
    ratio_before_ = ratio;
    plain_before_ = it.last_correction;
    return known && contraction < 1.0 &&
           it.last_correction * contraction / (1.0 - contraction) <= tolerance_ * it.displacement;
}

ConvergenceMonitor::Verdict ConvergenceMonitor::assess(const Iteration& it) {
    // Diverging: non-finite, or growing far beyond the start once the tangent has had a few
    // corrections (a contact change alone may start from a large out-of-balance force).
    if (it.k == 0) first_norm_ = it.norm;
    const bool diverging =
        !std::isfinite(it.norm) || (it.k >= 3 && it.norm > 1e6 * std::max(first_norm_, tolerance_ * it.scale));
    // Stalled: Newton's force or correction, or the elastic iteration's force, has not halved
    // for the window's iterations. Converging iterations halve them every few iterations; at a
    // load beyond the model's capacity they creep for ever. The elastic iteration's mixed
    // corrections rise and fall as Anderson's history turns over, so a new smallest one is no
    // sign of progress there (counting it let Salençon's excavation at 53k elements run two
    // tries of 66 iterations each before its load was halved: 180 iterations in the step
    // against 116 with this rule alone, with the same result).
    if (it.norm < 0.5 * best_norm_) {
        best_norm_ = it.norm;
        best_at_ = it.k;
    }
    if (it.k > 0 && it.last_correction < 0.5 * best_correction_) {
        best_correction_ = it.last_correction;
        best_correction_at_ = it.k;
    }
    // Newton minimising the potential energy (associated flow: the energy line search) lowers
    // it at every correction, so it cannot cycle: the increment converges, or it flows along a
    // mechanism until the mechanism rule below ends it. While it flows, its force and
    // correction need not fall (on the flexible Prandtl footing refined at the footing's edge, a
    // 1 kPa step at 99.5 % of the collapse load flowed from 1 cm to 0.6 m in 10 iterations and
    // was declared stalled, where its halves were carried to 0.4 % more load). A doubling of the
    // flow within the window is progress: from the first correction to the mechanism limit that
    // is a few doublings, so the window still bounds the try.
    if (it.k > 0 && it.flow > 0.0 && (flow_mark_ == 0.0 || it.flow > 2.0 * flow_mark_)) {
        flow_mark_ = it.flow;
        flow_doubled_at_ = it.k;
    }
    // (Once the force is within tolerance only the correction lags: the iteration is settling,
    // not stalled, and the iteration cap bounds it.)
    const bool stalled =
        it.norm > tolerance_ * it.scale &&
        (it.newton ? it.k - std::max({best_at_, best_correction_at_, flow_doubled_at_}) >= newton_stall_window
                   : it.k - best_at_ >= stall_window);
    // A mechanism: yielding material and a displacement many times the largest a step may take.
    // The load is past what the material can carry. In static DDA and dynamics the increment's
    // displacement (a step must stay within reach of contact detection); in a small-strain
    // analysis the displacement in all, so that the verdict does not depend on the load step:
    // near the collapse load a whole step's increment flowed past the limit where its halves,
    // each within it, carried more load (the flexible footing bisected to 5.1731 cu while whole
    // 1 kPa steps stopped at 5.17), and an increment that converges beyond the limit is a
    // mechanism too (mechanism_when_converged). Letting iterates pass the limit on their way,
    // up to ten times it, changed no verdict on 192 refined footings and cost 15–50 % more
    // factorisations (docs/benchmarks.md, "Newton minimising the energy under a load").
    const bool mechanism = beyond_mechanism_limit(it);
    const bool capped = polishing_ ? it.k - polish_from_ >= polish_iterations : it.k >= max_iterations_;
    if (diverging) return Verdict::Diverging;
    if (mechanism) return Verdict::Mechanism;
    if (stalled) return Verdict::Stalled;
    if (capped) return Verdict::Capped;
    return Verdict::Continue;
}

void ConvergenceMonitor::start_polishing(const Iteration& it) {
    polishing_ = true;
    polish_from_ = it.k;
    best_norm_ = it.norm;
    best_at_ = best_correction_at_ = it.k;
    best_correction_ = std::numeric_limits<double>::infinity();
}

std::string ConvergenceMonitor::why(Verdict v, const Iteration& it) const {
    const std::string where = " (" + std::to_string(it.yielding) + " integration points yielding)";
    char numbers[240];
    switch (v) {
        case Verdict::Diverging:
            std::snprintf(numbers, sizeof numbers, "the out-of-balance force, %.3g of the force scale, ",
                          it.norm / it.scale);
            return "the equilibrium iterations diverged: " + std::string(numbers) + "grew without bound";
        case Verdict::Mechanism:
            return std::string("a mechanism formed: the displacement ") + (it.total ? "" : "increment ") +
                   "reached " + std::to_string(it.largest) + " m (limit " + std::to_string(mechanism_displacement_) +
                   " m) with material yielding";
        case Verdict::Stalled:
            std::snprintf(numbers, sizeof numbers,
                          "the out-of-balance force, %.3g of the force scale, stayed above the tolerance %.3g "
                          "and stopped decreasing (not halved in %d iterations) after %d iterations",
                          it.norm / it.scale, tolerance_, it.newton ? newton_stall_window : stall_window, it.k);
            return "the equilibrium iterations stalled: " + std::string(numbers) + where;
        case Verdict::Capped:
            // Within the force tolerance only the displacement had not settled (converged needs
            // both): say that, not that the force was above a tolerance it was below.
            if (it.norm <= tolerance_ * it.scale) {
                std::snprintf(numbers, sizeof numbers,
                              "after %d iterations the out-of-balance force was within tolerance (%.3g of the "
                              "force scale) but the displacement still changed by %.3g of the increment per "
                              "iteration, above the tolerance %.3g",
                              it.k, it.norm / it.scale, it.last_correction / it.yardstick, tolerance_);
                return "the equilibrium iterations reached their limit: " + std::string(numbers) + where;
            }
            std::snprintf(numbers, sizeof numbers,
                          "after %d iterations the out-of-balance force was %.3g of the force scale, above the "
                          "tolerance %.3g",
                          it.k, it.norm / it.scale, tolerance_);
            return "the equilibrium iterations reached their limit: " + std::string(numbers) + where;
        case Verdict::Continue: break;
    }
    return {};
}

}  // namespace mcdda

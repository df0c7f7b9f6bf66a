#pragma once
/// \file ConvergenceMonitor.hpp
/// The verdicts of the equilibrium iterations of one load increment, iteration by iteration:
/// converged, still progressing, or failed (diverging, stalled, a mechanism, out of iterations).
/// Pure bookkeeping of norms, so each rule can be read and tested on its own.

#include <string>

namespace mcdda {

class ConvergenceMonitor {
public:
    /// `tolerance`: of the out-of-balance force relative to the force scale, and of the last
    /// correction relative to the increment. `max_iterations`: the cap of one try.
    /// `mechanism_displacement`: an increment beyond it, with material yielding, is a mechanism.
    ConvergenceMonitor(double tolerance, int max_iterations, double mechanism_displacement);

    /// One iteration's numbers: the largest out-of-balance force (`norm`) and its `scale`, the
    /// last correction and the increment's `yardstick`, the largest increment and the
    /// integration points yielding.
    struct Iteration {
        int k = 0;
        double norm = 0.0, scale = 1.0;
        double last_correction = 0.0, yardstick = 1.0;
        double displacement = 0.0;  ///< the largest displacement so far, with the increment
        /// What the mechanism rule weighs: the largest displacement of the increment, or with
        /// `total` the largest displacement in all (small strain, see assess).
        double largest = 0.0;
        bool total = false;
        /// The increment's largest displacement when the last correction minimised the potential
        /// energy along itself (the energy line search: associated flow); 0 otherwise.
        double flow = 0.0;
        int yielding = 0;
        bool newton = false;  ///< the tangent is in use (Newton), not the elastic matrix
        bool plain = false;   ///< the last correction was a whole, unmixed one with the elastic matrix
    };

    /// Converged: the force is small against the forces in play, and so is the last correction
    /// against the increment (a slow iteration leaves a small force but a large remaining
    /// displacement), or — plain elastic corrections — what is left to move against the
    /// displacement so far, or the iteration is linear and its one correction solved it exactly.
    /// `elastic_matrix`: the matrix in force is the elastic one of the current contact states.
    bool converged(const Iteration& it, bool elastic_matrix);
    /// The force alone is small (after a correction): enough for a round of the open–close loop
    /// whose contact states are about to change anyway.
    bool balanced(const Iteration& it) const { return it.k > 0 && it.norm <= tolerance_ * it.scale; }
    /// Newton's correction from a force already within tolerance that no share of it lowers
    /// (`lowered`: the share the line search took lowers it, Simulation::LineSearch) runs along
    /// the nearly singular tangent of a forming mechanism: its length measures that, not a
    /// distance to equilibrium. Iterating on raised the force back above the tolerance until the
    /// try stalled, an increment in equilibrium declared not carried; so it is accepted as it
    /// stands. For plain Newton only (small-strain, static, no closed contacts): the caller
    /// decides that.
    bool beyond_improvement(const Iteration& it, bool lowered) const {
        return !lowered && it.norm <= tolerance_ * it.scale;
    }

    /// A small-strain increment (`total`) that converged with a displacement beyond the
    /// mechanism limit, material yielding: not carried, a mechanism (see assess).
    bool mechanism_when_converged(const Iteration& it) const { return it.total && beyond_mechanism_limit(it); }

    enum class Verdict { Continue, Diverging, Stalled, Mechanism, Capped };
    /// Records the iteration and judges it (see the rules in the .cpp).
    Verdict assess(const Iteration& it);

    /// Non-associated flow: once the elastic iteration stalls or reaches its cap with material
    /// yielding, it has done what it can, and Newton with the exact (unsymmetric) tangent takes
    /// over. Close to equilibrium, where the active yield planes no longer change, that converges
    /// quadratically, so an increment that can be carried is not declared uncarried for a force
    /// just above the tolerance.
    bool hands_over_to_newton(Verdict v, const Iteration& it) const {
        return (v == Verdict::Stalled || v == Verdict::Capped) && !polishing_ && it.yielding > 0;
    }
    /// Whether the force is within `polish_reach` times the tolerance, where a polish can close
    /// the gap. Farther, the tangent is of yield planes that will still change: of the polishes
    /// traced in the shipped non-associated small-strain examples, 7 of 31 converged from within
    /// 100 times the tolerance and 1 of 12 from beyond (11 failed, 5 of them on a tangent the LU
    /// found singular), each LU costing about a Cholesky factorisation (docs/benchmarks.md, "A
    /// polish only near equilibrium").
    bool within_polish_reach(const Iteration& it) const { return it.norm <= polish_reach * tolerance_ * it.scale; }
    static constexpr double polish_reach = 100.0;
    /// Newton with the exact unsymmetric tangent takes over after iteration k (the polish of a
    /// non-associated model): a fresh stall window and a cap of its own.
    void start_polishing(const Iteration& it);
    bool polishing() const { return polishing_; }
    /// The contraction of plain elastic corrections that earlier equilibrium iterations of the
    /// same step measured (0: none): `settled` takes it until this iteration has measured its own.
    void set_step_contraction(double contraction) { step_contraction_ = contraction; }
    /// The last contraction this iteration measured (0: none yet).
    double contraction() const { return contraction_; }

    /// Why a failed try failed, in words for the user.
    std::string why(Verdict v, const Iteration& it) const;

private:
    /// Plain elastic corrections whose geometric tail is within the tolerance of the
    /// displacement so far (see the .cpp); records the corrections it needs.
    bool settled(const Iteration& it);

    double tolerance_;
    int max_iterations_;
    double mechanism_displacement_;
    /// Material yielding and the displacement the mechanism rule weighs beyond its limit.
    bool beyond_mechanism_limit(const Iteration& it) const {
        return it.yielding > 0 && it.largest > mechanism_displacement_;
    }
    double first_norm_ = 0.0;
    double best_norm_, best_correction_;
    double flow_mark_ = 0.0;  ///< the flow when it last doubled
    int best_at_ = 0, best_correction_at_ = 0, flow_doubled_at_ = 0;
    bool polishing_ = false;
    bool first_linear_ = false;  ///< nothing yielded at the first iteration
    double plain_before_ = 0.0;  ///< the plain correction before the last one (0: none)
    double ratio_before_ = 0.0;  ///< the contraction between the two before (0: none)
    int polish_from_ = 0;
    double step_contraction_ = 0.0;  ///< see set_step_contraction
    double contraction_ = 0.0;       ///< see contraction()
};

}  // namespace mcdda

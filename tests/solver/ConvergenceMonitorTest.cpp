// The verdicts of the equilibrium iterations (solver/run/ConvergenceMonitor), rule by rule.

#include "run/ConvergenceMonitor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using mcdda::ConvergenceMonitor;
using Verdict = ConvergenceMonitor::Verdict;

namespace {

ConvergenceMonitor::Iteration at(int k, double norm, double correction = 1.0, bool newton = false, int yielding = 1) {
    ConvergenceMonitor::Iteration it;
    it.k = k;
    it.norm = norm;
    it.scale = 1.0;
    it.last_correction = correction;
    it.yardstick = 1.0;
    it.largest = 0.0;
    it.yielding = yielding;
    it.newton = newton;
    return it;
}

}  // namespace

TEST(ConvergenceMonitor, ConvergedNeedsSmallForceAndSmallCorrectionAfterTheFirstIteration) {
    ConvergenceMonitor m(1e-4, 200, 1.0);
    EXPECT_FALSE(m.converged(at(0, 1e-6, 1e-6), false));  // nothing solved yet
    EXPECT_TRUE(m.converged(at(1, 1e-6, 1e-6), false));
    EXPECT_FALSE(m.converged(at(1, 1e-6, 1e-2), false));  // force small, displacement still moving
    EXPECT_FALSE(m.converged(at(1, 1e-2, 1e-6), false));
}

// Plain elastic corrections shrinking by 0.88 per iteration, of an increment of 1 in a state
// displaced by 100 so far (a load step of a hundredth): once three in a row show the ratio, the
// tail c·ρ/(1 − ρ) is measured against the displacement so far.
TEST(ConvergenceMonitor, PlainCorrectionsSettleAgainstTheDisplacementSoFar) {
    auto plain = [](int k, double correction, double so_far, bool is_plain = true) {
        ConvergenceMonitor::Iteration it = at(k, 1e-6, correction);
        it.displacement = so_far;
        it.plain = is_plain;
        return it;
    };
    ConvergenceMonitor m(1e-4, 200, 1.0);
    EXPECT_FALSE(m.converged(plain(1, 1e-3, 100.0), false));
    EXPECT_FALSE(m.converged(plain(2, 0.88e-3, 100.0), false));  // one ratio is not yet a trend
    // 0.7744e-3 · 0.88 / 0.12 = 5.7e-3 ≤ 1e-4 · 100; against the increment it needs 1e-4.
    EXPECT_TRUE(m.converged(plain(3, 0.7744e-3, 100.0), false));

    // The same corrections against a displacement so far no larger than the increment: not yet.
    ConvergenceMonitor first_step(1e-4, 200, 1.0);
    for (int k = 1; k <= 3; ++k) EXPECT_FALSE(first_step.converged(plain(k, 1e-3 * std::pow(0.88, k - 1), 1.0), false));

    // Mixed (Anderson) corrections rise and fall: no ratio is read from them.
    ConvergenceMonitor mixed(1e-4, 200, 1.0);
    for (int k = 1; k <= 4; ++k) EXPECT_FALSE(mixed.converged(plain(k, 1e-3 * std::pow(0.88, k - 1), 100.0, false), false));

    // A correction that grew again: the larger of the last two ratios (≥ 1) rules the tail out.
    ConvergenceMonitor bumpy(1e-4, 200, 1.0);
    EXPECT_FALSE(bumpy.converged(plain(1, 1e-3, 100.0), false));
    EXPECT_FALSE(bumpy.converged(plain(2, 1.2e-3, 100.0), false));
    EXPECT_FALSE(bumpy.converged(plain(3, 0.2e-3, 100.0), false));
    EXPECT_TRUE(bumpy.converged(plain(4, 0.12e-3, 100.0), false));  // 0.17 and 0.6 since
}

// The open–close rounds and relaxation increments of one step iterate about the same plastic
// zone: an iteration takes the contraction an earlier one of its step measured until it has two
// ratios of its own.
TEST(ConvergenceMonitor, TheStepsContractionServesUntilAnIterationMeasuresItsOwn) {
    auto plain = [](int k, double correction) {
        ConvergenceMonitor::Iteration it = at(k, 1e-6, correction);
        it.displacement = 100.0;
        it.plain = true;
        return it;
    };
    ConvergenceMonitor first(1e-4, 200, 1.0);
    EXPECT_EQ(first.contraction(), 0.0);
    first.converged(plain(1, 1e-3), false);
    first.converged(plain(2, 0.88e-3), false);
    first.converged(plain(3, 0.7744e-3), false);
    EXPECT_NEAR(first.contraction(), 0.88, 1e-12);

    // 0.5e-3 · 0.88 / 0.12 = 3.7e-3 ≤ 1e-4 · 100 at its first plain correction; alone it would
    // need two more.
    ConvergenceMonitor next(1e-4, 200, 1.0);
    next.set_step_contraction(first.contraction());
    EXPECT_TRUE(next.converged(plain(1, 0.5e-3), false));
    ConvergenceMonitor alone(1e-4, 200, 1.0);
    EXPECT_FALSE(alone.converged(plain(1, 0.5e-3), false));

    // A step whose corrections hardly contract: the tail 0.5e-3 · 0.999 / 0.001 = 0.5 is too long.
    ConvergenceMonitor slow(1e-4, 200, 1.0);
    slow.set_step_contraction(0.999);
    EXPECT_FALSE(slow.converged(plain(1, 0.5e-3), false));
    // A ratio of its own larger than the step's rules: 2e-2 → 1.96e-2 is 0.98, a tail of 0.96.
    ConvergenceMonitor larger(1e-4, 200, 1.0);
    larger.set_step_contraction(0.5);
    EXPECT_FALSE(larger.converged(plain(1, 2e-2), false));
    EXPECT_FALSE(larger.converged(plain(2, 0.98 * 2e-2), false));
    // No contraction at all (corrections that grew) lends nothing.
    ConvergenceMonitor grown(1e-4, 200, 1.0);
    grown.set_step_contraction(1.2);
    EXPECT_FALSE(grown.converged(plain(1, 0.5e-3), false));
}

TEST(ConvergenceMonitor, BalancedNeedsOnlyTheForceAfterTheFirstIteration) {
    const ConvergenceMonitor m(1e-4, 200, 1.0);
    EXPECT_FALSE(m.balanced(at(0, 1e-6, 1e-6)));      // nothing solved yet
    EXPECT_TRUE(m.balanced(at(1, 1e-6, 1e-2)));       // the displacement may still move
    EXPECT_FALSE(m.balanced(at(1, 1e-2, 1e-6)));
}

TEST(ConvergenceMonitor, AnIncrementInEquilibriumThatNewtonCannotImproveStands) {
    const ConvergenceMonitor m(1e-4, 200, 1.0);
    EXPECT_TRUE(m.beyond_improvement(at(3, 5e-5, 0.7, true), false));   // no share of the correction lowers it
    EXPECT_FALSE(m.beyond_improvement(at(3, 5e-5, 0.7, true), true));   // a share does: iterate on
    EXPECT_FALSE(m.beyond_improvement(at(3, 2e-4, 0.7, true), false));  // out of balance: not in equilibrium
}

TEST(ConvergenceMonitor, ALinearIterationHasConvergedAfterOneSolve) {
    ConvergenceMonitor m(1e-4, 200, 1.0);
    EXPECT_FALSE(m.converged(at(0, 1.0, 0.0, false, 0), true));
    // Its correction was large (it solved the whole increment) but exact.
    EXPECT_TRUE(m.converged(at(1, 1e-9, 0.5, false, 0), true));
    ConvergenceMonitor yielded(1e-4, 200, 1.0);
    EXPECT_FALSE(yielded.converged(at(0, 1.0, 0.0, false, 3), true));
    EXPECT_FALSE(yielded.converged(at(1, 1e-9, 0.5, false, 0), true));  // something yielded at the start
}

TEST(ConvergenceMonitor, StallsWhenTheForceIsNotHalvedWithinTheWindow) {
    ConvergenceMonitor elastic(1e-4, 1000, 1.0);
    int k = 0;
    Verdict v = Verdict::Continue;
    for (; k < 100 && v == Verdict::Continue; ++k) v = elastic.assess(at(k, 1.0 - 0.001 * k));
    EXPECT_EQ(v, Verdict::Stalled);
    EXPECT_EQ(k - 1, 30);  // the elastic iteration's window
    ConvergenceMonitor newton(1e-4, 1000, 1.0);
    v = Verdict::Continue;
    for (k = 0; k < 100 && v == Verdict::Continue; ++k) v = newton.assess(at(k, 1.0 - 0.001 * k, 1.0, true));
    EXPECT_EQ(v, Verdict::Stalled);
    EXPECT_EQ(k - 1, 11);  // Newton's, counted from its first correction (iteration 1)
    // Halving every few iterations never stalls.
    ConvergenceMonitor converging(1e-12, 1000, 1.0);
    for (k = 0; k < 120; ++k) ASSERT_EQ(converging.assess(at(k, std::pow(0.5, k / 5.0))), Verdict::Continue) << k;
}

TEST(ConvergenceMonitor, NewtonMinimisingTheEnergyProgressesWhileItsFlowDoubles) {
    // A Newton iteration that minimises the energy and flows along a forming mechanism: its force
    // and correction do not fall, but its increment doubles every third iteration. It goes on
    // (until it converges or the mechanism rule ends it) where the same numbers without the flow
    // stall after Newton's window.
    ConvergenceMonitor flowing(1e-4, 1000, 1e9);
    ConvergenceMonitor creeping(1e-4, 1000, 1e9);
    Verdict flow_verdict = Verdict::Continue, creep_verdict = Verdict::Continue;
    int k = 0;
    for (; k < 40; ++k) {
        auto it = at(k, 1.0, 1.0, true);
        creep_verdict = creeping.assess(it);
        it.flow = 0.01 * std::pow(2.0, k / 3);
        flow_verdict = flowing.assess(it);
        if (flow_verdict != Verdict::Continue) break;
    }
    EXPECT_EQ(k, 40) << "stalled while flowing";
    EXPECT_EQ(creep_verdict, Verdict::Stalled);
    // Once the flow stops doubling the window runs again.
    for (int j = 0; j < 12 && flow_verdict == Verdict::Continue; ++j, ++k) {
        auto it = at(k, 1.0, 1.0, true);
        it.flow = 0.01 * std::pow(2.0, 39 / 3) * 1.01;
        flow_verdict = flowing.assess(it);
    }
    EXPECT_EQ(flow_verdict, Verdict::Stalled);
}

TEST(ConvergenceMonitor, AMechanismOfTheDisplacementInAllSaysSo) {
    ConvergenceMonitor m(1e-4, 200, 1.0);
    auto it = at(0, 1.0);
    it.largest = 2.0;
    it.total = true;
    EXPECT_EQ(m.assess(it), Verdict::Mechanism);
    EXPECT_NE(m.why(Verdict::Mechanism, it).find("the displacement reached 2"), std::string::npos);
    it.total = false;
    EXPECT_NE(m.why(Verdict::Mechanism, it).find("the displacement increment reached 2"), std::string::npos);
}

TEST(ConvergenceMonitor, DivergenceMechanismAndCap) {
    ConvergenceMonitor m(1e-4, 200, 1.0);
    EXPECT_EQ(m.assess(at(0, 1.0)), Verdict::Continue);
    EXPECT_EQ(m.assess(at(1, std::numeric_limits<double>::quiet_NaN())), Verdict::Diverging);
    ConvergenceMonitor growing(1e-4, 200, 1.0);
    EXPECT_EQ(growing.assess(at(0, 1.0)), Verdict::Continue);
    EXPECT_EQ(growing.assess(at(2, 1e7)), Verdict::Continue);  // a contact change may start large
    EXPECT_EQ(growing.assess(at(3, 1e7)), Verdict::Diverging);
    ConvergenceMonitor mech(1e-4, 200, 1.0);
    auto it = at(0, 1.0);
    it.largest = 2.0;
    EXPECT_EQ(mech.assess(it), Verdict::Mechanism);
    it.yielding = 0;  // a large move without yielding is a contact question, not a mechanism
    ConvergenceMonitor rigid(1e-4, 200, 1.0);
    EXPECT_EQ(rigid.assess(it), Verdict::Continue);
    ConvergenceMonitor capped(1e-12, 5, 1.0);
    Verdict v = Verdict::Continue;
    int k = 0;
    for (; v == Verdict::Continue; ++k) v = capped.assess(at(k, std::pow(0.1, k)));
    EXPECT_EQ(v, Verdict::Capped);
    EXPECT_EQ(k - 1, 5);
    EXPECT_NE(capped.why(v, at(5, 1e-5)).find("reached their limit"), std::string::npos);
}

TEST(ConvergenceMonitor, ACapWithTheForceWithinToleranceBlamesTheDisplacement) {
    // The force was below the tolerance and only the corrections had not settled: the message
    // must not say the force was above the tolerance.
    ConvergenceMonitor m(1e-4, 5, 1.0);
    const std::string why = m.why(Verdict::Capped, at(5, 6.21e-6, 3e-3));
    EXPECT_EQ(why.find("force scale, above"), std::string::npos) << why;
    EXPECT_NE(why.find("within tolerance (6.21e-06 of the force scale)"), std::string::npos) << why;
    EXPECT_NE(why.find("changed by 0.003 of the increment"), std::string::npos) << why;
    const std::string force = m.why(Verdict::Capped, at(5, 2e-3, 1e-6));
    EXPECT_NE(force.find("out-of-balance force was 0.002 of the force scale, above the tolerance"), std::string::npos)
        << force;
}

TEST(ConvergenceMonitor, PolishingGetsAFreshWindowAndItsOwnCap) {
    ConvergenceMonitor m(1e-12, 40, 1.0);
    Verdict v = Verdict::Continue;
    int k = 0;
    for (; v == Verdict::Continue; ++k) v = m.assess(at(k, 1.0));
    --k;
    ASSERT_EQ(v, Verdict::Stalled);
    ASSERT_TRUE(m.hands_over_to_newton(v, at(k, 1.0)));
    EXPECT_FALSE(m.hands_over_to_newton(v, at(k, 1.0, 1.0, false, 0)));  // nothing yields: nothing to polish
    m.start_polishing(at(k, 1.0, 1.0, true));
    EXPECT_TRUE(m.polishing());
    EXPECT_FALSE(m.hands_over_to_newton(Verdict::Stalled, at(k, 1.0)));  // once only
    // Newton quartering the force every iteration runs until its cap of 30 iterations.
    int n = 0;
    v = Verdict::Continue;
    for (; v == Verdict::Continue; ++n) v = m.assess(at(k + n, std::pow(0.25, n), std::pow(0.25, n), true));
    EXPECT_EQ(v, Verdict::Capped);
    EXPECT_EQ(n - 1, 30);
}

TEST(ConvergenceMonitor, APolishReachesOnlyFromNearEquilibrium) {
    const ConvergenceMonitor m(1e-4, 40, 1.0);
    EXPECT_TRUE(m.within_polish_reach(at(10, 50 * 1e-4)));
    EXPECT_TRUE(m.within_polish_reach(at(10, ConvergenceMonitor::polish_reach * 1e-4)));
    EXPECT_FALSE(m.within_polish_reach(at(10, 424 * 1e-4)));  // Salençon's excavation at 53k elements
}

// A block on a 40° incline: with joint friction 20° it slides by
// s(t) = ½ g (sin α − cos α tan φ) t² (1.785 m at t = 1 s); with 40.1° it stays.

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

namespace {
constexpr double g = 9.81;
const double alpha = 40.0 * M_PI / 180.0;
}  // namespace

TEST(Incline, SlidingBlockFollowsTheClosedFormWithinTwoPercent) {
    auto run = mcdda::test::run_example("incline-sliding.json");
    ASSERT_TRUE(run.simulation);
    ASSERT_GE(run.simulation->state().time, 1.0 - 1e-9);
    const double phi = 20.0 * M_PI / 180.0;
    const double expected = 0.5 * g * (std::sin(alpha) - std::cos(alpha) * std::tan(phi)) * 1.0 * 1.0;
    const Point2 u = run.history.at(1.0, 0);
    const double along_slope = -(u.x * std::cos(alpha) + u.y * std::sin(alpha));  // down the slope
    const double across = -u.x * std::sin(alpha) + u.y * std::cos(alpha);
    std::cout << "incline (φ = 20°): s(1 s) = " << along_slope << " m, closed form " << expected << " m, error "
              << 100.0 * (along_slope - expected) / expected << " %; normal displacement " << across << " m\n";
    EXPECT_NEAR(expected, 1.785, 0.001);
    EXPECT_NEAR(along_slope, expected, 0.02 * expected);
    EXPECT_LT(std::fabs(across), 0.01);  // it slides along the plane, neither sinks nor lifts off
}

TEST(Incline, BlockStaysWhenFrictionExceedsTheSlope) {
    auto run = mcdda::test::run_example("incline-stable.json");
    ASSERT_TRUE(run.simulation);
    ASSERT_GE(run.simulation->state().time, 1.0 - 1e-9);
    const Point2 u = run.history.at(1.0, 0);
    const double moved = std::hypot(u.x, u.y);
    std::cout << "incline (φ = 40.1°): the block moved " << moved * 1000.0 << " mm in 1 s\n";
    EXPECT_LT(moved, 1e-3);
}

// The same block in a static analysis: whether it stands must not depend on how many steps
// gravity is applied in (static DDA carries part of each increment by its mass term; each step
// relaxes to equilibrium at its loads). The equilibrium verdict uses the run's own limit,
// analysis.equilibrium_ratio.
TEST(Incline, StaticVerdictDoesNotDependOnTheStepCount) {
    double reference_uy = 0.0;
    for (int steps : {3, 5, 10, 100})
        for (int phi : {44, 45, 46, 48}) {
            const std::vector<std::string> o = {"/analysis/type=\"static\"", "/analysis/steps=" + std::to_string(steps),
                                                "/joint_materials/0/friction_angle=" + std::to_string(phi)};
            auto run = mcdda::test::run_example("incline-stable.json", o);
            ASSERT_TRUE(run.simulation);
            const SimulationState& s = run.simulation->state();
            const double uy = run.history.points.back()[0].y;
            std::cout << steps << " steps, φj = " << phi << "°: unbalanced-force ratio " << s.unbalanced_ratio
                      << ", block uy " << uy * 1e3 << " mm\n";
            EXPECT_EQ(s.step, steps);
            EXPECT_LT(s.unbalanced_ratio, run.simulation->analysis().equilibrium_ratio) << steps << " steps, " << phi;
            // It settles elastically where it stands (0.065 mm): the same for every step count.
            if (reference_uy == 0.0) reference_uy = uy;
            EXPECT_LT(uy, 0.0);
            EXPECT_NEAR(uy, reference_uy, 0.02 * std::fabs(reference_uy)) << steps << " steps, " << phi;
        }
}

// And a block that must slide is out of balance by the share of its weight friction cannot
// hold, whatever the step count: (sin 40° − cos 40° tan φj) of it.
TEST(Incline, StaticSlidingBlockIsUnbalancedAtEveryStepCount) {
    for (int steps : {3, 10})
        for (int phi : {30, 38}) {
            const std::vector<std::string> o = {"/analysis/type=\"static\"", "/analysis/steps=" + std::to_string(steps),
                                                "/joint_materials/0/friction_angle=" + std::to_string(phi)};
            auto run = mcdda::test::run_example("incline-stable.json", o);
            ASSERT_TRUE(run.simulation);
            const double ratio = run.simulation->state().unbalanced_ratio;
            std::cout << steps << " steps, φj = " << phi << "°: unbalanced-force ratio " << ratio << "\n";
            EXPECT_GT(ratio, run.simulation->analysis().equilibrium_ratio) << steps << " steps, " << phi;
        }
}

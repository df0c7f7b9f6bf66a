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

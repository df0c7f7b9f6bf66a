// Lavarak pilot cavern (paper's Table 2; the cavern's shape is assumed, see the example): the
// plastic zone reaches 4–8 m into wall and roof, and the plastic run's crown moves more than the
// same model run elastic.

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

namespace {

/// Depth of the yielded zone above the crown (roof: within 1 m of the symmetry axis) and beside
/// the wall (at mid-height, within 1 m of y = −2.5), from the yielded elements' centroids.
std::pair<double, double> plastic_depths(const Simulation& s) {
    double roof = 0.0, wall = 0.0;
    for (std::size_t e = 0; e < s.mesh().triangles.size(); ++e) {
        if (s.state().plastic_state[e] == 0) continue;
        const auto& t = s.mesh().triangles[e];
        const auto& n = s.mesh().nodes;
        const double x = (n[t[0]].x + n[t[1]].x + n[t[2]].x) / 3, y = (n[t[0]].y + n[t[1]].y + n[t[2]].y) / 3;
        if (x < 1.0 && y > 5.0) roof = std::max(roof, y - 5.0);
        if (std::fabs(y + 2.5) < 1.0 && x > 5.0) wall = std::max(wall, x - 5.0);
    }
    return {roof, wall};
}

}  // namespace

TEST(Lavarak, PlasticZoneDepthAndCrownDisplacement) {
    auto plastic = mcdda::test::run_example("lavarak-cavern.json");
    auto elastic = mcdda::test::run_example("lavarak-cavern.json", {"/analysis/plasticity=false"});
    ASSERT_TRUE(plastic.simulation && elastic.simulation);
    const auto [roof, wall] = plastic_depths(*plastic.simulation);
    const double crown_plastic = -plastic.history.points.back()[0].y;
    const double crown_elastic = -elastic.history.points.back()[0].y;
    std::cout << "Lavarak: plastic zone " << roof << " m into the roof, " << wall << " m into the wall; crown moves "
              << crown_plastic * 1000 << " mm (elastic " << crown_elastic * 1000 << " mm)\n";
    std::cout << "extensometer (m above the crown: plastic, elastic mm):";
    const double heights[] = {0, 1.5, 3, 5, 7};
    for (int k = 0; k < 5; ++k)
        std::cout << " " << heights[k] << ": " << -plastic.history.points.back()[k].y * 1000 << ", "
                  << -elastic.history.points.back()[k].y * 1000 << ";";
    std::cout << "\n";
    EXPECT_GE(roof, 4.0);
    EXPECT_LE(roof, 8.0);
    EXPECT_GE(wall, 4.0);
    EXPECT_LE(wall, 8.0);
    EXPECT_GT(crown_plastic, 1.5 * crown_elastic);
}

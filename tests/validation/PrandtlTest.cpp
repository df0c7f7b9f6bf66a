// Rigid smooth strip footing on weightless undrained clay (the paper's parameters; docs/examples.md):
// the pressure grows 1 kPa per step until the soil fails; Prandtl: q/cu = 2 + π = 5.14.

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

TEST(Prandtl, BearingFailureNearTwoPlusPi) {
    const Preprocessed p = preprocess_file(std::string(MCDDA_EXAMPLES_DIR) + "/prandtl-footing.json", {});
    ASSERT_TRUE(p.ok);
    Simulation s(p);
    const double cu = 100e3;
    std::vector<double> load, settlement;  // q/cu and settlement of the footing centre (m)
    bool collapsed = false;
    try {
        while (s.state().step < p.model.analysis.steps) {
            s.advance();
            load.push_back(s.load_magnitudes()[0].second / cu);
            const int node = s.boundary_conditions().measurement_nodes[0];
            settlement.push_back(-s.state().displacement[2 * node + 1]);
        }
    } catch (const PlasticCollapse& e) {
        collapsed = true;
        std::cout << "collapse: " << e.what() << "\n";
    }
    ASSERT_TRUE(collapsed) << "no bearing failure up to q/cu = " << load.back();
    ASSERT_GT(load.size(), 100u);
    const double failure = load.back();  // the last load carried
    const double prandtl = 2.0 + M_PI;
    // The load–settlement curve turns over: the last 10 kPa cost far more settlement than the first.
    const double initial_rate = (settlement[9] - settlement[0]) / (load[9] - load[0]);
    const std::size_t n = load.size();
    const double final_rate = (settlement[n - 1] - settlement[n - 11]) / (load[n - 1] - load[n - 11]);
    std::cout << "Prandtl footing: failure at q/cu = " << failure << " (2 + π = " << prandtl << ", error "
              << 100.0 * (failure - prandtl) / prandtl << " %); settlement " << settlement.back() * 1000
              << " mm; settlement per unit q/cu near failure " << final_rate / initial_rate
              << " times the initial one\n";
    EXPECT_NEAR(failure, prandtl, 0.05 * prandtl);
    EXPECT_GT(final_rate, 5.0 * initial_rate);
}

// Kirsch: elastic plate with a circular hole under biaxial far-field stress.
// Hoop stress at the wall, compression positive: (σH + σh) − 2(σH − σh)cos 2θ.

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>

using namespace mcdda;

namespace {

/// Hoop stress (compression positive) at the wall on the ray at angle `theta`, extrapolated from
/// the elements near the ray by a least-squares fit of Kirsch's radial form A + B/r² + C/r⁴.
double wall_hoop_stress(const Simulation& s, double theta) {
    std::vector<double> r_values, hoop;
    for (int e = 0; e < static_cast<int>(s.mesh().triangles.size()); ++e) {
        const Point2 c = mcdda::test::centroid(s, e);
        const double r = std::hypot(c.x, c.y);
        const double angle = std::atan2(c.y, c.x);
        if (r > 2.0 || std::fabs(angle - theta) > 4.0 * M_PI / 180.0) continue;
        const Eigen::Vector3d& sigma = s.state().stress[e];
        // σθθ = σxx sin²θ + σyy cos²θ − 2 τxy sinθ cosθ at the element's own angle; tension positive.
        const double sn = std::sin(angle), cs = std::cos(angle);
        hoop.push_back(-(sigma[0] * sn * sn + sigma[1] * cs * cs - 2.0 * sigma[2] * sn * cs));
        r_values.push_back(r);
    }
    EXPECT_GE(hoop.size(), 10u);
    Eigen::MatrixXd a(hoop.size(), 3);
    Eigen::VectorXd b(hoop.size());
    for (std::size_t i = 0; i < hoop.size(); ++i) {
        a(i, 0) = 1.0;
        a(i, 1) = 1.0 / std::pow(r_values[i], 2);
        a(i, 2) = 1.0 / std::pow(r_values[i], 4);
        b[i] = hoop[i];
    }
    const Eigen::Vector3d fit = a.colPivHouseholderQr().solve(b);
    return fit.sum();  // at r = a = 1
}

}  // namespace

TEST(Kirsch, HoopStressAtTheWallWithinFivePercent) {
    auto run = mcdda::test::run_example("kirsch.json");
    ASSERT_TRUE(run.simulation);
    const double sh = 10e6, sv = 5e6;  // far field: horizontal, vertical (compression)
    const double expected_crown = 3 * sh - sv;   // θ = 90°: 25 MPa
    const double expected_springline = 3 * sv - sh;  // θ = 0°: 5 MPa
    const double crown = wall_hoop_stress(*run.simulation, M_PI / 2);
    const double springline = wall_hoop_stress(*run.simulation, 0.0);
    std::cout << "Kirsch hoop stress at the wall: 90° " << crown / 1e6 << " MPa (closed form " << expected_crown / 1e6
              << ", error " << 100 * (crown - expected_crown) / expected_crown << " %), 0° " << springline / 1e6
              << " MPa (closed form " << expected_springline / 1e6 << ", error "
              << 100 * (springline - expected_springline) / expected_springline << " %)\n";
    EXPECT_NEAR(crown, expected_crown, 0.05 * expected_crown);
    EXPECT_NEAR(springline, expected_springline, 0.05 * expected_springline);
}

// Direct shear of a plane of coplanar non-persistent joints (examples/jennings-direct-shear.json):
// the joints end in the rock, so they are cracks inside one block, and the rock bridges between
// them are Mohr–Coulomb with ψ = φ. Held normal stress σn = 1 MPa, the upper half pushed
// sideways. Jennings (1970): the peak mean shear stress on the plane is
// k(cj + σn tan φj) + (1 − k)(cr + σn tan φr) for joint persistence k.

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

using namespace mcdda;

namespace {

constexpr double length = 10.0;  // m, the shear plane
constexpr double normal_stress = 1e6, rock_cohesion = 1e6, joint_cohesion = 0.0;
const double tan_rock = std::tan(35.0 * M_PI / 180.0), tan_joint = std::tan(35.0 * M_PI / 180.0);

/// Five joints of total length k · 10 m centred on 1, 3, …, 9 m along y = 2 m.
std::string joints(double k) {
    std::ostringstream out;
    out.precision(17);
    out << "/joints=[";
    for (int i = 0; i < 5; ++i) {
        const double centre = 2.0 * i + 1.0, half = k;  // segment length 2k
        out << (i ? "," : "") << R"({"name": "joint )" << i + 1 << R"(", "joint_material": "joint", "points": [[)"
            << centre - half << ",2],[" << centre + half << ",2]]}";
    }
    out << "]";
    return out.str();
}

/// The peak over the steps of the push's reaction over the plane's length (Pa). The upper half
/// is held only by the plane and the push (its top carries the normal pressure, its right side
/// is free), so that reaction is the shear force on the plane.
double peak_shear_stress(double k) {
    const Preprocessed p =
        preprocess_file(std::string(MCDDA_EXAMPLES_DIR) + "/jennings-direct-shear.json", {joints(k)});
    EXPECT_TRUE(p.ok);
    if (!p.ok) return 0.0;
    Simulation s(p);
    constexpr int push = 3;  // the fourth roller
    double peak = 0.0;
    while (s.state().step < p.model.analysis.steps) {
        s.advance();
        peak = std::max(peak, std::fabs(s.state().roller_reactions.at(push).x) / length);
    }
    return peak;
}

void expect_jennings(double k) {
    const double jennings = k * (joint_cohesion + normal_stress * tan_joint) + (1 - k) * (rock_cohesion + normal_stress * tan_rock);
    const double peak = peak_shear_stress(k);
    std::cout << "Jennings direct shear, k = " << k << ": peak " << peak / 1e6 << " MPa, Jennings " << jennings / 1e6
              << " MPa (" << 100 * (peak / jennings - 1) << " %)\n";
    EXPECT_NEAR(peak, jennings, 0.05 * jennings);
}

}  // namespace

TEST(JenningsShear, PersistenceHalfPeakWithinFivePercent) { expect_jennings(0.5); }

TEST(JenningsShear, PersistenceFourFifthsPeakWithinFivePercent) { expect_jennings(0.8); }

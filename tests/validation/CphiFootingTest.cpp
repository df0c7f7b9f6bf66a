// Rigid smooth strip footing on c–φ soil (docs/examples.md): c = 10 kPa, φ = ψ = 20°, a 20 kPa
// surcharge beside the footing. Weightless, Prandtl–Reissner gives the collapse pressure exactly:
// c·Nc + q0·Nq with Nq = e^(π tan φ) tan²(45° + φ/2) and Nc = (Nq − 1) cot φ. With soil weight
// (γ = 16 kN/m³) no exact value exists; Terzaghi's superposition adds ½γB·Nγ with the published
// Nγ(20°) = 1.6 (exact, smooth) … 5.4 (Vesić), and the run must report a collapse bracket there
// (no load carried by inertia).

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace {

const double phi = 20.0 * M_PI / 180.0;
const double Nq = std::exp(M_PI * std::tan(phi)) * std::pow(std::tan(M_PI / 4 + phi / 2), 2);
const double Nc = (Nq - 1.0) / std::tan(phi);
constexpr double c = 10e3, q0 = 20e3, unit_weight = 16e3, B = 4.0;

void expect_bracket(const mcdda::test::CollapseRun& r) {
    ASSERT_TRUE(r.collapsed);
    EXPECT_LE(r.carried, r.not_carried);
    EXPECT_LT(r.not_carried - r.carried, 0.002 * r.carried);
    // Settlement never decreases while the load rises.
    for (std::size_t i = 1; i < r.settlement.size(); ++i) EXPECT_GE(r.settlement[i], r.settlement[i - 1]);
}

}  // namespace

TEST(CphiFooting, WeightlessCollapseWithinThreePercentOfPrandtlReissner) {
    const double exact = c * Nc + q0 * Nq;
    EXPECT_NEAR(exact, 276.3e3, 0.1e3);
    const auto r = mcdda::test::run_to_collapse("cphi-footing.json");
    expect_bracket(r);
    std::cout << "c-φ footing, weightless: collapse between " << r.carried / 1e3 << " and " << r.not_carried / 1e3
              << " kPa (Prandtl–Reissner " << exact / 1e3 << " kPa, error " << 100 * (r.carried / exact - 1)
              << " %)\n";
    EXPECT_NEAR(r.carried, exact, 0.03 * exact);  // acceptance: 3 %
}

TEST(CphiFooting, WithSoilWeightCollapsesWithinTerzaghiRange) {
    const double low = c * Nc + q0 * Nq + 0.5 * unit_weight * B * 1.6, high = c * Nc + q0 * Nq + 0.5 * unit_weight * B * 5.4;
    const auto r = mcdda::test::run_to_collapse("cphi-footing-weight.json");
    expect_bracket(r);
    std::cout << "c-φ footing with weight: collapse between " << r.carried / 1e3 << " and " << r.not_carried / 1e3
              << " kPa (Terzaghi superposition " << low / 1e3 << " … " << high / 1e3 << " kPa)\n";
    EXPECT_GT(r.carried, low);
    EXPECT_LT(r.carried, high);
}

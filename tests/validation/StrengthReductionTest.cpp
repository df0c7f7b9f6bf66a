// The factor of safety by strength reduction (run/StrengthReduction.hpp) against closed forms,
// and its independence of the numerical settings.
//
// Weightless undrained clay (cu = 100 kPa, φ = ψ = 0) under a flexible smooth strip footing
// pressure held at q = 400 kPa: the clay stands while cu/F ≥ q/(2 + π), so
// F = (2 + π) cu / q = 1.2854 (Prandtl). examples/prandtl-flexible-footing.json, 330 six-node
// elements, refined at the footing's edge.

#include "RunModel.hpp"

#include "Preprocess.hpp"
#include "material/HoekBrown.hpp"
#include "material/MaterialLaws.hpp"
#include "material/StrengthReduction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace mcdda;

namespace {

constexpr double pi = 3.14159265358979323846;

/// The Prandtl footing as a strength reduction analysis under a held 400 kPa.
std::vector<std::string> prandtl_held(std::vector<std::string> more = {}) {
    std::vector<std::string> o = {"/analysis/type=\"strength_reduction\"", "/analysis/steps=1",
                                  "/edge_pressures/0/pressure=400000", "/load_tables/0/extrapolate=false"};
    o.insert(o.end(), more.begin(), more.end());
    return o;
}

const double prandtl_factor = (2.0 + pi) * 100e3 / 400e3;

}  // namespace

TEST(StrengthReduction, PrandtlFootingUnderAHeldLoad) {
    const FactorOfSafety f = test::strength_reduction_of("prandtl-flexible-footing.json", prandtl_held());
    ASSERT_TRUE(f.found);
    // The bracket is within the default tolerance (0.5 %) and the factor within 1 % of Prandtl's.
    EXPECT_LE(f.not_converged - f.converged, 0.005 * f.converged * (1 + 1e-9));
    EXPECT_NEAR(f.value, prandtl_factor, 0.01 * prandtl_factor);
    EXPECT_EQ(f.trials, static_cast<int>(f.table.size()));
    for (const StrengthTrial& t : f.table) {
        if (t.factor <= f.converged) EXPECT_TRUE(t.stands) << "F = " << t.factor << " below the factor did not stand";
        if (t.factor >= f.not_converged) EXPECT_FALSE(t.stands) << "F = " << t.factor << " above the factor stood";
    }
}

TEST(StrengthReduction, PrandtlFactorDoesNotDependOnTheSettings) {
    const double reference = test::strength_reduction_of("prandtl-flexible-footing.json", prandtl_held()).value;
    ASSERT_GT(reference, 0.0);
    const std::vector<std::pair<std::string, std::vector<std::string>>> variants = {
        {"load in 10 steps", {"/analysis/steps=10", "/load_tables/0/points=[[0,0],[10,1]]"}},
        {"iteration cap x4", {"/analysis/plastic_iterations=2000"}},
        {"search tolerance / 4", {"/analysis/factor_tolerance=0.00125"}},
        {"equilibrium tolerance / 10", {"/analysis/plastic_tolerance=1e-5"}},
    };
    for (const auto& [name, more] : variants) {
        const FactorOfSafety f = test::strength_reduction_of("prandtl-flexible-footing.json", prandtl_held(more));
        EXPECT_TRUE(f.found) << name;
        EXPECT_NEAR(f.value, reference, 0.01 * reference) << name;
    }
}

// A rigid wedge on a planar joint (examples/slope-wedge.json, rock elastic and not reduced):
// the joint from (12, 3) on the face to (32.78, 15) on the crest dips α = 30°, L = 24.0 m; the
// wedge above it, (12, 3)–(32.78, 15)–(20, 15), has 76.71 m² and W = 25 kN/m³ × 76.71 m² =
// 1.918 MN/m. Limit equilibrium: F = (c L + W cos α tan φ) / (W sin α).
namespace {

double wedge_factor(double cohesion, double friction_degrees) {
    const double w = 25e3 * 76.70765815, length = 24.0, alpha = pi / 6;
    return (cohesion * length + w * std::cos(alpha) * std::tan(friction_degrees * pi / 180)) / (w * std::sin(alpha));
}

std::vector<std::string> wedge_search(std::vector<std::string> more = {}) {
    std::vector<std::string> o = {"/analysis/type=\"strength_reduction\"", "/analysis/steps=1"};
    o.insert(o.end(), more.begin(), more.end());
    return o;
}

}  // namespace

TEST(StrengthReduction, PlanarWedgeSlidesAtTheLimitEquilibriumFactor) {
    // Without cohesion F = tan 20° / tan 30° = 0.630: a factor below 1 is found, not an error.
    const FactorOfSafety dry = test::strength_reduction_of("slope-wedge.json", wedge_search());
    ASSERT_TRUE(dry.found);
    EXPECT_NEAR(dry.value, wedge_factor(0, 20), 0.01 * wedge_factor(0, 20));
    EXPECT_LT(dry.value, 1.0);
    // With a joint cohesion of 10 kPa: (240 kN + 604.5 kN) / 958.8 kN = 0.881.
    const FactorOfSafety cohesive = test::strength_reduction_of("slope-wedge.json", wedge_search({"/joint_materials/0/cohesion=10000"}));
    ASSERT_TRUE(cohesive.found);
    EXPECT_NEAR(cohesive.value, wedge_factor(10e3, 20), 0.01 * wedge_factor(10e3, 20));
}

TEST(StrengthReduction, WedgeFactorDoesNotDependOnTheSettings) {
    const double expected = wedge_factor(0, 20);
    const std::vector<std::pair<std::string, std::vector<std::string>>> variants = {
        {"10 steps", {"/analysis/steps=10"}},
        {"contact iteration cap x4", {"/analysis/open_close_iterations=40"}},
        {"search tolerance / 4", {"/analysis/factor_tolerance=0.00125"}},
        {"equilibrium tolerance / 10", {"/analysis/plastic_tolerance=1e-5"}},
        {"finer mesh", {"/mesh/size=0.75"}},
    };
    for (const auto& [name, more] : variants) {
        const FactorOfSafety f = test::strength_reduction_of("slope-wedge.json", wedge_search(more));
        EXPECT_TRUE(f.found) << name;
        EXPECT_NEAR(f.value, expected, 0.01 * expected) << name;
    }
}

TEST(StrengthReduction, SafetyStageOfAStagedTunnelReportsItsFactor) {
    // examples/jointed-tunnel-safety.json: the jointed tunnel built in four stages, then a safety
    // stage. The finished tunnel stands with its strengths (F = 1 stands), and dividing them by
    // 5 is too much for the jointed granite around a 6 m opening.
    const FactorOfSafety f = test::strength_reduction_of("jointed-tunnel-safety.json", {});
    ASSERT_TRUE(f.found);
    EXPECT_GT(f.value, 1.0);
    EXPECT_LT(f.value, 5.0);
    EXPECT_LE(f.not_converged - f.converged, 0.005 * f.converged * (1 + 1e-9));
    ASSERT_FALSE(f.table.empty());
    EXPECT_DOUBLE_EQ(f.table.front().factor, 1.0);
    EXPECT_TRUE(f.table.front().stands);
}

TEST(StrengthReduction, ReducesCohesionFrictionAndTensionOfWhatIsReduced) {
    Material m;
    m.parameters["cohesion"] = 10e3;
    m.parameters["friction_angle"] = 30 * pi / 180;
    m.parameters["dilation_angle"] = 30 * pi / 180;
    m.parameters["tensile_strength"] = 5e3;
    const Material r = reduced_strength(m, 2.0, AnalysisSettings::NonAssociatedFlow::Davis);  // ψ = φ: no β
    EXPECT_DOUBLE_EQ(r.parameter("cohesion"), 5e3);
    EXPECT_NEAR(std::tan(r.parameter("friction_angle")), std::tan(m.parameter("friction_angle")) / 2.0, 1e-14);
    EXPECT_DOUBLE_EQ(r.parameter("tensile_strength"), 2.5e3);
    EXPECT_DOUBLE_EQ(r.parameter("dilation_angle"), r.parameter("friction_angle"));  // ψ ≤ reduced φ
    m.reduce = false;
    EXPECT_DOUBLE_EQ(reduced_strength(m, 2.0, AnalysisSettings::NonAssociatedFlow::Davis).parameter("cohesion"), 10e3);
    JointMaterial j;
    j.cohesion = 1e3;
    j.friction_angle = 20 * pi / 180;
    const JointMaterial rj = reduced_strength(j, 0.5);  // factors below 1 strengthen
    EXPECT_DOUBLE_EQ(rj.cohesion, 2e3);
    EXPECT_NEAR(std::tan(rj.friction_angle), 2.0 * std::tan(j.friction_angle), 1e-14);
}

TEST(StrengthReduction, DavisLowersNonAssociatedStrengthsAndMakesTheFlowAssociated) {
    Material m;
    m.parameters["cohesion"] = 10e3;
    m.parameters["friction_angle"] = 30 * pi / 180;
    m.parameters["dilation_angle"] = 0.0;
    m.parameters["tensile_strength"] = 5e3;
    const Material r = reduced_strength(m, 2.0, AnalysisSettings::NonAssociatedFlow::Davis);
    // Reduced: tan φ_F = tan 30° / 2, so φ_F = 16.10°; with ψ = 0, β = cos φ_F = 0.96077.
    const double phi_f = std::atan(std::tan(m.parameter("friction_angle")) / 2.0);
    EXPECT_NEAR(davis_factor(phi_f, 0.0), 0.96077, 1e-5);
    EXPECT_NEAR(r.parameter("cohesion"), 0.96077 * 5e3, 0.1);
    EXPECT_NEAR(std::tan(r.parameter("friction_angle")), 0.96077 * std::tan(phi_f), 1e-5);
    EXPECT_DOUBLE_EQ(r.parameter("dilation_angle"), r.parameter("friction_angle"));  // associated
    EXPECT_DOUBLE_EQ(r.parameter("tensile_strength"), 2.5e3);          // the cut-off flows associated already
    // Associated materials, and the law solved directly, are not changed.
    m.parameters["dilation_angle"] = m.parameter("friction_angle");
    EXPECT_DOUBLE_EQ(reduced_strength(m, 2.0, AnalysisSettings::NonAssociatedFlow::Davis).parameter("cohesion"), 5e3);
    m.parameters["dilation_angle"] = 0.0;
    EXPECT_DOUBLE_EQ(reduced_strength(m, 2.0, AnalysisSettings::NonAssociatedFlow::Direct).parameter("cohesion"), 5e3);
    EXPECT_DOUBLE_EQ(reduced_strength(m, 2.0, AnalysisSettings::NonAssociatedFlow::Direct).parameter("dilation_angle"), 0.0);
    EXPECT_DOUBLE_EQ(davis_factor(0.3, 0.3), 1.0);
}

// Hoek–Brown: the reduction divides the deviator the rock mass carries at every confinement by F
// (σci/F and mi/F). Checked on the yield function of the reduced law at four confinements.
TEST(StrengthReduction, HoekBrownDeviatorIsDividedAtEveryConfinement) {
    Material m;
    m.law = "hoek-brown";
    m.young_modulus = 5e9;
    m.poisson_ratio = 0.25;
    m.parameters = {{"uniaxial_strength", 40e6}, {"gsi", 55}, {"mi", 12}, {"disturbance", 0.3}, {"dilation_angle", 0.0}};
    const double F = 1.7;
    const Material r = reduced_strength(m, F, AnalysisSettings::NonAssociatedFlow::Davis);
    EXPECT_DOUBLE_EQ(r.parameter("uniaxial_strength"), 40e6 / F);
    EXPECT_DOUBLE_EQ(r.parameter("gsi"), 55);
    const HoekBrownParameters p = hoek_brown_parameters(55, 12, 0.3);
    const auto reduced = make_constitutive_law(r, true);
    const auto* law = dynamic_cast<const HoekBrown*>(reduced.get());
    ASSERT_TRUE(law);
    for (double confinement : {0.0, 1e6, 5e6, 20e6}) {
        const double deviator = 40e6 * std::pow(p.mb * confinement / 40e6 + p.s, p.a) / F;
        // σ3c = the confinement, σ1c = σ3c + the reduced deviator, σzz between them.
        const PlaneStress at{-confinement, -(confinement + deviator), 0.0, -(confinement + 0.5 * deviator)};
        EXPECT_NEAR(law->yield(at), 0.0, 1e-9 * deviator) << "σ3 = " << confinement;
        const PlaneStress beyond{-confinement, -(confinement + 1.01 * deviator), 0.0, -(confinement + 0.5 * deviator)};
        EXPECT_GT(law->yield(beyond), 0.0);
    }
}

// With GSI = 100 and mi = 0.001 the Hoek–Brown criterion is Tresca's, σ1 − σ3 = σci, to 0.13 %
// under the footing's stresses: the Prandtl footing of clay cu = σci/2 under a held 400 kPa then
// has Prandtl's factor (2 + π) cu/q, as the Mohr–Coulomb clay has (both reductions divide cu by F).
// Its flow (ψ = 0 on a criterion with a hint of friction) is non-associated: on the example's mesh,
// refined at the footing's edge, the elastic iteration of trials that stand stalls at 100–250
// times the tolerance, and the factor came out 8 % low (1.1807) while trials turned Newton with
// the unsymmetric tangent away from that far.
TEST(StrengthReduction, HoekBrownTrescaFootingHasPrandtlsFactor) {
    const FactorOfSafety f = test::strength_reduction_of(
        "prandtl-flexible-footing.json",
        prandtl_held({R"(/materials/0={"name": "clay", "law": "hoek-brown", "young_modulus": 1e7, "poisson_ratio": 0.3,
                       "uniaxial_strength": 200000, "gsi": 100, "mi": 1e-3})"}));
    ASSERT_TRUE(f.found);
    std::cout << "Hoek–Brown (Tresca limit) footing: F = " << f.value << " (Prandtl " << prandtl_factor << ")\n";
    EXPECT_NEAR(f.value, prandtl_factor, 0.01 * prandtl_factor);
}

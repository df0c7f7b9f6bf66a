// Point-level tests of the generalised Hoek–Brown law: the GSI parameters of Hoek, Carranza-Torres
// & Corkum (2002), the exact return onto the curved surface, both edges, the apex and the tension
// cut-off (trials built backwards from a stress on the surface and a flow with known multipliers),
// the original criterion for GSI = 100, the algorithmic tangent against central finite differences
// of the return, continuity of the return across the borders between its regions, and robustness
// far outside the surface.

#include "fem/PlaneStrain.hpp"
#include "material/HoekBrown.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <stdexcept>

using namespace mcdda;

namespace {

constexpr double deg = M_PI / 180.0;
const double E = 10e9, nu = 0.25, sigma_ci = 50e6;
const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
const HoekBrownParameters gsi50 = hoek_brown_parameters(50, 10, 0);  // mb 1.677, s 0.00387, a 0.506
const Eigen::Matrix3d D_principal = lambda * Eigen::Matrix3d::Ones() + 2 * G * Eigen::Matrix3d::Identity();

double k_psi(double psi) { return (1 + std::sin(psi)) / (1 - std::sin(psi)); }

/// The compressive major stress at failure for a compressive minor one (compression positive).
double strength(const HoekBrownParameters& p, double sigma3c) {
    return sigma3c + sigma_ci * std::pow(p.mb * sigma3c / sigma_ci + p.s, p.a);
}

/// A state with in-plane principal stresses a (at θ from x) and b, and σzz = z.
PlaneStress rotated(double a, double b, double theta, double z) {
    const double cc = std::cos(theta), ss = std::sin(theta);
    return {a * cc * cc + b * ss * ss, a * ss * ss + b * cc * cc, (a - b) * cc * ss, z};
}

/// Sorted principal stresses (σ1 ≥ σ2 ≥ σ3) placed in a plane-strain state: slot `out_of_plane`
/// is σzz, the other two in plane at angle θ.
PlaneStress placed(const Eigen::Vector3d& sorted, int out_of_plane, double theta) {
    double in_plane[2];
    int k = 0;
    for (int i = 0; i < 3; ++i)
        if (i != out_of_plane) in_plane[k++] = sorted[i];
    return rotated(in_plane[0], in_plane[1], theta, sorted[out_of_plane]);
}

Eigen::Vector3d principal(const PlaneStress& s) {
    const double centre = 0.5 * (s.xx + s.yy), radius = std::hypot(0.5 * (s.xx - s.yy), s.xy);
    std::array<double, 3> p{centre + radius, centre - radius, s.zz};
    std::sort(p.begin(), p.end(), std::greater<double>());
    return {p[0], p[1], p[2]};
}

/// σ + D Δε in plane strain (Δεzz = 0), engineering shear strain.
PlaneStress add_strain(const PlaneStress& s, const Vector3& de) {
    const double volumetric = de[0] + de[1];
    return {s.xx + lambda * volumetric + 2 * G * de[0], s.yy + lambda * volumetric + 2 * G * de[1], s.xy + G * de[2],
            s.zz + lambda * volumetric};
}

Vector3 in_plane(const PlaneStress& s) { return {s.xx, s.yy, s.xy}; }
Eigen::Vector4d all(const PlaneStress& s) { return {s.xx, s.yy, s.xy, s.zz}; }
double size_of(const PlaneStress& s) { return all(s).cwiseAbs().maxCoeff(); }

/// f at the returned stress relative to the stress scale: the return lands on the surface to 1e-12.
double relative_yield(const HoekBrown& m, const PlaneStress& s) {
    return std::fabs(m.yield(s)) / std::max(size_of(s), sigma_ci);
}

double elastic_norm() { return plane_strain_elasticity(E, nu).cwiseAbs().maxCoeff(); }

/// dσ/dΔε by central differences, step 1e-7 of the trial's strain scale.
Matrix3 finite_difference_tangent(const HoekBrown& m, const PlaneStress& trial) {
    const double h = 1e-7 * std::max(size_of(trial), sigma_ci * gsi50.s) / E;
    Matrix3 C;
    for (int j = 0; j < 3; ++j) {
        const Vector3 de = h * Vector3::Unit(j);
        C.col(j) = (in_plane(m.return_map(add_strain(trial, de)).stress) -
                    in_plane(m.return_map(add_strain(trial, -de)).stress)) / (2 * h);
    }
    return C;
}

/// Returns the trial, checks the expected active surfaces, the tangent against finite differences
/// (1e-5 of ‖D‖) and that the tangent overload returns the same stress as the plain one.
Matrix3 checked_tangent(const HoekBrown& m, const PlaneStress& trial, int active_surfaces) {
    Matrix3 C;
    const ReturnResult r = m.return_map(trial, &C);
    EXPECT_EQ(r.active_surfaces, active_surfaces);
    const ReturnResult plain = m.return_map(trial);
    EXPECT_EQ(r.stress.xx, plain.stress.xx);
    EXPECT_EQ(r.stress.zz, plain.stress.zz);
    const Matrix3 difference = C - finite_difference_tangent(m, trial);
    EXPECT_LT(difference.cwiseAbs().maxCoeff(), 1e-5 * elastic_norm()) << "tangent\n" << C << "\nerror\n" << difference;
    return C;
}

/// A stress on the main surface, sorted: σ3c = `confinement` (compression positive), σ2 a fraction
/// of the way from σ3 to σ1.
Eigen::Vector3d on_surface(const HoekBrownParameters& p, double confinement, double fraction) {
    const double s1 = -confinement, s3 = -strength(p, confinement);
    return {s1, s3 + fraction * (s1 - s3), s3};
}

}  // namespace

TEST(HoekBrown, ParametersFromGsiFollowHoekCarranzaTorresCorkum2002) {
    // GSI 50, mi 10, D 0: mb = 10 e^(−50/28), s = e^(−50/9), a = 1/2 + (e^(−10/3) − e^(−20/3))/6.
    EXPECT_NEAR(gsi50.mb, 1.67677, 1e-5);
    EXPECT_NEAR(gsi50.s, 0.0038659, 1e-7);
    EXPECT_NEAR(gsi50.a, 0.505734, 1e-6);
    EXPECT_NEAR(hoek_brown_tensile_strength(sigma_ci, gsi50.mb, gsi50.s), 115278.6, 0.1);
    // Blast damage D = 0.7 weakens the mass: mb = 10 e^(−50/18.2), s = e^(−50/6.9); a does not change.
    const HoekBrownParameters damaged = hoek_brown_parameters(50, 10, 0.7);
    EXPECT_NEAR(damaged.mb, 0.641037, 1e-6);
    EXPECT_NEAR(damaged.s, 0.000712752, 1e-9);
    EXPECT_EQ(damaged.a, gsi50.a);
    // Intact rock, GSI 100: the original criterion, mb = mi, s = 1, a = 1/2.
    const HoekBrownParameters intact = hoek_brown_parameters(100, 10, 0);
    EXPECT_DOUBLE_EQ(intact.mb, 10.0);
    EXPECT_DOUBLE_EQ(intact.s, 1.0);
    EXPECT_NEAR(intact.a, 0.5, 1e-15);
    // Very poor rock mass: a tends to 2/3.
    EXPECT_NEAR(hoek_brown_parameters(0, 10, 0).a, 0.5 + (1 - std::exp(-20.0 / 3.0)) / 6, 1e-15);
    EXPECT_THROW(hoek_brown_parameters(120, 10, 0), std::invalid_argument);
    EXPECT_THROW(hoek_brown_parameters(50, 0, 0), std::invalid_argument);
    EXPECT_THROW(hoek_brown_parameters(50, 10, 1.5), std::invalid_argument);
}

TEST(HoekBrown, ConstructorChecksParametersAndTheCutOffBelowTheApex) {
    EXPECT_THROW(HoekBrown(E, 0.5, sigma_ci, gsi50, 0, 0), std::invalid_argument);
    EXPECT_THROW(HoekBrown(E, nu, 0, gsi50, 0, 0), std::invalid_argument);
    EXPECT_THROW(HoekBrown(E, nu, sigma_ci, HoekBrownParameters{1, 1, 1.5}, 0, 0), std::invalid_argument);
    EXPECT_THROW(HoekBrown(E, nu, sigma_ci, gsi50, -1 * deg, 0), std::invalid_argument);
    const double apex = hoek_brown_tensile_strength(sigma_ci, gsi50.mb, gsi50.s);
    EXPECT_EQ(HoekBrown(E, nu, sigma_ci, gsi50, 0, 0).tensile_limit(), apex);
    EXPECT_EQ(HoekBrown(E, nu, sigma_ci, gsi50, 0, 2 * apex).tensile_limit(), apex);  // the criterion's own is lower
    EXPECT_EQ(HoekBrown(E, nu, sigma_ci, gsi50, 0, 0.5 * apex).tensile_limit(), 0.5 * apex);
    const HoekBrown m(E, nu, sigma_ci, gsi50, 10 * deg, 0);
    EXPECT_TRUE(m.may_yield());
    EXPECT_FALSE(m.symmetric_tangent());
    EXPECT_EQ(m.elasticity(), plane_strain_elasticity(E, nu));
}

TEST(HoekBrown, InsideTheSurfaceNothingChanges) {
    const HoekBrown m(E, nu, sigma_ci, gsi50, 0, 0);
    // σ3c = 5 MPa carries σ1c up to 25.5 MPa.
    const PlaneStress s = rotated(-6e6, -20e6, 25 * deg, -12e6);
    ASSERT_LT(m.yield(s), 0.0);
    Matrix3 C;
    const ReturnResult r = m.return_map(s, &C);
    EXPECT_FALSE(r.plastic);
    EXPECT_EQ(r.active_surfaces, 0);
    EXPECT_EQ(r.equivalent_plastic_strain, 0.0);
    EXPECT_EQ(all(r.stress), all(s));
    EXPECT_EQ(C, plane_strain_elasticity(E, nu));
}

TEST(HoekBrown, YieldFunctionIsTheCriterionInPrincipalStresses) {
    const HoekBrown m(E, nu, sigma_ci, gsi50, 0, 0);
    // On the surface for any intermediate stress and any placement of σzz.
    for (double confinement : {0.0, 1e6, 10e6, 40e6})
        for (int z = 0; z < 3; ++z) {
            const PlaneStress s = placed(on_surface(gsi50, confinement, 0.3), z, 40 * deg);
            EXPECT_LT(std::fabs(m.yield(s)), 1e-9 * sigma_ci);
        }
    // Unconfined compressive strength σci s^a, and the apex in hydrostatic tension.
    EXPECT_NEAR(m.yield(rotated(0, 0, 0, -sigma_ci * std::pow(gsi50.s, gsi50.a))), 0.0, 1e-6);
    const double apex = m.tensile_limit();
    EXPECT_NEAR(m.yield(rotated(apex, apex, 0, apex)), 0.0, 1e-6);
    EXPECT_GT(m.yield(rotated(1.01 * apex, apex, 0, apex)), 0.0);  // beyond the apex: outside
    EXPECT_GT(m.yield(rotated(-5e6, -5e6, 0, -40e6)), 0.0);
}

TEST(HoekBrown, ReturnsOntoTheMainSurface) {
    // Trials built from a stress on the surface and the flow Δεp = γ (Kψ, 0, −1): the return must
    // give that stress back, with the principal directions kept.
    for (double psi : {0.0, 10.0, 30.0}) {
        const HoekBrown m(E, nu, sigma_ci, gsi50, psi * deg, 0);
        const Eigen::Vector3d flow_direction(k_psi(psi * deg), 0, -1);
        for (double confinement : {0.2e6, 3e6, 20e6})
            for (double gamma : {1e-5, 1e-3}) {
                const Eigen::Vector3d target = on_surface(gsi50, confinement, 0.4);
                const Eigen::Vector3d trial = target + gamma * D_principal * flow_direction;
                for (int z = 0; z < 3; ++z) {
                    const PlaneStress t = placed(trial, z, 35 * deg);
                    const ReturnResult r = m.return_map(t);
                    EXPECT_TRUE(r.plastic);
                    EXPECT_EQ(r.active_surfaces, 1);
                    EXPECT_LT(relative_yield(m, r.stress), 1e-12);
                    EXPECT_LT((principal(r.stress) - target).cwiseAbs().maxCoeff(), 1e-10 * target.cwiseAbs().maxCoeff())
                        << "ψ " << psi << " σ3c " << confinement << " γ " << gamma;
                    EXPECT_NEAR(r.equivalent_plastic_strain, gamma * std::sqrt(2.0 / 3.0) * flow_direction.norm(), 1e-9 * gamma);
                    if (z == 1) {  // σ1, σ3 in plane: the principal direction at 35° is kept
                        EXPECT_NEAR(r.stress.xy / (r.stress.xx - r.stress.yy), t.xy / (t.xx - t.yy), 1e-9);
                    }
                }
            }
    }
}

TEST(HoekBrown, ReturnsOntoBothEdges) {
    // σ1 = σ2 (both least compressive) with flow γA m_A + γB m_B, and σ2 = σ3 with γA m_A + γC m_C.
    for (double psi : {0.0, 20.0}) {
        const double K = k_psi(psi * deg);
        const HoekBrown m(E, nu, sigma_ci, gsi50, psi * deg, 0);
        const Eigen::Vector3d mA(K, 0, -1), mB(0, K, -1), mC(K, -1, 0);
        for (double confinement : {0.5e6, 8e6}) {
            const Eigen::Vector3d upper = on_surface(gsi50, confinement, 1.0);  // σ1 = σ2
            const Eigen::Vector3d lower = on_surface(gsi50, confinement, 0.0);  // σ2 = σ3
            const struct {
                Eigen::Vector3d target, flow;
            } cases[] = {{upper, 2e-4 * mA + 1e-4 * mB}, {upper, 1e-4 * mA + 3e-4 * mB},
                         {lower, 2e-4 * mA + 1e-4 * mC}, {lower, 1e-4 * mA + 3e-4 * mC}};
            for (const auto& k : cases)
                for (int z = 0; z < 3; ++z) {
                    const PlaneStress t = placed(k.target + D_principal * k.flow, z, -20 * deg);
                    const ReturnResult r = m.return_map(t);
                    EXPECT_EQ(r.active_surfaces, 2);
                    EXPECT_LT(relative_yield(m, r.stress), 1e-12);
                    EXPECT_LT((principal(r.stress) - k.target).cwiseAbs().maxCoeff(), 1e-10 * k.target.cwiseAbs().maxCoeff());
                    EXPECT_NEAR(r.equivalent_plastic_strain, std::sqrt(2.0 / 3.0) * k.flow.norm(), 1e-9 * k.flow.norm());
                }
        }
    }
}

TEST(HoekBrown, ReturnsOntoTheApexInHydrostaticTension) {
    for (double psi : {0.0, 30.0}) {
        const HoekBrown m(E, nu, sigma_ci, gsi50, psi * deg, 0);
        const double apex = hoek_brown_tensile_strength(sigma_ci, gsi50.mb, gsi50.s);
        for (const PlaneStress& trial : {rotated(3e6, 2.5e6, 20 * deg, 2.8e6), rotated(0.2e6, 0.2e6, 0, 0.2e6),
                                         rotated(40e6, 1e6, -50 * deg, 25e6)}) {
            Matrix3 C;
            const ReturnResult r = m.return_map(trial, &C);
            EXPECT_EQ(r.active_surfaces, 3);
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(principal(r.stress)[i], apex, 1e-9 * apex);
            EXPECT_EQ(C, Matrix3::Zero());
            EXPECT_GT(r.equivalent_plastic_strain, 0.0);
        }
    }
}

TEST(HoekBrown, TensionCutOffAndItsCorners) {
    // σt = 50 kPa, below the apex (115 kPa): on σ1 = σt the criterion gives σ3 = σ3*.
    const double t = 50e3;
    const double corner = t - sigma_ci * std::pow(gsi50.mb * (hoek_brown_tensile_strength(sigma_ci, gsi50.mb, gsi50.s) - t) / sigma_ci, gsi50.a);
    ASSERT_NEAR(corner, -2.2087e6, 100.0);
    for (double psi : {0.0, 25.0}) {
        const double K = k_psi(psi * deg);
        const HoekBrown m(E, nu, sigma_ci, gsi50, psi * deg, t);
        const Eigen::Vector3d mA(K, 0, -1), mB(0, K, -1), mC(K, -1, 0), e1(1, 0, 0), e2(0, 1, 0), e3(0, 0, 1);
        const struct {
            Eigen::Vector3d target, flow;
            int active;
        } cases[] = {
            {{t, -0.5e6, -1e6}, 1e-4 * e1, 1},                       // the cut-off alone
            {{t, -1e6, corner}, 1e-4 * mA + 1e-4 * e1, 2},           // cut-off and the surface
            {{t, t, -1e6}, 1e-4 * e1 + 0.5e-4 * e2, 2},              // the cut-off's edge σ1 = σ2 = σt
            {{t, t, corner}, 1e-4 * mA + 1e-4 * mB + 1e-4 * e1, 3},  // cut-off edge on the surface's edge
            {{t, corner, corner}, 1e-4 * mA + 1e-4 * mC + 1e-4 * e1, 3},
            {{t, t, t}, 1e-4 * e1 + 1e-4 * e2 + 1e-4 * e3, 3},       // the cut-off's apex
        };
        for (const auto& k : cases)
            for (int z = 0; z < 3; ++z) {
                const PlaneStress trial = placed(k.target + D_principal * k.flow, z, 70 * deg);
                const ReturnResult r = m.return_map(trial);
                EXPECT_EQ(r.active_surfaces, k.active) << "target " << k.target.transpose();
                EXPECT_LT((principal(r.stress) - k.target).cwiseAbs().maxCoeff(), 1e-9 * k.target.cwiseAbs().maxCoeff())
                    << "ψ " << psi << " target " << k.target.transpose() << " returned " << principal(r.stress).transpose();
                EXPECT_LE(m.yield(r.stress), 1e-9 * sigma_ci);
                EXPECT_NEAR(r.equivalent_plastic_strain, std::sqrt(2.0 / 3.0) * k.flow.norm(), 1e-8 * k.flow.norm());
            }
    }
}

TEST(HoekBrown, IntactRockIsTheOriginalCriterion) {
    // GSI = 100, a = 1/2: σ1c = σ3c + √(mi σci σ3c + σci²) (Hoek & Brown 1980), checked directly
    // on returned stresses; and its uniaxial strengths σci and σci(√(mi² + 4) − mi)/2 in tension.
    const double mi = 12;
    const HoekBrownParameters intact = hoek_brown_parameters(100, mi, 0);
    const HoekBrown m(E, nu, sigma_ci, intact, 5 * deg, 0);
    for (const PlaneStress& trial : {rotated(-10e6, -200e6, 10 * deg, -80e6), rotated(-1e6, -90e6, 0, -30e6),
                                     rotated(-30e6, -400e6, 80 * deg, -200e6)}) {
        const ReturnResult r = m.return_map(trial);
        ASSERT_EQ(r.active_surfaces, 1);
        const Eigen::Vector3d p = principal(r.stress);
        const double major = -p[2], minor = -p[0];
        EXPECT_NEAR(major, minor + std::sqrt(mi * sigma_ci * minor + sigma_ci * sigma_ci), 1e-10 * major);
    }
    EXPECT_NEAR(m.yield(rotated(0, 0, 0, -sigma_ci)), 0.0, 1e-10 * sigma_ci);
    const double tensile = sigma_ci * (std::sqrt(mi * mi + 4) - mi) / 2;  // uniaxial: σ3c = −T, σ1c = 0
    EXPECT_NEAR(m.yield(rotated(tensile, 0, 0, 0)), 0.0, 1e-10 * sigma_ci);
}

TEST(HoekBrownTangent, ElasticIsThePlaneStrainMatrix) {
    const HoekBrown m(E, nu, sigma_ci, gsi50, 10 * deg, 0);
    const Matrix3 C = checked_tangent(m, rotated(-6e6, -20e6, 25 * deg, -12e6), 0);
    EXPECT_EQ(C, plane_strain_elasticity(E, nu));
}

TEST(HoekBrownTangent, MainSurfaceAndRotatedStates) {
    for (double psi : {0.0, 10.0, 30.0}) {
        const HoekBrown m(E, nu, sigma_ci, gsi50, psi * deg, 0);
        const Eigen::Vector3d flow(k_psi(psi * deg), 0, -1);
        for (double confinement : {0.3e6, 5e6, 30e6})
            for (int z = 0; z < 3; ++z)
                for (double theta : {0.0, 30.0, -75.0}) {
                    const Eigen::Vector3d trial = on_surface(gsi50, confinement, 0.3) + 2e-4 * D_principal * flow;
                    const Matrix3 C = checked_tangent(m, placed(trial, z, theta * deg), 1);
                    // With σzz intermediate the plastic mode (Kψ, −1) lies in the plane and has no
                    // stiffness; the flow is not associated.
                    if (z == 1) {
                        EXPECT_LT(std::fabs(C.determinant()), 1e-6 * plane_strain_elasticity(E, nu).determinant());
                    }
                    EXPECT_GT((C - C.transpose()).cwiseAbs().maxCoeff(), 1e-4 * elastic_norm());
                }
    }
}

TEST(HoekBrownTangent, Edges) {
    for (double psi : {0.0, 20.0}) {
        const double K = k_psi(psi * deg);
        const HoekBrown m(E, nu, sigma_ci, gsi50, psi * deg, 0);
        const Eigen::Vector3d mA(K, 0, -1), mB(0, K, -1), mC(K, -1, 0);
        for (double confinement : {0.5e6, 8e6})
            for (int z = 0; z < 3; ++z) {
                // Multipliers well apart from 0, so that central differences stay on the edge.
                const Eigen::Vector3d upper = on_surface(gsi50, confinement, 1.0) + D_principal * (2e-4 * mA + 1e-4 * mB);
                const Eigen::Vector3d lower = on_surface(gsi50, confinement, 0.0) + D_principal * (2e-4 * mA + 1e-4 * mC);
                checked_tangent(m, placed(upper, z, 35 * deg), 2);
                checked_tangent(m, placed(lower, z, 35 * deg), 2);
                checked_tangent(m, placed(upper, z, 0.0), 2);
            }
    }
}

TEST(HoekBrownTangent, CutOffCorners) {
    const double t = 50e3;
    const double corner = t - sigma_ci * std::pow(gsi50.mb * (hoek_brown_tensile_strength(sigma_ci, gsi50.mb, gsi50.s) - t) / sigma_ci, gsi50.a);
    for (double psi : {0.0, 25.0}) {
        const double K = k_psi(psi * deg);
        const HoekBrown m(E, nu, sigma_ci, gsi50, psi * deg, t);
        const Eigen::Vector3d mA(K, 0, -1), e1(1, 0, 0), e2(0, 1, 0);
        for (int z = 0; z < 3; ++z) {
            checked_tangent(m, placed(Eigen::Vector3d(t, -0.5e6, -1e6) + D_principal * (1e-4 * e1), z, 20 * deg), 1);
            checked_tangent(m, placed(Eigen::Vector3d(t, -1e6, corner) + D_principal * (1e-4 * mA + 1e-4 * e1), z, 20 * deg), 2);
            checked_tangent(m, placed(Eigen::Vector3d(t, t, -1e6) + D_principal * (1e-4 * e1 + 0.5e-4 * e2), z, 20 * deg), 2);
            const Matrix3 C = checked_tangent(m, placed(Eigen::Vector3d(t, t, t) + D_principal * Eigen::Vector3d(1e-4, 2e-4, 3e-4), z, 20 * deg), 3);
            EXPECT_EQ(C, Matrix3::Zero());
        }
    }
}

TEST(HoekBrownTangent, RandomStatesAgreeWithFiniteDifferences) {
    // Away from the borders between regions (where the return has kinks) the tangent is the
    // derivative: skip states whose perturbed returns change the number of active surfaces.
    std::mt19937 rng(20250207);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto between = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
    int checked = 0, by_size[4] = {0, 0, 0, 0};
    double worst = 0.0;
    for (double psi : {0.0, 15.0})
        for (double tensile : {0.0, 60e3}) {
            const HoekBrown m(E, nu, sigma_ci, gsi50, psi * deg, tensile);
            for (int i = 0; i < 600; ++i) {
                // General states, near-hydrostatic ones about the apex (0.115 MPa) and ones with two
                // close principal stresses (edges).
                double p[3];
                const int kind = i % 3;
                if (kind == 0) {
                    for (double& v : p) v = -40e6 * std::pow(unit(rng), 2) + 1e6 * unit(rng);
                } else if (kind == 1) {
                    const double mean = between(-1.5e6, 1e6);
                    for (double& v : p) v = mean + between(-0.5e6, 0.5e6);
                } else {
                    p[0] = -30e6 * std::pow(unit(rng), 2) + 0.5e6 * unit(rng);
                    p[1] = p[0] + between(-0.3e6, 0.3e6);
                    p[2] = -30e6 * std::pow(unit(rng), 2) + 0.5e6 * unit(rng);
                }
                std::shuffle(p, p + 3, rng);
                const PlaneStress trial = rotated(p[0], p[1], M_PI * (unit(rng) - 0.5), p[2]);
                Matrix3 C;
                const ReturnResult r = m.return_map(trial, &C);
                bool smooth = true;
                const double h = 1e-5 * std::max(size_of(trial), sigma_ci * gsi50.s) / E;
                for (int j = 0; j < 3 && smooth; ++j)
                    for (double sign : {-1.0, 1.0})
                        smooth = smooth && m.return_map(add_strain(trial, sign * h * Vector3::Unit(j))).active_surfaces == r.active_surfaces;
                if (!smooth) continue;
                ++checked;
                ++by_size[r.active_surfaces];
                const double error = (C - finite_difference_tangent(m, trial)).cwiseAbs().maxCoeff() / elastic_norm();
                worst = std::max(worst, error);
                EXPECT_LT(error, 1e-5) << "ψ " << psi << " σt " << tensile << " trial " << all(trial).transpose()
                                       << " active " << r.active_surfaces;
            }
        }
    std::printf("%d states checked (elastic %d, 1 surface %d, 2 surfaces %d, 3 surfaces %d), largest tangent error "
                "%.2e of max|D|\n",
                checked, by_size[0], by_size[1], by_size[2], by_size[3], worst);
    EXPECT_GT(checked, 2000);
    for (int k = 0; k < 4; ++k) EXPECT_GT(by_size[k], 50) << "active surfaces " << k;
}

TEST(HoekBrown, ReturnIsContinuousAcrossRegionBorders) {
    // Along random segments of trial stresses: between neighbouring samples the returned stress
    // changes by at most 10 times the trial's change (the return is Lipschitz; 2.8 measured), and
    // wherever the number of active surfaces changes the segment is bisected down to 1e-15 of
    // its length: a jump in the returned stress (a wrongly chosen region) would stay there, a
    // continuous return closes it.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int borders = 0, apex_borders = 0;
    double steepest = 0.0;
    for (double psi : {0.0, 20.0})
        for (double tensile : {0.0, 60e3}) {
            const HoekBrown m(E, nu, sigma_ci, gsi50, psi * deg, tensile);
            for (int line = 0; line < 100; ++line) {
                // Every other segment between states about the apex (0.115 MPa) and the cut-off
                // (0.06 MPa): mean stress −0.3 to 0.8 MPa, spread 0.6 MPa.
                auto random_state = [&] {
                    double p[3];
                    const double mean = -0.3e6 + 1.1e6 * unit(rng);
                    for (double& v : p)
                        v = line % 2 ? mean + 0.6e6 * (unit(rng) - 0.5) : -12e6 * std::pow(unit(rng), 2) + 1.5e6 * unit(rng);
                    return all(rotated(p[0], p[1], M_PI * unit(rng), p[2]));
                };
                const Eigen::Vector4d from = random_state(), to = random_state();
                const double length = (to - from).cwiseAbs().maxCoeff();
                auto at = [&](double u) {
                    const Eigen::Vector4d x = from + u * (to - from);
                    return m.return_map(PlaneStress{x[0], x[1], x[2], x[3]});
                };
                const int samples = 1000;
                ReturnResult previous = at(0.0);
                for (int k = 1; k <= samples; ++k) {
                    const ReturnResult current = at(double(k) / samples);
                    const double ratio = (all(current.stress) - all(previous.stress)).cwiseAbs().maxCoeff() / (length / samples);
                    steepest = std::max(steepest, ratio);
                    EXPECT_LT(ratio, 10.0) << "ψ " << psi << " σt " << tensile << " at u = " << double(k) / samples;
                    if (current.active_surfaces != previous.active_surfaces) {
                        ++borders;
                        if (std::max(current.active_surfaces, previous.active_surfaces) == 3) ++apex_borders;
                        double lo = double(k - 1) / samples, hi = double(k) / samples;
                        for (int b = 0; b < 40; ++b) {
                            const double mid = 0.5 * (lo + hi);
                            (at(mid).active_surfaces == previous.active_surfaces ? lo : hi) = mid;
                        }
                        const double jump = (all(at(hi).stress) - all(at(lo).stress)).cwiseAbs().maxCoeff();
                        EXPECT_LT(jump, 1e-6 * length) << "ψ " << psi << " σt " << tensile << " from "
                                                       << previous.active_surfaces << " to " << current.active_surfaces
                                                       << " at u = " << lo;
                    }
                    previous = current;
                }
            }
        }
    std::printf("%d borders crossed (%d of them to or from the apex), steepest change %.2f\n", borders, apex_borders, steepest);
    EXPECT_GT(borders, 300);
    EXPECT_GT(apex_borders, 50);
}

TEST(HoekBrown, FarOutsideAndDegenerateTrialsStayFiniteAndOnTheSurface) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (double psi : {0.0, 40.0})
        for (double tensile : {0.0, 20e3})
            for (const HoekBrownParameters& p : {gsi50, hoek_brown_parameters(10, 7, 1), HoekBrownParameters{5, 0, 0.6}}) {
                const HoekBrown m(E, nu, sigma_ci, p, psi * deg, tensile);
                for (int i = 0; i < 3000; ++i) {
                    const double scale = std::pow(10.0, 300 * (0.5 + 0.5 * unit(rng)));  // 1 Pa to 1e300 Pa
                    double v[3] = {scale * unit(rng), scale * unit(rng), scale * unit(rng)};
                    if (i % 5 == 0) v[1] = v[0];
                    if (i % 7 == 0) v[2] = v[0] = v[1];                 // hydrostatic
                    if (i % 11 == 0) v[0] = m.tensile_limit();            // σ1 at the apex or cut-off
                    const PlaneStress trial = rotated(v[0], v[1], M_PI * unit(rng), v[2]);
                    Matrix3 C;
                    ReturnResult r;
                    ASSERT_NO_THROW(r = m.return_map(trial, &C));
                    ASSERT_TRUE(all(r.stress).allFinite() && C.allFinite() && std::isfinite(r.equivalent_plastic_strain))
                        << all(trial).transpose();
                    const double f = m.yield(r.stress);
                    if (r.plastic) {
                        EXPECT_LT(std::fabs(f), 1e-9 * std::max(size_of(r.stress), sigma_ci)) << all(trial).transpose();
                    } else {
                        EXPECT_LE(f, m.tolerance());
                    }
                }
            }
}

TEST(HoekBrown, StrainPathOfOneElementStaysOnTheSurface) {
    // One triangle sheared and compressed step by step: every plastic return lands on the surface,
    // and the stress never leaves it.
    const HoekBrown m(E, nu, sigma_ci, gsi50, 5 * deg, 0);
    const Matrix3 D = plane_strain_elasticity(E, nu);
    const TriangleShape shape = triangle_shape({0, 0}, {1, 0}, {0, 1});
    PlaneStress s{-2e6, -2e6, 0, -1e6};
    int plastic_steps = 0;
    for (int step = 0; step < 300; ++step) {
        Vector6 du;
        du << 0, 0, 2e-6, -1e-6, 3e-6, -4e-6;
        const Vector3 ds = D * (shape.B * du);
        const ReturnResult r = m.return_map(PlaneStress{s.xx + ds[0], s.yy + ds[1], s.xy + ds[2], s.zz + lambda * (shape.B * du).head<2>().sum()});
        s = r.stress;
        if (r.plastic) {
            ++plastic_steps;
            EXPECT_LT(relative_yield(m, s), 1e-12) << "step " << step;
        }
        EXPECT_LE(m.yield(s), m.tolerance()) << "step " << step;
    }
    EXPECT_GT(plastic_steps, 100);
}

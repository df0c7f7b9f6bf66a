// Point-level tests of the Mohr–Coulomb return mapping: exact return onto the plane, the edges
// and the apex, the plastic flow direction, the tension cut-off, and a strain path.

#include "fem/PlaneStrain.hpp"
#include "material/MohrCoulomb.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

namespace {

constexpr double deg = M_PI / 180.0;
const double E = 5000e6, nu = 0.2, c = 0.5e6;

PlaneStress principal_state(double a, double b, double z) { return {a, b, 0.0, z}; }

/// |f| relative to the cohesion: the return must land on the surface to 1e-8.
double relative_yield(const MohrCoulomb& m, const PlaneStress& s) { return std::fabs(m.yield(s)) / c; }

}  // namespace

TEST(MohrCoulomb, InsideTheSurfaceNothingChanges) {
    const MohrCoulomb m(E, nu, c, 30 * deg, 0, 0);
    const PlaneStress s{-3e6, -2e6, 0.3e6, -2.5e6};
    const ReturnResult r = m.return_map(s);
    EXPECT_FALSE(r.plastic);
    EXPECT_EQ(r.stress.xx, s.xx);
    EXPECT_EQ(r.stress.xy, s.xy);
}

TEST(MohrCoulomb, TheElasticVerdictIsTheYieldFunctionsEvenJustInsideTheSurface) {
    // Trial stresses scattered about the surface (in-plane shear as large as the normal
    // difference, where the quick bound on Mohr's radius is loosest, and the out-of-plane value
    // anywhere in the order): plastic exactly where the yield function is positive, with and
    // without the tension cut-off, with the tangent asked for or not.
    for (const double tension : {0.0, 0.2e6}) {
        const MohrCoulomb m(E, nu, c, 35 * deg, 5 * deg, tension);
        int elastic = 0, plastic = 0;
        for (int i = 0; i < 20000; ++i) {
            const double a = std::sin(1.7 * i), b = std::sin(2.3 * i + 1.0), z = std::sin(0.7 * i + 2.0);
            const double size = 0.3e6 + 4e6 * (0.5 + 0.5 * std::sin(0.31 * i));
            PlaneStress s{-2e6 + size * a, -2e6 + size * b, size * 0.5 * (a - b) * std::cos(0.9 * i), -2e6 + size * z};
            const double f = m.yield(s);
            if (std::fabs(f) < 1e-6 * c) continue;  // on the surface: rounding decides
            Eigen::Matrix3d tangent;
            const ReturnResult r = m.return_map(s, i % 2 ? &tangent : nullptr);
            ASSERT_EQ(r.plastic, f > 0.0) << i << ": f = " << f;
            (r.plastic ? plastic : elastic) += 1;
        }
        EXPECT_GT(elastic, 1000);
        EXPECT_GT(plastic, 1000);
    }
}

TEST(MohrCoulomb, ReturnsOntoTheMainPlane) {
    const MohrCoulomb m(E, nu, c, 30 * deg, 10 * deg, 0);
    const PlaneStress trial{-1e6, -12e6, 2e6, -6e6};  // σ1, σ2, σ3 well apart
    ASSERT_GT(m.yield(trial), 0.0);
    const ReturnResult r = m.return_map(trial);
    EXPECT_TRUE(r.plastic);
    EXPECT_EQ(r.active_surfaces, 1);
    EXPECT_LT(relative_yield(m, r.stress), 1e-8);
    EXPECT_GT(r.equivalent_plastic_strain, 0.0);
    // The principal directions do not turn: τxy/(σxx − σyy) is kept.
    EXPECT_NEAR(r.stress.xy / (r.stress.xx - r.stress.yy), trial.xy / (trial.xx - trial.yy), 1e-9);
}

TEST(MohrCoulomb, FlowFollowsTheDilationAngle) {
    // Δσ = −D Δεp with Δεp ∝ (1 + sin ψ, 0, −(1 − sin ψ)): the volumetric part of Δσ is
    // −3K Δγ 2 sin ψ, zero for ψ = 0 and negative (compressive correction … dilation) for ψ > 0.
    const PlaneStress trial = principal_state(-1e6, -12e6, -6e6);
    for (double psi : {0.0, 10.0, 30.0}) {
        const MohrCoulomb m(E, nu, c, 30 * deg, psi * deg, 0);
        const ReturnResult r = m.return_map(trial);
        const double mean_change = (r.stress.xx + r.stress.yy + r.stress.zz - trial.xx - trial.yy - trial.zz) / 3;
        if (psi == 0.0) EXPECT_NEAR(mean_change, 0.0, 1e-6 * c);
        else EXPECT_LT(mean_change, 0.0);
        EXPECT_LT(relative_yield(m, r.stress), 1e-8);
        // The intermediate principal stress moves by 2λ sin ψ Δγ only (λ-coupling).
    }
}

TEST(MohrCoulomb, ReturnsOntoTheEdges) {
    const MohrCoulomb m(E, nu, c, 30 * deg, 0, 0);
    // σ1 ≈ σ2 ≫ σ3 (triaxial extension side) and σ1 ≫ σ2 ≈ σ3 (compression side): the main-plane
    // return would break the principal order, so two planes are active.
    for (const PlaneStress trial : {principal_state(-1.0e6, -1.2e6, -20e6), principal_state(-1e6, -20e6, -20.3e6)}) {
        const ReturnResult r = m.return_map(trial);
        EXPECT_TRUE(r.plastic);
        EXPECT_EQ(r.active_surfaces, 2);
        EXPECT_LT(relative_yield(m, r.stress), 1e-8);
        const auto p = MohrCoulomb::principal(r.stress);
        // On an edge two principal stresses coincide.
        EXPECT_LT(std::min(std::fabs(p[0] - p[1]), std::fabs(p[1] - p[2])), 1e-6 * c);
    }
}

TEST(MohrCoulomb, ReturnsOntoTheApex) {
    const double phi = 30 * deg;
    const MohrCoulomb m(E, nu, c, phi, phi, 0);
    const PlaneStress trial = principal_state(3e6, 2.5e6, 2.8e6);  // hydrostatic tension beyond c·cot φ
    const ReturnResult r = m.return_map(trial);
    EXPECT_TRUE(r.plastic);
    EXPECT_EQ(r.active_surfaces, 3);
    const double apex = c / std::tan(phi);
    for (double v : MohrCoulomb::principal(r.stress)) EXPECT_NEAR(v, apex, 1e-8 * c);
    EXPECT_LT(relative_yield(m, r.stress), 1e-8);
}

TEST(MohrCoulomb, TensionCutOff) {
    const MohrCoulomb m(E, nu, c, 30 * deg, 0, 0.2e6);
    const ReturnResult r = m.return_map(principal_state(1e6, -0.5e6, -0.2e6));
    EXPECT_TRUE(r.plastic);
    const auto p = MohrCoulomb::principal(r.stress);
    EXPECT_NEAR(p[0], 0.2e6, 1e-8 * c);
    EXPECT_LE(m.yield(r.stress), 1e-8 * c);
}

TEST(MohrCoulomb, StrainPathOfOneElementStaysOnTheSurface) {
    // One triangle sheared and compressed step by step (prescribed nodal displacements): every
    // plastic return lands on the surface and the stress never leaves it.
    const MohrCoulomb m(E, nu, c, 30 * deg, 5 * deg, 0);
    const Matrix3 D = plane_strain_elasticity(E, nu);
    const TriangleShape shape = triangle_shape({0, 0}, {1, 0}, {0, 1});
    PlaneStress s{-2e6, -2e6, 0, -0.8e6};
    int plastic_steps = 0;
    for (int step = 0; step < 200; ++step) {
        Vector6 du;
        du << 0, 0, 2e-6, -1e-6, 3e-6, -4e-6;  // shear plus vertical compression
        const Vector3 de = shape.B * du;
        const Vector3 ds = D * de;
        const PlaneStress trial{s.xx + ds[0], s.yy + ds[1], s.xy + ds[2], s.zz + nu * (ds[0] + ds[1])};
        const ReturnResult r = m.return_map(trial);
        s = r.stress;
        if (r.plastic) {
            ++plastic_steps;
            EXPECT_LT(relative_yield(m, s), 1e-8) << "step " << step;
        } else {
            EXPECT_LE(m.yield(s), 1e-8 * c) << "step " << step;
        }
    }
    EXPECT_GT(plastic_steps, 50);
}

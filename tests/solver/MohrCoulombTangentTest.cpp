// The algorithmic tangent of the Mohr–Coulomb return mapping against central finite differences
// of the return itself (elastic, plane, both edges, apex, cut-off; ψ = φ and ψ = 0; rotated
// states), and the allocation-free return against the previous implementation on random states.

#include "fem/PlaneStrain.hpp"
#include "material/MohrCoulomb.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace mcdda;

namespace {

constexpr double deg = M_PI / 180.0;
const double E = 5000e6, nu = 0.2, c = 0.5e6;
const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));

/// A state with in-plane principal stresses a (at θ from x) and b, and σzz = z.
PlaneStress rotated(double a, double b, double theta, double z) {
    const double cc = std::cos(theta), ss = std::sin(theta);
    return {a * cc * cc + b * ss * ss, a * ss * ss + b * cc * cc, (a - b) * cc * ss, z};
}

/// σ + D Δε in plane strain (Δεzz = 0), engineering shear strain.
PlaneStress add_strain(const PlaneStress& s, const Vector3& de) {
    const double volumetric = de[0] + de[1];
    return {s.xx + lambda * volumetric + 2 * G * de[0], s.yy + lambda * volumetric + 2 * G * de[1], s.xy + G * de[2],
            s.zz + lambda * volumetric};
}

Vector3 in_plane(const PlaneStress& s) { return {s.xx, s.yy, s.xy}; }

/// dσ/dΔε by central differences, step 1e-7 of the trial's strain scale.
Matrix3 finite_difference_tangent(const MohrCoulomb& m, const PlaneStress& trial) {
    const double size = std::max({std::fabs(trial.xx), std::fabs(trial.yy), std::fabs(trial.xy), std::fabs(trial.zz), c});
    const double h = 1e-7 * size / E;
    Matrix3 C;
    for (int j = 0; j < 3; ++j) {
        const Vector3 de = h * Vector3::Unit(j);
        const Vector3 plus = in_plane(m.return_map(add_strain(trial, de)).stress);
        const Vector3 minus = in_plane(m.return_map(add_strain(trial, -de)).stress);
        C.col(j) = (plus - minus) / (2 * h);
    }
    return C;
}

double elastic_norm() { return plane_strain_elasticity(E, nu).cwiseAbs().maxCoeff(); }

/// Returns the trial, checks the tangent against finite differences (1e-5 of ‖D‖) and the
/// expected number of active surfaces; gives the tangent.
Matrix3 checked_tangent(const MohrCoulomb& m, const PlaneStress& trial, int active_surfaces) {
    Matrix3 C;
    const ReturnResult r = m.return_map(trial, &C);
    EXPECT_EQ(r.active_surfaces, active_surfaces);
    EXPECT_EQ(r.plastic, active_surfaces > 0);
    // The tangent overload returns the same stress as the plain one.
    const ReturnResult plain = m.return_map(trial);
    EXPECT_EQ(r.stress.xx, plain.stress.xx);
    EXPECT_EQ(r.stress.zz, plain.stress.zz);
    const Matrix3 difference = C - finite_difference_tangent(m, trial);
    EXPECT_LT(difference.cwiseAbs().maxCoeff(), 1e-5 * elastic_norm()) << "tangent\n" << C << "\nerror\n" << difference;
    return C;
}

double asymmetry(const Matrix3& C) { return (C - C.transpose()).cwiseAbs().maxCoeff() / elastic_norm(); }

// --- The return mapping as it was before the allocation-free rewrite (commit 2df2356), kept
// verbatim as the reference the new one must reproduce.

struct LegacyPlane {
    Eigen::Vector3d n, m;
    double k;
};

ReturnResult legacy_return_map(double young_modulus, double poisson_ratio, double cohesion, double friction_angle,
                               double dilation_angle, double tensile, const PlaneStress& trial) {
    const double lambda_ = young_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
    const double shear_modulus_ = young_modulus / (2 * (1 + poisson_ratio));
    const double cohesion_ = cohesion, sin_phi_ = std::sin(friction_angle), cos_phi_ = std::cos(friction_angle);
    const double sin_psi_ = std::sin(dilation_angle), tensile_strength_ = tensile;
    const double tolerance_ = 1e-10 * std::max({cohesion, tensile, 1e-6 * young_modulus, 1.0});

    ReturnResult result;
    result.stress = trial;
    const double centre = 0.5 * (trial.xx + trial.yy);
    const double radius = std::hypot(0.5 * (trial.xx - trial.yy), trial.xy);
    const double theta = 0.5 * std::atan2(2 * trial.xy, trial.xx - trial.yy);
    const double values[3] = {centre + radius, centre - radius, trial.zz};  // a, b, z
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int i, int j) { return values[i] > values[j]; });
    const Eigen::Vector3d s(values[order[0]], values[order[1]], values[order[2]]);

    std::vector<LegacyPlane> planes;
    auto mohr_coulomb = [&](int major, int minor) {
        LegacyPlane p;
        p.n.setZero();
        p.m.setZero();
        p.n[major] = 1 + sin_phi_;
        p.n[minor] = -(1 - sin_phi_);
        p.m[major] = 1 + sin_psi_;
        p.m[minor] = -(1 - sin_psi_);
        p.k = 2 * cohesion_ * cos_phi_;
        return p;
    };
    planes.push_back(mohr_coulomb(0, 2));
    planes.push_back(mohr_coulomb(0, 1));
    planes.push_back(mohr_coulomb(1, 2));
    if (tensile_strength_ > 0.0)
        for (int i = 0; i < 3; ++i) {
            LegacyPlane p;
            p.n = p.m = Eigen::Vector3d::Unit(i);
            p.k = tensile_strength_;
            planes.push_back(p);
        }
    auto violation = [&](const Eigen::Vector3d& x) {
        double worst = -1e300;
        for (const LegacyPlane& p : planes) worst = std::max(worst, p.n.dot(x) - p.k);
        return worst;
    };
    if (violation(s) <= tolerance_) return result;  // elastic

    Eigen::Matrix3d D = lambda_ * Eigen::Matrix3d::Ones() + 2 * shear_modulus_ * Eigen::Matrix3d::Identity();
    const int count = static_cast<int>(planes.size());
    std::vector<int> subsets;
    for (int mask = 1; mask < (1 << count); ++mask) subsets.push_back(mask);
    std::stable_sort(subsets.begin(), subsets.end(),
                     [](int a, int b) { return __builtin_popcount(a) < __builtin_popcount(b); });
    const double scale = tolerance_;
    Eigen::Vector3d best = s;
    Eigen::Vector3d best_flow = Eigen::Vector3d::Zero();
    double best_violation = 1e300;
    int best_size = 0;
    for (int mask : subsets) {
        std::vector<int> active;
        for (int i = 0; i < count; ++i)
            if (mask & (1 << i)) active.push_back(i);
        if (active.size() > 3) continue;
        const int m = static_cast<int>(active.size());
        Eigen::MatrixXd A(m, m);
        Eigen::VectorXd f(m);
        for (int r = 0; r < m; ++r) {
            f[r] = planes[active[r]].n.dot(s) - planes[active[r]].k;
            for (int col = 0; col < m; ++col) A(r, col) = planes[active[r]].n.dot(D * planes[active[col]].m);
        }
        Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
        if (!lu.isInvertible()) continue;
        const Eigen::VectorXd gamma = lu.solve(f);
        Eigen::Vector3d flow = Eigen::Vector3d::Zero();
        for (int r = 0; r < m; ++r) flow += gamma[r] * planes[active[r]].m;
        const Eigen::Vector3d x = s - D * flow;
        const double v = violation(x);
        const bool ordered = x[0] >= x[1] - 1e-9 * (std::fabs(x[1]) + scale) && x[1] >= x[2] - 1e-9 * (std::fabs(x[2]) + scale);
        const bool non_negative = (gamma.array() >= -1e-12).all();
        if (non_negative && ordered && v <= 1e-9 * (x.cwiseAbs().maxCoeff() + cohesion_ + scale)) {
            best = x;
            best_flow = flow;
            best_size = m;
            best_violation = v;
            break;
        }
    }
    if (best_violation > 1e299) {
        double apex = sin_phi_ > 1e-12 ? cohesion_ * cos_phi_ / sin_phi_ : s.mean();
        if (tensile_strength_ > 0.0) apex = std::min(apex, tensile_strength_);
        best = Eigen::Vector3d::Constant(apex);
        best_flow = D.inverse() * (s - best);
        best_size = 3;
    }
    double returned[3];
    for (int i = 0; i < 3; ++i) returned[order[i]] = best[i];
    const double c2 = std::cos(theta) * std::cos(theta), s2 = std::sin(theta) * std::sin(theta);
    const double cs = std::sin(theta) * std::cos(theta);
    result.stress.xx = returned[0] * c2 + returned[1] * s2;
    result.stress.yy = returned[0] * s2 + returned[1] * c2;
    result.stress.xy = (returned[0] - returned[1]) * cs;
    result.stress.zz = returned[2];
    result.plastic = true;
    result.active_surfaces = best_size;
    result.equivalent_plastic_strain = std::sqrt(2.0 / 3.0 * best_flow.squaredNorm());
    return result;
}

/// A random trial around the yield surface of cohesion c: general states, near-hydrostatic ones
/// (apex, cut-off) and ones with two close principal stresses (edges), at a random angle.
PlaneStress random_trial(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto between = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
    double p[3];
    const int kind = static_cast<int>(unit(rng) * 3);
    if (kind == 0) {
        for (double& v : p) v = between(-30 * c, 6 * c);
    } else if (kind == 1) {
        const double mean = between(-8 * c, 6 * c);
        for (double& v : p) v = mean + between(-c, c);
    } else {
        const double pair = between(-30 * c, 4 * c);
        p[0] = pair;
        p[1] = pair + between(-0.5 * c, 0.5 * c);
        p[2] = between(-30 * c, 4 * c);
    }
    std::shuffle(p, p + 3, rng);
    return rotated(p[0], p[1], between(-M_PI, M_PI), p[2]);
}

}  // namespace

TEST(MohrCoulombTangent, ElasticIsThePlaneStrainMatrix) {
    const MohrCoulomb m(E, nu, c, 30 * deg, 0, 0);
    const PlaneStress trial{-3e6, -2e6, 0.3e6, -2.5e6};
    const Matrix3 C = checked_tangent(m, trial, 0);
    EXPECT_LT((C - plane_strain_elasticity(E, nu)).cwiseAbs().maxCoeff(), 1e-12 * elastic_norm());
}

TEST(MohrCoulombTangent, MainPlane) {
    const PlaneStress trial{-1e6, -12e6, 2e6, -6e6};
    for (double psi : {0.0, 10.0, 30.0}) {
        const MohrCoulomb m(E, nu, c, 30 * deg, psi * deg, 0);
        const Matrix3 C = checked_tangent(m, trial, 1);
        if (psi == 30.0) EXPECT_LT(asymmetry(C), 1e-12);
        else EXPECT_GT(asymmetry(C), 1e-3);
        // Softer than elastic: a plastic mode has zero stiffness.
        EXPECT_LT(std::fabs(C.determinant()), 1e-6 * plane_strain_elasticity(E, nu).determinant());
    }
}

TEST(MohrCoulombTangent, RotatedStateWithLargeShear) {
    // The principal axes turn with the strain: the spin term carries the shear stiffness.
    const PlaneStress trial{-5e6, -6e6, 6e6, -4e6};
    for (double psi : {0.0, 10.0, 30.0}) {
        const MohrCoulomb m(E, nu, c, 30 * deg, psi * deg, 0);
        const Matrix3 C = checked_tangent(m, trial, 1);
        if (psi == 30.0) EXPECT_LT(asymmetry(C), 1e-12);
    }
}

TEST(MohrCoulombTangent, Edges) {
    // σzz in the coinciding pair on either side (σ1 = σ2: triaxial-compression-like, σ2 = σ3:
    // extension-like), and the in-plane pair coinciding (the returned in-plane stress is then
    // isotropic, so no shear stiffness is left), last exactly (σa = σb: no principal direction).
    struct Case {
        double a, b, z;
    };
    for (const Case& k : {Case{-1.0e6, -20e6, -1.2e6}, Case{-1e6, -20e6, -20.3e6}, Case{-1.0e6, -1.2e6, -20e6},
                          Case{-1e6, -20.3e6, -20e6}, Case{-20e6, -20.3e6, -1e6}, Case{-20e6, -20e6, -1e6}})
        for (double psi : {0.0, 30.0}) {
            const MohrCoulomb m(E, nu, c, 30 * deg, psi * deg, 0);
            const Matrix3 C = checked_tangent(m, rotated(k.a, k.b, 35 * deg, k.z), 2);
            if (psi == 30.0) EXPECT_LT(asymmetry(C), 1e-12);
        }
}

TEST(MohrCoulombTangent, ApexHasNoStiffness) {
    // ψ = φ: all three planes active; ψ = 0: no consistent set, the stress goes to the apex.
    for (double psi : {0.0, 30.0})
        for (const PlaneStress& trial : {rotated(3e6, 2.5e6, 20 * deg, 2.8e6), rotated(40e6, 10e6, -50 * deg, 25e6)}) {
            const MohrCoulomb m(E, nu, c, 30 * deg, psi * deg, 0);
            const Matrix3 C = checked_tangent(m, trial, 3);
            EXPECT_LT(C.cwiseAbs().maxCoeff(), 1e-9 * elastic_norm());
        }
}

TEST(MohrCoulombTangent, TensionCutOff) {
    const double tensile = 0.2e6;
    struct Case {
        PlaneStress trial;
        int active;
    };
    const Case cases[] = {
        {rotated(1e6, -0.5e6, 30 * deg, -0.2e6), 1},         // σ1 on the cut-off
        {rotated(1.52e6, -1.063e6, -70 * deg, -0.222e6), 2},  // cut-off and the main plane
        {rotated(1e6, 0.9e6, 10 * deg, -0.3e6), 2},          // σ1 = σ2 on the cut-off (in-plane pair)
        {rotated(1e6, -0.3e6, 10 * deg, 0.9e6), 2},          // σ1 = σ2 on the cut-off (with σzz)
        {rotated(3e6, 2.5e6, 20 * deg, 2.8e6), 3},           // the cut-off apex
    };
    for (const Case& k : cases)
        for (double psi : {0.0, 30.0}) {
            const MohrCoulomb m(E, nu, c, 30 * deg, psi * deg, tensile);
            const Matrix3 C = checked_tangent(m, k.trial, k.active);
            if (psi == 30.0) EXPECT_LT(asymmetry(C), 1e-12);
        }
}

TEST(MohrCoulombTangent, RandomStatesAgreeWithFiniteDifferences) {
    // Away from the boundaries between active sets (where the return has kinks) the tangent is
    // the derivative: skip states whose perturbed returns change the active set.
    std::mt19937 rng(20240611);
    int checked = 0;
    for (double psi : {0.0, 10.0, 35.0})
        for (double tensile : {0.0, 0.4 * c}) {
            const MohrCoulomb m(E, nu, c, 35 * deg, psi * deg, tensile);
            for (int i = 0; i < 150; ++i) {
                const PlaneStress trial = random_trial(rng);
                Matrix3 C;
                const ReturnResult r = m.return_map(trial, &C);
                bool smooth = true;
                const double h = 1e-5 * std::max({std::fabs(trial.xx), std::fabs(trial.yy), std::fabs(trial.zz), c}) / E;
                for (int j = 0; j < 3 && smooth; ++j)
                    for (double sign : {-1.0, 1.0})
                        smooth = smooth && m.return_map(add_strain(trial, sign * h * Vector3::Unit(j))).active_surfaces ==
                                               r.active_surfaces;
                if (!smooth) continue;
                ++checked;
                const Matrix3 difference = C - finite_difference_tangent(m, trial);
                EXPECT_LT(difference.cwiseAbs().maxCoeff(), 1e-5 * elastic_norm())
                    << "ψ " << psi << " σt " << tensile << " trial " << trial.xx << " " << trial.yy << " " << trial.xy
                    << " " << trial.zz << " active " << r.active_surfaces;
                if (psi == 35.0) EXPECT_LT(asymmetry(C), 1e-10);
            }
        }
    EXPECT_GT(checked, 700);
}

TEST(MohrCoulombTangent, ReturnEqualsThePreviousImplementation) {
    std::mt19937 rng(7);
    int counts[4] = {0, 0, 0, 0};  // elastic, plane, edge, apex
    for (double phi : {0.0, 20.0, 35.0})
        for (double psi_fraction : {0.0, 1.0 / 3.0, 1.0})
            for (double tensile : {0.0, 0.3 * c, 3 * c}) {
                const double psi = psi_fraction * phi;
                const MohrCoulomb m(E, nu, c, phi * deg, psi * deg, tensile);
                for (int i = 0; i < 120; ++i) {
                    const PlaneStress trial = random_trial(rng);
                    const ReturnResult now = m.return_map(trial);
                    const ReturnResult before = legacy_return_map(E, nu, c, phi * deg, psi * deg, tensile, trial);
                    const double size =
                        std::max({std::fabs(trial.xx), std::fabs(trial.yy), std::fabs(trial.xy), std::fabs(trial.zz), c});
                    ASSERT_EQ(now.plastic, before.plastic);
                    ASSERT_EQ(now.active_surfaces, before.active_surfaces);
                    EXPECT_NEAR(now.stress.xx, before.stress.xx, 1e-12 * size);
                    EXPECT_NEAR(now.stress.yy, before.stress.yy, 1e-12 * size);
                    EXPECT_NEAR(now.stress.xy, before.stress.xy, 1e-12 * size);
                    EXPECT_NEAR(now.stress.zz, before.stress.zz, 1e-12 * size);
                    EXPECT_NEAR(now.equivalent_plastic_strain, before.equivalent_plastic_strain,
                                1e-12 * before.equivalent_plastic_strain + 1e-12 * size / E);
                    ++counts[now.active_surfaces];
                }
            }
    for (int k = 0; k < 4; ++k) EXPECT_GT(counts[k], 50) << "active surfaces " << k;
}

#include "material/MohrCoulomb.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mcdda {

namespace {

/// A yield plane in principal-stress space (sorted σ1 ≥ σ2 ≥ σ3): f = n·σ − k, flow along m.
struct Plane {
    Eigen::Vector3d n, m;
    double k;
};

}  // namespace

MohrCoulomb::MohrCoulomb(double E, double nu, double c, double phi, double psi, double tensile)
    : lambda_(E * nu / ((1 + nu) * (1 - 2 * nu))), shear_modulus_(E / (2 * (1 + nu))), cohesion_(c),
      sin_phi_(std::sin(phi)), cos_phi_(std::cos(phi)), sin_psi_(std::sin(psi)), tensile_strength_(tensile),
      tolerance_(1e-10 * std::max({c, tensile, 1e-6 * E, 1.0})) {}

MohrCoulomb::MohrCoulomb(const Material& m)
    : MohrCoulomb(m.young_modulus, m.poisson_ratio, m.cohesion, m.friction_angle, m.dilation_angle,
                  m.tensile_strength) {}

std::array<double, 3> MohrCoulomb::principal(const PlaneStress& s) {
    const double centre = 0.5 * (s.xx + s.yy);
    const double radius = std::hypot(0.5 * (s.xx - s.yy), s.xy);
    std::array<double, 3> p{centre + radius, centre - radius, s.zz};
    std::sort(p.begin(), p.end(), std::greater<double>());
    return p;
}

double MohrCoulomb::yield(const PlaneStress& s) const {
    const auto p = principal(s);
    double f = (p[0] - p[2]) + (p[0] + p[2]) * sin_phi_ - 2 * cohesion_ * cos_phi_;
    if (tensile_strength_ > 0.0) f = std::max(f, p[0] - tensile_strength_);
    return f;
}

ReturnResult MohrCoulomb::return_map(const PlaneStress& trial) const {
    ReturnResult result;
    result.stress = trial;

    // Principal values with the in-plane direction θ of the major in-plane stress a; b is the
    // minor in-plane one, z the out-of-plane one.
    const double centre = 0.5 * (trial.xx + trial.yy);
    const double radius = std::hypot(0.5 * (trial.xx - trial.yy), trial.xy);
    const double theta = 0.5 * std::atan2(2 * trial.xy, trial.xx - trial.yy);
    const double values[3] = {centre + radius, centre - radius, trial.zz};  // a, b, z
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int i, int j) { return values[i] > values[j]; });
    const Eigen::Vector3d s(values[order[0]], values[order[1]], values[order[2]]);

    // The candidate planes: Mohr–Coulomb between each pair (main plane 1–3, edges 1–2 and
    // 2–3) and, with a cut-off, the tension planes.
    std::vector<Plane> planes;
    auto mohr_coulomb = [&](int major, int minor) {
        Plane p;
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
            Plane p;
            p.n = p.m = Eigen::Vector3d::Unit(i);
            p.k = tensile_strength_;
            planes.push_back(p);
        }
    auto violation = [&](const Eigen::Vector3d& x) {
        double worst = -1e300;
        for (const Plane& p : planes) worst = std::max(worst, p.n.dot(x) - p.k);
        return worst;
    };
    if (violation(s) <= tolerance_) return result;  // elastic

    Eigen::Matrix3d D = lambda_ * Eigen::Matrix3d::Ones() + 2 * shear_modulus_ * Eigen::Matrix3d::Identity();
    const int count = static_cast<int>(planes.size());
    // Try active sets by increasing size: the first that returns onto all its planes with
    // non-negative multipliers, keeps the principal order and violates no other plane is the
    // return (plane, edge, apex; the cut-off combinations alike).
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
            for (int c = 0; c < m; ++c) A(r, c) = planes[active[r]].n.dot(D * planes[active[c]].m);
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
        // No active set is consistent: with non-associated flow (ψ < φ) the return to the apex
        // needs negative multipliers on the plane and edges. The stress then goes to the apex
        // itself (de Souza Neto et al., Box 8.5): hydrostatic at c·cot φ, or at the cut-off.
        double apex = sin_phi_ > 1e-12 ? cohesion_ * cos_phi_ / sin_phi_ : s.mean();
        if (tensile_strength_ > 0.0) apex = std::min(apex, tensile_strength_);
        best = Eigen::Vector3d::Constant(apex);
        best_flow = D.inverse() * (s - best);
        best_size = 3;
    }

    // Back to x, y, z: the principal directions do not change (isotropic elasticity).
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

}  // namespace mcdda

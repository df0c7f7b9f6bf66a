#include "material/MohrCoulomb.hpp"

#include "material/Elasticity.hpp"
#include "material/StrengthReduction.hpp"
#include "model/Defaults.hpp"
#include "material/PrincipalFrame.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace mcdda {

namespace {

constexpr int popcount(int mask) {
    int n = 0;
    for (; mask; mask &= mask - 1) ++n;
    return n;
}

/// The active sets (bit i = plane i) of at most 3 of `Planes` planes, by size, then by mask:
/// plane before edge before apex, and the order a stable sort of all masks by size gives.
template <int Planes, int Count>
constexpr std::array<std::uint8_t, Count> make_active_sets() {
    std::array<std::uint8_t, Count> sets{};
    int k = 0;
    for (int size = 1; size <= 3; ++size)
        for (int mask = 1; mask < (1 << Planes); ++mask)
            if (popcount(mask) == size) sets[k++] = static_cast<std::uint8_t>(mask);
    return sets;
}

constexpr auto kThreePlaneSets = make_active_sets<3, 7>();
constexpr auto kSixPlaneSets = make_active_sets<6, 41>();

}  // namespace

MohrCoulomb::MohrCoulomb(double E, double nu, double c, double phi, double psi, double tensile)
    : lambda_(E * nu / ((1 + nu) * (1 - 2 * nu))), shear_modulus_(E / (2 * (1 + nu))), cohesion_(c),
      sin_phi_(std::sin(phi)), cos_phi_(std::cos(phi)), sin_psi_(std::sin(psi)), tensile_strength_(tensile),
      tolerance_(1e-10 * std::max({c, tensile, 1e-6 * E, 1.0})) {
    elasticity_ = lambda_ * Eigen::Matrix3d::Ones() + 2 * shear_modulus_ * Eigen::Matrix3d::Identity();
    plane_strain_ = plane_strain_elasticity(E, nu);  // the same D, bit for bit, as every other law
    compliance_ = elasticity_.inverse();
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
    planes_[0] = mohr_coulomb(0, 2);
    planes_[1] = mohr_coulomb(0, 1);
    planes_[2] = mohr_coulomb(1, 2);
    plane_count_ = 3;
    if (tensile_strength_ > 0.0)
        for (int i = 0; i < 3; ++i) {
            Plane& p = planes_[plane_count_++];
            p.n = p.m = Eigen::Vector3d::Unit(i);
            p.k = tensile_strength_;
        }
    for (int i = 0; i < plane_count_; ++i) planes_[i].Dm = elasticity_ * planes_[i].m;

    // FullPivLU's rank test drops the singular sets: with ψ = 0 (or φ = 0) the three
    // Mohr–Coulomb planes are linearly dependent.
    auto add = [&](auto size, const ActiveSet& set) {
        constexpr int K = decltype(size)::value;
        Eigen::Matrix<double, K, K> A;
        for (int r = 0; r < K; ++r)
            for (int c = 0; c < K; ++c) A(r, c) = planes_[set.planes[r]].n.dot(planes_[set.planes[c]].Dm);
        ActiveSet& stored = sets_[set_count_];
        stored = set;
        stored.inverse.setZero();
        if constexpr (K == 1) {
            if (A(0, 0) == 0.0) return;  // FullPivLU's test for 1×1
            stored.inverse(0, 0) = 1.0 / A(0, 0);
        } else {
            Eigen::FullPivLU<Eigen::Matrix<double, K, K>> lu;
            lu.compute(A);
            if (!lu.isInvertible()) return;
            stored.inverse.template topLeftCorner<K, K>() = lu.solve(Eigen::Matrix<double, K, K>::Identity());
        }
        ++set_count_;
    };
    const std::uint8_t* masks = plane_count_ == 6 ? kSixPlaneSets.data() : kThreePlaneSets.data();
    const int mask_count = static_cast<int>(plane_count_ == 6 ? kSixPlaneSets.size() : kThreePlaneSets.size());
    for (int k = 0; k < mask_count; ++k) {
        ActiveSet set;
        for (int i = 0; i < plane_count_; ++i)
            if (masks[k] & (1 << i)) set.planes[set.size++] = i;
        switch (set.size) {
        case 1: add(std::integral_constant<int, 1>{}, set); break;
        case 2: add(std::integral_constant<int, 2>{}, set); break;
        default: add(std::integral_constant<int, 3>{}, set); break;
        }
    }
}

MohrCoulomb::MohrCoulomb(const Material& m)
    : MohrCoulomb(m.young_modulus, m.poisson_ratio, m.parameter("cohesion"), m.parameter("friction_angle"),
                  m.parameter("dilation_angle"), m.parameter("tensile_strength")) {}

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

ReturnResult MohrCoulomb::return_map(const PlaneStress& trial) const { return return_map(trial, nullptr); }

ReturnResult MohrCoulomb::return_map(const PlaneStress& trial, Eigen::Matrix3d* tangent) const {
    ReturnResult result;
    result.stress = trial;
    auto violation = [&](const Eigen::Vector3d& x) {
        double worst = -1e300;
        for (int i = 0; i < plane_count_; ++i) worst = std::max(worst, planes_[i].n.dot(x) - planes_[i].k);
        return worst;
    };
    auto elastic = [&]() {
        if (tangent) {
            const double diagonal = lambda_ + 2 * shear_modulus_;
            *tangent << diagonal, lambda_, 0.0, lambda_, diagonal, 0.0, 0.0, 0.0, shear_modulus_;
        }
        return result;
    };
    // Most points stay elastic, and the test needs no principal frame (a hypot, a division)
    // where it passes with room to spare: the radius of Mohr's circle is at most
    // |½(σxx − σyy)| + |τxy|, and with a larger radius the major principal value can only rise
    // and the minor only fall, which raises the largest of the planes' functions (that of the
    // major and the minor value, or the major's tension cut-off). Passed by more than any
    // rounding there, the exact test below passes too: the same verdict, not an approximation.
    {
        const double centre = 0.5 * (trial.xx + trial.yy);
        const double radius_bound = std::fabs(0.5 * (trial.xx - trial.yy)) + std::fabs(trial.xy);
        double v[3] = {centre + radius_bound, centre - radius_bound, trial.zz};
        if (v[2] > v[0]) std::swap(v[2], v[0]);
        if (v[2] > v[1]) std::swap(v[2], v[1]);
        const double rounding =
            1e-13 * (std::fabs(v[0]) + std::fabs(v[1]) + std::fabs(v[2]) + cohesion_ + tensile_strength_);
        if (violation(Eigen::Vector3d(v[0], v[1], v[2])) <= tolerance_ - rounding) return elastic();
    }

    // Principal values sorted (the frame keeps the way back to x, y, z).
    const PrincipalFrame frame(trial);
    const Eigen::Vector3d& s = frame.sorted;
    if (violation(s) <= tolerance_) return elastic();

    const double scale = tolerance_;
    Eigen::Vector3d best = s;
    Eigen::Vector3d best_flow = Eigen::Vector3d::Zero();
    int best_size = 0;
    Eigen::Matrix3d sorted_derivative;  // dσ/ds in sorted principal order, when tangent is wanted

    // Closest-point projection onto the planes of `set` (K of them): Δγ = A⁻¹ f with
    // A_rc = n_r·D m_c, f_r = n_r·s − k_r; accepted if it lands on all of them with Δγ ≥ 0, keeps
    // the principal order and violates no other plane.
    auto attempt = [&](auto size, const ActiveSet& set) {
        constexpr int K = decltype(size)::value;
        const auto inverse = set.inverse.template topLeftCorner<K, K>();
        Eigen::Matrix<double, K, 1> f;
        for (int r = 0; r < K; ++r) f[r] = planes_[set.planes[r]].n.dot(s) - planes_[set.planes[r]].k;
        const Eigen::Matrix<double, K, 1> gamma = inverse * f;
        if (!(gamma.array() >= -1e-12).all()) return false;
        Eigen::Vector3d flow = Eigen::Vector3d::Zero();
        for (int r = 0; r < K; ++r) flow += gamma[r] * planes_[set.planes[r]].m;
        const Eigen::Vector3d x = s - elasticity_ * flow;
        const bool ordered = x[0] >= x[1] - 1e-9 * (std::fabs(x[1]) + scale) && x[1] >= x[2] - 1e-9 * (std::fabs(x[2]) + scale);
        if (!ordered || violation(x) > 1e-9 * (x.cwiseAbs().maxCoeff() + cohesion_ + scale)) return false;
        best = x;
        best_flow = flow;
        best_size = K;
        if (tangent) {
            // x = s − D M A⁻¹ (Nᵀ s − k), so dx/ds = I − D M A⁻¹ Nᵀ.
            Eigen::Matrix<double, 3, K> DM;
            Eigen::Matrix<double, K, 3> Nt;
            for (int r = 0; r < K; ++r) {
                DM.col(r) = planes_[set.planes[r]].Dm;
                Nt.row(r) = planes_[set.planes[r]].n.transpose();
            }
            sorted_derivative = Eigen::Matrix3d::Identity() - DM * (inverse * Nt);
        }
        return true;
    };

    // Active sets by increasing size: the first consistent one is the return (plane, edge,
    // apex; the cut-off combinations alike).
    bool found = false;
    for (int k = 0; k < set_count_ && !found; ++k) {
        switch (sets_[k].size) {
        case 1: found = attempt(std::integral_constant<int, 1>{}, sets_[k]); break;
        case 2: found = attempt(std::integral_constant<int, 2>{}, sets_[k]); break;
        default: found = attempt(std::integral_constant<int, 3>{}, sets_[k]); break;
        }
    }
    if (!found) {
        // No active set is consistent: with non-associated flow (ψ < φ) the return to the apex
        // needs negative multipliers on the plane and edges. The stress then goes to the apex
        // itself (de Souza Neto et al., Box 8.5): hydrostatic at c·cot φ, or at the cut-off,
        // neither depending on the trial stress, so dσ/ds = 0.
        bool follows_mean = !(sin_phi_ > 1e-12);  // φ = 0: the "apex" is the mean stress
        double apex = follows_mean ? s.mean() : cohesion_ * cos_phi_ / sin_phi_;
        if (tensile_strength_ > 0.0 && tensile_strength_ < apex) {
            apex = tensile_strength_;
            follows_mean = false;
        }
        best = Eigen::Vector3d::Constant(apex);
        best_flow = compliance_ * (s - best);
        best_size = 3;
        if (tangent) sorted_derivative.setConstant(follows_mean ? 1.0 / 3.0 : 0.0);
    }

    // Back to x, y, z: the principal directions do not change (isotropic elasticity).
    double returned[3];
    result.stress = frame.stress(best, returned);
    result.plastic = true;
    result.active_surfaces = best_size;
    result.equivalent_plastic_strain = std::sqrt(2.0 / 3.0 * best_flow.squaredNorm());

    if (tangent) *tangent = frame.tangent(sorted_derivative, returned, elasticity_, shear_modulus_, tolerance_);
    return result;
}

namespace {

std::string degrees(double radians) { return value_text(Quantity::Angle, radians); }

void check_mohr_coulomb(const Material& m, bool plasticity, std::vector<LawProblem>& problems) {
    const double phi = m.parameter("friction_angle"), psi = m.parameter("dilation_angle");
    if (psi >= 0.0 && psi > phi)
        problems.push_back({"dilation_angle", "dilation angle " + degrees(psi) + " exceeds the friction angle " + degrees(phi)});
    if (plasticity && m.parameter("cohesion") == 0.0 && phi == 0.0)
        problems.push_back({"", "a plastic material needs cohesion or friction (both are zero)"});
}

/// c/F, atan(tan φ/F), σt/F and ψ ≤ the reduced φ; with Davis's treatment of non-associated
/// flow the associated equivalent of those (material/StrengthReduction.hpp).
Material reduced_mohr_coulomb(const Material& m, double factor, AnalysisSettings::NonAssociatedFlow flow) {
    Material r = m;
    double c = m.parameter("cohesion") / factor;
    double phi = std::atan(std::tan(m.parameter("friction_angle")) / factor);
    double psi = std::min(m.parameter("dilation_angle"), phi);
    if (flow == AnalysisSettings::NonAssociatedFlow::Davis && psi < phi) {
        const double beta = davis_factor(phi, psi);
        c *= beta;
        phi = std::atan(beta * std::tan(phi));
        psi = phi;
    }
    r.parameters["cohesion"] = c;
    r.parameters["friction_angle"] = phi;
    r.parameters["dilation_angle"] = psi;
    r.parameters["tensile_strength"] = m.parameter("tensile_strength") / factor;
    return r;
}

}  // namespace

const MaterialLaw& mohr_coulomb_law() {
    static const MaterialLaw law{
        "mohr-coulomb", MCDDA_TRANSLATABLE("ModelFields", "Mohr–Coulomb"),
        MCDDA_TRANSLATABLE("ModelFields", "Perfectly plastic with cohesion c and friction angle φ, non-associated flow by ψ, optional tension cut-off"),
        {
            {"cohesion", "cohesion", MCDDA_TRANSLATABLE("ModelFields", "Cohesion c"), Quantity::Stress, 0.0, Bound{0.0, true},
             std::nullopt, max_stress, nullptr, MCDDA_TRANSLATABLE("ModelFields", "Mohr–Coulomb cohesion c, ≥ 0")},
            {"friction_angle", "friction angle", MCDDA_TRANSLATABLE("ModelFields", "Friction angle φ"), Quantity::Angle, 0.0,
             Bound{0.0, true}, Bound{pi / 2, false}, 0.0, nullptr,
             MCDDA_TRANSLATABLE("ModelFields", "Mohr–Coulomb friction angle φ, in [0°, 90°)")},
            {"dilation_angle", "dilation angle", MCDDA_TRANSLATABLE("ModelFields", "Dilation angle ψ"), Quantity::Angle, 0.0,
             Bound{0.0, true}, std::nullopt, 0.0, nullptr,
             MCDDA_TRANSLATABLE("ModelFields", "Dilation angle ψ of the plastic flow, 0 ≤ ψ ≤ φ (ψ = φ: associated flow)")},
            {"tensile_strength", "tensile strength", MCDDA_TRANSLATABLE("ModelFields", "Tensile strength"), Quantity::Stress, 0.0,
             Bound{0.0, true}, std::nullopt, max_stress, nullptr,
             MCDDA_TRANSLATABLE("ModelFields", "Tension cut-off of the Mohr–Coulomb surface, ≥ 0; 0 = no tension")},
        },
        check_mohr_coulomb,
        reduced_mohr_coulomb,
        [](const Material& m) { return m.parameter("dilation_angle") < m.parameter("friction_angle"); },
        [](const Material& m) -> std::unique_ptr<ConstitutiveLaw> { return std::make_unique<MohrCoulomb>(m); },
    };
    return law;
}

}  // namespace mcdda

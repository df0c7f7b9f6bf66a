#include "material/HoekBrown.hpp"

#include "material/Elasticity.hpp"
#include "material/PrincipalFrame.hpp"
#include "model/Defaults.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

namespace mcdda {

namespace {

/// The root x > 0 of c1 x + σci x^a = F (c1, σci, F > 0, 0 < a ≤ 1). The left side increases and
/// is concave, so Newton's method from below the root climbs to it monotonically, and quadratically
/// once close; the root lies between min(F/2c1, (F/2σci)^(1/a)) (one of the two terms is at least
/// F/2) and min(F/c1, (F/σci)^(1/a)), which start and cap the iteration.
double hoek_brown_argument(double c1, double sigma_ci, double a, double F) {
    const double hi = std::min(F / c1, std::pow(F / sigma_ci, 1 / a));
    double x = std::min(F / (2 * c1), std::pow(F / (2 * sigma_ci), 1 / a));
    if (!(x > 0.0)) return 0.0;  // F below what the powers resolve: at the apex
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double xa = std::pow(x, a);
        const double g = c1 * x + sigma_ci * xa - F;
        if (!(g < 0.0)) break;  // at the root, or past it by rounding
        const double next = std::min(x - g / (c1 + a * sigma_ci * xa / x), hi);
        if (!(next > x)) break;  // no progress left
        x = next;
    }
    return x;
}

}  // namespace

HoekBrownParameters hoek_brown_parameters(double gsi, double mi, double disturbance) {
    if (!(gsi >= 0.0 && gsi <= 100.0) || !(mi > 0.0 && std::isfinite(mi)) || !(disturbance >= 0.0 && disturbance <= 1.0))
        throw std::invalid_argument("hoek_brown_parameters: needs 0 ≤ GSI ≤ 100, mi > 0 and 0 ≤ D ≤ 1");
    HoekBrownParameters p;
    p.mb = mi * std::exp((gsi - 100) / (28 - 14 * disturbance));
    p.s = std::exp((gsi - 100) / (9 - 3 * disturbance));
    p.a = 0.5 + (std::exp(-gsi / 15) - std::exp(-20.0 / 3.0)) / 6;
    return p;
}

double hoek_brown_tensile_strength(double sigma_ci, double mb, double s) { return s * sigma_ci / mb; }

HoekBrown::HoekBrown(double E, double nu, double sigma_ci, const HoekBrownParameters& hb, double psi, double tensile)
    : lambda_(E * nu / ((1 + nu) * (1 - 2 * nu))), shear_modulus_(E / (2 * (1 + nu))), sigma_ci_(sigma_ci), hb_(hb),
      k_psi_((1 + std::sin(psi)) / (1 - std::sin(psi))), apex_(hoek_brown_tensile_strength(sigma_ci, hb.mb, hb.s)),
      cut_off_(tensile > 0.0 && tensile < apex_ ? tensile : 0.0),
      tolerance_(1e-10 * std::max({sigma_ci, 1e-6 * E, 1.0})) {
    const bool valid = E > 0.0 && std::isfinite(E) && nu > -1.0 && nu < 0.5 && sigma_ci > 0.0 &&
                       std::isfinite(sigma_ci) && hb.mb > 0.0 && std::isfinite(hb.mb) && hb.s >= 0.0 && hb.s <= 1.0 &&
                       hb.a > 0.0 && hb.a <= 1.0 && psi >= 0.0 && psi < M_PI / 2 && tensile >= 0.0 && std::isfinite(tensile);
    if (!valid) throw std::invalid_argument("HoekBrown: material parameters out of range");
    elasticity_ = lambda_ * Eigen::Matrix3d::Ones() + 2 * shear_modulus_ * Eigen::Matrix3d::Identity();
    plane_strain_ = plane_strain_elasticity(E, nu);  // the same D, bit for bit, as every other law
    compliance_ = elasticity_.inverse();

    // Flow directions in sorted principal space, the gradients of Kψ σi − σj: m_A of the main
    // surface (σ1, σ3), m_B of the sector (σ2, σ3) that meets it at σ1 = σ2, m_C of (σ1, σ2)
    // that meets it at σ2 = σ3.
    const double K = k_psi_;
    const Eigen::Vector3d mA(K, 0, -1), mB(0, K, -1), mC(K, -1, 0);
    const Eigen::Vector3d e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY();
    // On an edge the two multipliers differ by what keeps the pair equal, δ = w·s (the pair's
    // elastic gap closes at 2GKψ resp. 2G per unit δ); Γ, their sum, is left to the criterion.
    mean_flow_ = {mA, 0.5 * (mA + mB), 0.5 * (mA + mC)};
    fixed_flow_ = {Eigen::Vector3d::Zero(), 0.5 * (mA - mB), 0.5 * (mA - mC)};
    weight_ = {Eigen::Vector3d::Zero(), Eigen::Vector3d(1, -1, 0) / (2 * shear_modulus_ * K),
               Eigen::Vector3d(0, 1, -1) / (2 * shear_modulus_)};
    for (int k = 0; k < 3; ++k) {
        d_mean_flow_[k] = elasticity_ * mean_flow_[k];
        d_fixed_flow_[k] = elasticity_ * fixed_flow_[k];
    }

    if (cut_off_ > 0.0) {
        // Where σ1 = σt the criterion fixes σ3 (or σ2 = σ3 on the edge): the corners are linear.
        const double t = cut_off_;
        const double corner = t - sigma_ci_ * std::pow(hb_.mb * (apex_ - t) / sigma_ci_, hb_.a);
        auto add = [&](std::initializer_list<int> rows, Eigen::Vector3d target, std::initializer_list<Eigen::Vector3d> flows) {
            Corner c;
            c.size = static_cast<int>(rows.size());
            std::copy(rows.begin(), rows.end(), c.rows.begin());
            c.target = target;
            int column = 0;
            for (const Eigen::Vector3d& m : flows) c.flows.col(column++) = m;
            const Eigen::Matrix3d DM = elasticity_ * c.flows;
            Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
            for (int r = 0; r < c.size; ++r)
                for (int col = 0; col < c.size; ++col) A(r, col) = DM(c.rows[r], col);
            Eigen::FullPivLU<Eigen::Matrix3d> lu(A);
            if (!lu.isInvertible()) return;  // not for these flows; kept as a guard
            c.inverse = lu.inverse();
            Eigen::Matrix3d Nt = Eigen::Matrix3d::Zero();
            for (int r = 0; r < c.size; ++r) Nt(r, c.rows[r]) = 1.0;
            // All three components fixed: the returned stress does not depend on the trial.
            c.derivative = c.size == 3 ? Eigen::Matrix3d::Zero().eval()
                                       : (Eigen::Matrix3d::Identity() - DM * c.inverse * Nt).eval();
            corners_[corner_count_++] = c;
        };
        // By size, and within a size in the order the planes main, 1–2, 2–3, σ1, σ2, σ3 of a
        // Mohr–Coulomb law with cut-off would give their masks.
        add({0}, Eigen::Vector3d(t, 0, 0), {e1});
        add({0, 2}, Eigen::Vector3d(t, corner, 0), {mA, e1});
        add({0, 1}, Eigen::Vector3d(t, t, 0), {e1, e2});
        add({0, 1, 2}, Eigen::Vector3d(t, t, corner), {mA, mB, e1});
        add({0, 1, 2}, Eigen::Vector3d(t, corner, corner), {mA, mC, e1});
        add({0, 1, 2}, Eigen::Vector3d(t, t, corner), {mA, mB, e2});
        add({0, 1, 2}, Eigen::Vector3d(t, t, corner), {mA, e1, e2});
        add({0, 1, 2}, Eigen::Vector3d(t, t, corner), {mB, e1, e2});
        // The cut-off's own apex, σ = σt (1, 1, 1), is the fallback below.
    }
}

double HoekBrown::violation(const Eigen::Vector3d& x) const {
    const double argument = hb_.mb * (apex_ - x[0]) / sigma_ci_;  // s − mb σ1/σci, exactly 0 at the apex
    double f = argument >= 0.0 ? (x[0] - x[2]) - sigma_ci_ * std::pow(argument, hb_.a) : (x[0] - x[2]) + (x[0] - apex_);
    if (cut_off_ > 0.0) f = std::max(f, x[0] - cut_off_);
    return f;
}

double HoekBrown::yield(const PlaneStress& s) const { return violation(PrincipalFrame(s).sorted); }

bool HoekBrown::admissible(const Eigen::Vector3d& x) const {
    const double scale = tolerance_;
    const bool ordered = x[0] >= x[1] - 1e-9 * (std::fabs(x[1]) + scale) && x[1] >= x[2] - 1e-9 * (std::fabs(x[2]) + scale);
    return ordered && violation(x) <= 1e-9 * (x.cwiseAbs().maxCoeff() + sigma_ci_ + scale);
}

bool HoekBrown::smooth_return(int kind, const Eigen::Vector3d& s, bool derivative, Return& out) const {
    // σ = s̃ − Γ D m̄ with s̃ = s − δ D d. Along that line σ1 = apex − (σci/mb) x, with x the
    // criterion's argument s − mb σ1/σci, and f = F0 − c1 x − σci x^a: a root x > 0 exists
    // exactly when F0 > 0 (else the line passes beyond the apex) and is unique.
    const double delta = weight_[kind].dot(s);
    const Eigen::Vector3d shifted = s - delta * d_fixed_flow_[kind];
    const Eigen::Vector3d& v = d_mean_flow_[kind];
    const double p = v[0], q = v[0] - v[2];  // both > 0 for ψ ≥ 0 and ν > −1
    const double F0 = (shifted[0] - shifted[2]) - q * (shifted[0] - apex_) / p;
    if (!(F0 > 0.0)) return false;
    const double ratio = sigma_ci_ / hb_.mb;
    const double x = hoek_brown_argument(q * ratio / p, sigma_ci_, hb_.a, F0);
    const double gamma = (shifted[0] - apex_ + ratio * x) / p;
    // Both multipliers of an edge, (Γ ± δ)/2, must be ≥ 0 (δ ≥ 0 as s is sorted).
    if (!(gamma - delta >= -1e-12)) return false;
    Eigen::Vector3d sigma = shifted - gamma * v;
    if (kind == 1) sigma[1] = sigma[0];  // the edge exactly, not to rounding
    if (kind == 2) sigma[1] = sigma[2];
    if (!admissible(sigma)) return false;
    out.stress = sigma;
    out.flow = gamma * mean_flow_[kind] + delta * fixed_flow_[kind];
    out.size = kind == 0 ? 1 : 2;
    if (derivative) {
        // The potential is linear, so dσ/ds = I − D M (Nᵀ D M)⁻¹ Nᵀ over the active sectors with
        // their gradients at σ, each scaled by 1/(1 + a mb x^(a−1)) to stay finite at the apex.
        const double w = std::pow(x, 1 - hb_.a) / (std::pow(x, 1 - hb_.a) + hb_.a * hb_.mb);
        const double K = k_psi_;
        if (kind == 0) {
            const Eigen::Vector3d n(1, 0, -w);
            out.derivative = Eigen::Matrix3d::Identity() - v * n.transpose() / n.dot(v);
        } else {
            Eigen::Matrix<double, 3, 2> N, M;
            N.col(0) = Eigen::Vector3d(1, 0, -w);
            M.col(0) = Eigen::Vector3d(K, 0, -1);
            N.col(1) = kind == 1 ? Eigen::Vector3d(0, 1, -w) : Eigen::Vector3d(1, -w, 0);
            M.col(1) = kind == 1 ? Eigen::Vector3d(0, K, -1) : Eigen::Vector3d(K, -1, 0);
            const Eigen::Matrix<double, 3, 2> DM = elasticity_ * M;
            const Eigen::Matrix2d A = N.transpose() * DM;
            out.derivative = Eigen::Matrix3d::Identity() - DM * A.inverse() * N.transpose();
        }
    }
    return true;
}

bool HoekBrown::corner_return(const Corner& c, const Eigen::Vector3d& s, Return& out) const {
    Eigen::Vector3d excess = Eigen::Vector3d::Zero();
    for (int r = 0; r < c.size; ++r) excess[r] = s[c.rows[r]] - c.target[r];
    const Eigen::Vector3d gamma = c.inverse * excess;
    for (int r = 0; r < c.size; ++r)
        if (!(gamma[r] >= -1e-12)) return false;
    Eigen::Vector3d flow = Eigen::Vector3d::Zero();
    for (int r = 0; r < c.size; ++r) flow += gamma[r] * c.flows.col(r);
    Eigen::Vector3d sigma = s - elasticity_ * flow;
    for (int r = 0; r < c.size; ++r) sigma[c.rows[r]] = c.target[r];
    if (!admissible(sigma)) return false;
    out.stress = sigma;
    out.flow = flow;
    out.derivative = c.derivative;
    out.size = c.size;
    return true;
}

ReturnResult HoekBrown::return_map(const PlaneStress& trial) const { return return_map(trial, nullptr); }

ReturnResult HoekBrown::return_map(const PlaneStress& trial, Eigen::Matrix3d* tangent) const {
    ReturnResult result;
    result.stress = trial;
    const PrincipalFrame frame(trial);
    const Eigen::Vector3d& s = frame.sorted;
    if (!(violation(s) > tolerance_)) {  // elastic (and NaN in, NaN out)
        if (tangent) *tangent = plane_strain_;
        return result;
    }

    // Returns by increasing number of active surfaces, the first consistent one taken (as
    // MohrCoulomb does): the main surface, then the cut-off alone; the two edges, then the
    // cut-off's corners with the surface and its own edge; then the three-surface corners.
    Return best;
    bool found = false;
    for (int size = 1; size <= 3 && !found; ++size) {
        if (size == 1) found = smooth_return(0, s, tangent != nullptr, best);
        if (size == 2) found = smooth_return(1, s, tangent != nullptr, best) || smooth_return(2, s, tangent != nullptr, best);
        for (int k = 0; k < corner_count_ && !found; ++k)
            if (corners_[k].size == size) found = corner_return(corners_[k], s, best);
    }
    if (!found) {
        // No consistent return: the trial lies beyond the apex, or beyond the cut-off's apex
        // σ1 = σ2 = σ3 = σt, where the flows of the surfaces cannot reach it with multipliers ≥ 0
        // (non-associated flow) or where all three cut-off planes are active. The stress goes to
        // that point itself, hydrostatic, not depending on the trial (dσ/ds = 0).
        best.stress = Eigen::Vector3d::Constant(tensile_limit());
        best.flow = compliance_ * (s - best.stress);
        best.derivative.setZero();
        best.size = 3;
    }

    double returned[3];
    result.stress = frame.stress(best.stress, returned);
    result.plastic = true;
    result.active_surfaces = best.size;
    // hypot, not the squared norm: finite for any finite trial.
    result.equivalent_plastic_strain = std::sqrt(2.0 / 3.0) * std::hypot(best.flow[0], best.flow[1], best.flow[2]);
    if (tangent) *tangent = frame.tangent(best.derivative, returned, elasticity_, shear_modulus_, tolerance_);
    return result;
}

namespace {

std::unique_ptr<ConstitutiveLaw> create_hoek_brown(const Material& m) {
    const HoekBrownParameters p = hoek_brown_parameters(m.parameter("gsi"), m.parameter("mi"), m.parameter("disturbance"));
    return std::make_unique<HoekBrown>(m.young_modulus, m.poisson_ratio, m.parameter("uniaxial_strength"), p,
                                       m.parameter("dilation_angle"), m.parameter("tensile_strength"));
}

/// The deviator the rock mass carries at every confinement divided by F:
///   σ1 − σ3 = σci (mb σ3/σci + s)^a / F = (σci/F) ((mb/F) σ3/(σci/F) + s)^a,
/// the same criterion with σci/F and mb/F (mi/F), s and a unchanged (docs/plasticity.md,
/// "Hoek–Brown"); the tension cut-off σt/F; ψ as given.
Material reduced_hoek_brown(const Material& m, double factor, AnalysisSettings::NonAssociatedFlow) {
    Material r = m;
    r.parameters["uniaxial_strength"] = m.parameter("uniaxial_strength") / factor;
    r.parameters["mi"] = m.parameter("mi") / factor;
    r.parameters["tensile_strength"] = m.parameter("tensile_strength") / factor;
    return r;
}

}  // namespace

const MaterialLaw& hoek_brown_law() {
    static const MaterialLaw law{
        "hoek-brown", MCDDA_TRANSLATABLE("ModelFields", "Hoek–Brown"),
        MCDDA_TRANSLATABLE("ModelFields", "Generalised Hoek–Brown rock mass (2002): strength from σci, GSI, mi and the disturbance D"),
        {
            {"uniaxial_strength", "uniaxial compressive strength", MCDDA_TRANSLATABLE("ModelFields", "Intact strength σci"),
             Quantity::Stress, std::nullopt, Bound{0.0, false}, std::nullopt, max_stress, nullptr,
             MCDDA_TRANSLATABLE("ModelFields", "Uniaxial compressive strength σci of the intact rock, > 0")},
            {"gsi", "GSI", MCDDA_TRANSLATABLE("ModelFields", "GSI"), Quantity::Ratio, std::nullopt, Bound{0.0, true},
             Bound{100.0, true}, 0.0, nullptr,
             MCDDA_TRANSLATABLE("ModelFields", "Geological Strength Index of the rock mass, 0 to 100 (100: intact rock)")},
            {"mi", "mi", MCDDA_TRANSLATABLE("ModelFields", "Intact constant mi"), Quantity::Ratio, std::nullopt, Bound{0.0, false},
             std::nullopt, 100.0, nullptr,
             MCDDA_TRANSLATABLE("ModelFields", "Hoek–Brown constant mi of the intact rock, > 0 (about 4 for claystone to 33 for granite)")},
            {"disturbance", "disturbance factor", MCDDA_TRANSLATABLE("ModelFields", "Disturbance D"), Quantity::Ratio, 0.0,
             Bound{0.0, true}, Bound{1.0, true}, 0.0, nullptr,
             MCDDA_TRANSLATABLE("ModelFields", "Disturbance factor D by blasting and stress relaxation, 0 (undisturbed) to 1")},
            {"dilation_angle", "dilation angle", MCDDA_TRANSLATABLE("ModelFields", "Dilation angle ψ"), Quantity::Angle, 0.0,
             Bound{0.0, true}, Bound{pi / 2, false}, 0.0, nullptr,
             MCDDA_TRANSLATABLE("ModelFields", "Dilation angle ψ of the plastic flow (constant), in [0°, 90°)")},
            {"tensile_strength", "tensile strength", MCDDA_TRANSLATABLE("ModelFields", "Tension cut-off"), Quantity::Stress, 0.0,
             Bound{0.0, true}, std::nullopt, max_stress, MCDDA_TRANSLATABLE("ModelFields", "the Hoek–Brown tensile strength"),
             MCDDA_TRANSLATABLE("ModelFields", "A tension cut-off below the Hoek–Brown tensile strength s σci/mb, ≥ 0; 0 = none but the criterion's own")},
        },
        nullptr,
        reduced_hoek_brown,
        [](const Material&) { return true; },
        create_hoek_brown,
    };
    return law;
}

}  // namespace mcdda

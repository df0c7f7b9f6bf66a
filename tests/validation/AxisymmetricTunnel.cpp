#include "AxisymmetricTunnel.hpp"

#include "material/MohrCoulomb.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mcdda::test {

namespace {

// Internally tension positive, components (r, θ, z), u outward, as the solver's MohrCoulomb.
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct Point {
    double r, weight;         // weight = h r (the 2π is dropped throughout)
    int node;                 // first node of the element
    double n1, n2, dn1, dn2;  // shape functions and their r-derivatives there
};

/// Consistent tangent of the return that produced `s` (exact for Mohr–Coulomb's linear planes
/// with fixed principal directions): D − D M (Nᵀ D M)⁻¹ Nᵀ D over the active planes.
Mat3 plastic_tangent(const Mat3& D, const Vec3& s, int active, double sin_phi, double sin_psi, double k) {
    if (active >= 3) return 1e-9 * D;  // apex: no stiffness (kept regular)
    int o[3] = {0, 1, 2};
    std::sort(o, o + 3, [&](int i, int j) { return s[i] > s[j]; });
    auto plane = [&](int major, int minor, double sine) {
        Vec3 v = Vec3::Zero();
        v[major] = 1 + sine;
        v[minor] = -(1 - sine);
        return v;
    };
    Eigen::Matrix<double, 3, Eigen::Dynamic> N(3, active), M(3, active);
    N.col(0) = plane(o[0], o[2], sin_phi);
    M.col(0) = plane(o[0], o[2], sin_psi);
    if (active == 2) {
        // The edge: the second plane is whichever of 1–2 and 2–3 the stress lies on.
        const double f12 = plane(o[0], o[1], sin_phi).dot(s) - k;
        const double f23 = plane(o[1], o[2], sin_phi).dot(s) - k;
        const bool upper = std::fabs(f12) <= std::fabs(f23);
        N.col(1) = upper ? plane(o[0], o[1], sin_phi) : plane(o[1], o[2], sin_phi);
        M.col(1) = upper ? plane(o[0], o[1], sin_psi) : plane(o[1], o[2], sin_psi);
    }
    const Eigen::MatrixXd A = N.transpose() * D * M;
    return D - D * M * A.inverse() * N.transpose() * D;
}

/// Solves a tridiagonal system in place (lower[i] = K(i, i−1), upper[i] = K(i, i+1)).
void solve_tridiagonal(std::vector<double> lower, std::vector<double> diag, std::vector<double> upper,
                       std::vector<double>& rhs) {
    const std::size_t n = diag.size();
    for (std::size_t i = 1; i < n; ++i) {
        const double m = lower[i] / diag[i - 1];
        diag[i] -= m * upper[i - 1];
        rhs[i] -= m * rhs[i - 1];
    }
    rhs[n - 1] /= diag[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) rhs[i] = (rhs[i] - upper[i] * rhs[i + 1]) / diag[i];
}

}  // namespace

AxisymmetricTunnelResult solve_axisymmetric_tunnel(const AxisymmetricTunnelSpec& spec) {
    if (spec.elements < 1 || spec.increments < 1 || !(spec.b > spec.a) || !(spec.a > 0))
        throw std::invalid_argument("solve_axisymmetric_tunnel: bad spec");
    const double E = spec.young_modulus, nu = spec.poisson_ratio;
    const MohrCoulomb mc(E, nu, spec.cohesion, spec.friction_angle, spec.dilation_angle, 0.0);
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
    const Mat3 D = lambda * Mat3::Ones() + 2 * G * Mat3::Identity();
    const double sin_phi = std::sin(spec.friction_angle), sin_psi = std::sin(spec.dilation_angle);
    const double k = 2 * spec.cohesion * std::cos(spec.friction_angle);

    // Nodes uniform in log r: element size ∝ r, fine at the wall where the gradients are.
    const int ne = spec.elements, nn = ne + 1;
    std::vector<double> node_r(nn);
    for (int i = 0; i < nn; ++i) node_r[i] = spec.a * std::pow(spec.b / spec.a, double(i) / ne);
    node_r[ne] = spec.b;

    // One integration point per linear element, at its middle: the plastic flow rule constrains
    // the strain at every yielding point (like incompressibility), and with two points per
    // element the mesh locks (σr at the wall came out 0.3 MPa instead of 0 for ψ = 30°).
    std::vector<Point> points;
    points.reserve(ne);
    for (int e = 0; e < ne; ++e) {
        const double r1 = node_r[e], r2 = node_r[e + 1], h = r2 - r1;
        Point p;
        p.r = 0.5 * (r1 + r2);
        p.weight = h * p.r;
        p.node = e;
        p.n1 = p.n2 = 0.5;
        p.dn1 = -1 / h;
        p.dn2 = 1 / h;
        points.push_back(p);
    }
    const std::size_t np = points.size();

    const double sz0 = spec.sigma_z0.value_or(spec.P0);
    std::vector<Vec3> stress(np, Vec3(-spec.P0, -spec.P0, -sz0)), trial_stress(np);
    std::vector<double> u(nn, 0.0), du(nn, 0.0);
    const bool fixed = spec.outer == OuterBoundary::Fixed;
    const int free = fixed ? nn - 1 : nn;  // u(b) = 0 drops the last node
    const double reference = std::max({std::fabs(spec.P0), std::fabs(spec.Pi), spec.cohesion}) * spec.a;
    const double tolerance = mc.tolerance();

    AxisymmetricTunnelResult result;
    std::vector<double> lower(free), diag(free), upper(free), residual(free);
    for (int step = 1; step <= spec.increments; ++step) {
        const double p = spec.P0 + (spec.Pi - spec.P0) * double(step) / spec.increments;
        std::fill(du.begin(), du.end(), 0.0);
        bool converged = false;
        for (int iteration = 0; iteration < 50; ++iteration) {
            // Stresses from the increment's displacement, internal force and tangent.
            std::fill(lower.begin(), lower.end(), 0.0);
            std::fill(diag.begin(), diag.end(), 0.0);
            std::fill(upper.begin(), upper.end(), 0.0);
            std::fill(residual.begin(), residual.end(), 0.0);
            residual[0] += p * spec.a;  // σr(a) = −p pushes the wall outward
            if (!fixed) residual[nn - 1] -= spec.P0 * spec.b;
            for (std::size_t i = 0; i < np; ++i) {
                const Point& q = points[i];
                const double der = q.dn1 * du[q.node] + q.dn2 * du[q.node + 1];
                const double hoop = (q.n1 * du[q.node] + q.n2 * du[q.node + 1]) / q.r;
                Vec3 s = stress[i] + D * Vec3(der, hoop, 0.0);
                Mat3 t = D;
                const PlaneStress trial{s[0], s[1], 0.0, s[2]};
                if (mc.yield(trial) > tolerance) {
                    const ReturnResult rr = mc.return_map(trial);
                    if (rr.plastic) {
                        s = Vec3(rr.stress.xx, rr.stress.yy, rr.stress.zz);
                        t = plastic_tangent(D, s, rr.active_surfaces, sin_phi, sin_psi, k);
                    }
                }
                trial_stress[i] = s;
                // B rows: εr = dN·u, εθ = N·u / r.
                const double b1[2] = {q.dn1, q.n1 / q.r}, b2[2] = {q.dn2, q.n2 / q.r};
                const int n1 = q.node, n2 = q.node + 1;
                const double w = q.weight;
                auto kij = [&](const double* bi, const double* bj) {
                    double v = 0.0;
                    for (int x = 0; x < 2; ++x)
                        for (int y = 0; y < 2; ++y) v += bi[x] * t(x, y) * bj[y];
                    return w * v;
                };
                if (n1 < free) {
                    residual[n1] -= w * (b1[0] * s[0] + b1[1] * s[1]);
                    diag[n1] += kij(b1, b1);
                }
                if (n2 < free) {
                    residual[n2] -= w * (b2[0] * s[0] + b2[1] * s[1]);
                    diag[n2] += kij(b2, b2);
                    lower[n2] += kij(b2, b1);
                    upper[n1] += kij(b1, b2);
                }
            }
            double worst = 0.0;
            for (double v : residual) worst = std::max(worst, std::fabs(v));
            ++result.newton_iterations;
            if (worst <= 1e-10 * reference) {
                converged = true;
                break;
            }
            solve_tridiagonal(lower, diag, upper, residual);
            for (int i = 0; i < free; ++i) du[i] += residual[i];
        }
        if (!converged)
            throw std::runtime_error("solve_axisymmetric_tunnel: increment " + std::to_string(step) +
                                     " did not converge");
        stress = trial_stress;
        for (int i = 0; i < nn; ++i) u[i] += du[i];
    }

    result.wall_displacement = -u[0];
    result.r.resize(np);
    result.sigma_r.resize(np);
    result.sigma_theta.resize(np);
    result.sigma_z.resize(np);
    result.yielding.resize(np);
    std::vector<double> f(np);
    const double yielding_tolerance = 1e-6 * std::max(spec.cohesion, std::fabs(spec.P0));
    int last_plastic = -1;
    for (std::size_t i = 0; i < np; ++i) {
        result.r[i] = points[i].r;
        result.sigma_r[i] = -stress[i][0];
        result.sigma_theta[i] = -stress[i][1];
        result.sigma_z[i] = -stress[i][2];
        f[i] = mc.yield(PlaneStress{stress[i][0], stress[i][1], 0.0, stress[i][2]});
        result.yielding[i] = f[i] > -yielding_tolerance;
        if (result.yielding[i]) last_plastic = static_cast<int>(i);
    }
    // Plastic radius: where f of the elastic zone, A + B/r² there (Lamé), reaches zero, from the
    // two points just outside the last yielding one; within one point spacing of that point.
    result.plastic_radius = spec.a;
    if (last_plastic >= 0) {
        result.plastic_radius = points[last_plastic].r;
        const std::size_t i1 = last_plastic + 1, i2 = last_plastic + 2;
        if (i2 < np && f[i1] != f[i2]) {
            const double x1 = 1 / (points[i1].r * points[i1].r), x2 = 1 / (points[i2].r * points[i2].r);
            const double x = x1 - f[i1] * (x2 - x1) / (f[i2] - f[i1]);
            if (x > 0)
                result.plastic_radius = std::clamp(1 / std::sqrt(x), points[last_plastic].r, points[i1].r);
        }
    }
    return result;
}

double sigma_z_not_intermediate_radius(const AxisymmetricTunnelResult& result) {
    double radius = 0.0;
    for (std::size_t i = 0; i < result.r.size(); ++i) {
        if (!result.yielding[i]) continue;
        const double lo = std::min(result.sigma_r[i], result.sigma_theta[i]);
        const double hi = std::max(result.sigma_r[i], result.sigma_theta[i]);
        const double tie = 1e-9 * (std::fabs(hi) + std::fabs(lo));  // on the edge σz = σθ to roundoff
        const double sz = result.sigma_z[i];
        if (sz >= hi - tie || sz <= lo + tie) radius = std::max(radius, result.r[i]);
    }
    return radius;
}

SalenconClosedForm salencon_closed_form(const AxisymmetricTunnelSpec& spec) {
    const double E = spec.young_modulus, nu = spec.poisson_ratio, G = E / (2 * (1 + nu));
    const double P0 = spec.P0, Pi = spec.Pi, a = spec.a;
    const double sp = std::sin(spec.friction_angle), ss = std::sin(spec.dilation_angle);
    const double Kp = (1 + sp) / (1 - sp), Kpsi = (1 + ss) / (1 - ss);
    const double q = 2 * spec.cohesion * std::cos(spec.friction_angle) / (1 - sp);  // 2c tan(45° + φ/2)
    const double Q = q / (Kp - 1), A = Pi + Q;
    const double sigma_re = (2 * P0 - q) / (Kp + 1);
    const double R0 = a * std::pow((sigma_re + Q) / A, 1 / (Kp - 1));
    if (R0 <= a) return {a, (P0 - Pi) * a / (2 * G)};  // elastic

    // Plastic zone, σr = A (r/a)^(Kp−1) − Q, σθ = Kp σr + q, εz = εz^p = 0 (σz intermediate):
    // the flow rule gives εr^p + Kψ εθ^p = 0, so (r^Kψ u)' = r^Kψ (εr^e + Kψ εθ^e) with the
    // plane-strain elastic strains of the stress change, α + β (r/a)^(Kp−1) (tension positive).
    const double C1 = (1 - nu * nu) / E, C2 = nu * (1 + nu) / E;
    const double alpha = (1 + Kpsi) * (C1 - C2) * (P0 + Q);
    const double beta = A * (C2 * (Kp + Kpsi) - C1 * (1 + Kpsi * Kp));
    const double integral = alpha * (std::pow(R0, Kpsi + 1) - std::pow(a, Kpsi + 1)) / (Kpsi + 1) +
                            beta * std::pow(a, 1 - Kp) * (std::pow(R0, Kpsi + Kp) - std::pow(a, Kpsi + Kp)) / (Kpsi + Kp);
    const double u_R0 = -(P0 - sigma_re) * R0 / (2 * G);  // elastic zone, outward
    const double u_a = (std::pow(R0, Kpsi) * u_R0 - integral) / std::pow(a, Kpsi);
    return {R0, -u_a};
}

double lame_wall_displacement(const AxisymmetricTunnelSpec& spec) {
    const double E = spec.young_modulus, nu = spec.poisson_ratio;
    const double G = E / (2 * (1 + nu)), lambda_plus_G = E / (2 * (1 + nu) * (1 - 2 * nu));
    const double a = spec.a, b = spec.b;
    const double dp = spec.Pi - spec.P0;  // change of the inner pressure (compression positive)
    if (spec.outer == OuterBoundary::Traction)
        return -dp * a * (1 + nu) / E * ((1 - 2 * nu) * a * a + b * b) / (b * b - a * a);
    // u = A r + B/r with u(b) = 0 and σr(a) = −dp (tension positive).
    const double B = dp / (2 * lambda_plus_G / (b * b) + 2 * G / (a * a));
    return -B * (1 / a - a / (b * b));
}

}  // namespace mcdda::test

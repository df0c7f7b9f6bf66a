#include "HoekBrownTunnel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace mcdda::test {

namespace {

double shear_modulus(const HoekBrownTunnelSpec& spec) { return spec.young_modulus / (2 * (1 + spec.poisson_ratio)); }

double k_psi(const HoekBrownTunnelSpec& spec) {
    return (1 + std::sin(spec.dilation_angle)) / (1 - std::sin(spec.dilation_angle));
}

void check(const HoekBrownTunnelSpec& spec) {
    const bool valid = spec.radius > 0 && spec.young_modulus > 0 && spec.poisson_ratio > -1 && spec.poisson_ratio < 0.5 &&
                       spec.sigma_ci > 0 && spec.mb > 0 && spec.s >= 0 && spec.a > 0 && spec.a <= 1 &&
                       spec.dilation_angle >= 0 && spec.dilation_angle < M_PI / 2 && spec.pi <= spec.p0 &&
                       spec.pi >= -spec.s * spec.sigma_ci / spec.mb;
    if (!valid) throw std::invalid_argument("Hoek–Brown tunnel: spec out of range");
}

/// σθ − σr on the yield surface: σci (mb σr/σci + s)^a.
double strength(const HoekBrownTunnelSpec& spec, double sigma_r) {
    return spec.sigma_ci * std::pow(std::max(spec.mb * sigma_r / spec.sigma_ci + spec.s, 0.0), spec.a);
}

}  // namespace

HoekBrownTunnelSolution carranza_torres_fairhurst(const HoekBrownTunnelSpec& spec) {
    check(spec);
    if (spec.a != 0.5) throw std::invalid_argument("carranza_torres_fairhurst: the closed form needs a = 1/2");
    const double scale = spec.mb * spec.sigma_ci, shift = spec.s / (spec.mb * spec.mb);
    const double G = shear_modulus(spec), nu = spec.poisson_ratio, K = k_psi(spec), R = spec.radius;
    // Scaled in-situ stress and internal pressure, S0 = σ0/(mb σci) + s/mb², Pi likewise.
    const double S0 = spec.p0 / scale + shift, Pi = spec.pi / scale + shift;
    // At the elastic–plastic boundary σθ + σr = 2 σ0 and Sθ = Sr + √Sr: 2 Sr + √Sr = 2 S0, so
    // Pi_cr = [1 − √(1 + 16 S0)]²/16, and pi_cr = (Pi_cr − s/mb²) mb σci.
    const double root = 1 - std::sqrt(1 + 16 * S0);
    const double Pcr = root * root / 16;
    HoekBrownTunnelSolution out;
    out.critical_pressure = (Pcr - shift) * scale;
    if (spec.pi >= out.critical_pressure) {  // elastic: Lamé for the infinite medium
        out.plastic_radius = R;
        out.wall_displacement = (spec.p0 - spec.pi) * R / (2 * G);
        return out;
    }
    // Plastic zone: dSr/dr = √Sr / r, so √Sr = √Pi + ln(r/R)/2 and R_pl = R exp[2(√Pi_cr − √Pi)].
    const double L = 2 * (std::sqrt(Pcr) - std::sqrt(Pi));  // ln(R_pl/R)
    out.plastic_radius = R * std::exp(L);
    // Wall displacement (Carranza-Torres & Fairhurst 1999; restated in their convergence-
    // confinement paper, Tunn. Undergr. Space Technol. 15 (2000) 187–213):
    //   2G/(σ0 − pi_cr) · u/R = (Kψ − 1)/(Kψ + 1) + 2/(Kψ + 1) (R_pl/R)^(Kψ+1)
    //     + (1 − 2ν)/(4 (S0 − Pi_cr)) ln²(R_pl/R)
    //     − [ (1 − 2ν)/(Kψ + 1) √Pi_cr/(S0 − Pi_cr) + (1 − ν)/2 (Kψ − 1)/(Kψ + 1)² /(S0 − Pi_cr) ]
    //       · [ (Kψ + 1) ln(R_pl/R) − (R_pl/R)^(Kψ+1) + 1 ].
    // It is the integral of the flow rule with the plane-strain elastic strains of the stress
    // change (checked symbolically; (b) integrates the same equations numerically).
    const double gap = S0 - Pcr, power = std::exp((K + 1) * L);
    const double bracket = (1 - 2 * nu) / (K + 1) * std::sqrt(Pcr) / gap + (1 - nu) / 2 * (K - 1) / ((K + 1) * (K + 1)) / gap;
    const double scaled = (K - 1) / (K + 1) + 2 / (K + 1) * power + (1 - 2 * nu) / (4 * gap) * L * L -
                          bracket * ((K + 1) * L - power + 1);
    out.wall_displacement = scaled * (spec.p0 - out.critical_pressure) * R / (2 * G);
    return out;
}

HoekBrownTunnelStresses carranza_torres_fairhurst_stresses(const HoekBrownTunnelSpec& spec, double r) {
    const HoekBrownTunnelSolution solution = carranza_torres_fairhurst(spec);
    const double scale = spec.mb * spec.sigma_ci, shift = spec.s / (spec.mb * spec.mb);
    if (r >= solution.plastic_radius) {  // elastic zone: σ0 ∓ (σ0 − pcr)(R_pl/r)²
        const double boundary = solution.plastic_radius > spec.radius ? solution.critical_pressure : spec.pi;
        const double change = (spec.p0 - boundary) * std::pow(solution.plastic_radius / r, 2);
        return {spec.p0 - change, spec.p0 + change};
    }
    const double root = std::sqrt(spec.pi / scale + shift) + 0.5 * std::log(r / spec.radius);  // √Sr
    return {(root * root - shift) * scale, (root * root + root - shift) * scale};
}

double hoek_brown_critical_pressure(const HoekBrownTunnelSpec& spec) {
    check(spec);
    // 2 (p0 − σ) falls and σci (mb σ/σci + s)^a rises on [−s σci/mb, p0]; their difference changes
    // sign there once. Bisection to the resolution of doubles.
    double lo = -spec.s * spec.sigma_ci / spec.mb, hi = spec.p0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (2 * (spec.p0 - mid) > strength(spec, mid) ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

HoekBrownTunnelSolution hoek_brown_tunnel_integration(const HoekBrownTunnelSpec& spec, int steps,
                                                      HoekBrownTunnelProfile* profile) {
    check(spec);
    if (steps < 1) throw std::invalid_argument("hoek_brown_tunnel_integration: steps < 1");
    const double G = shear_modulus(spec), nu = spec.poisson_ratio, K = k_psi(spec), R = spec.radius, p0 = spec.p0;
    if (profile) *profile = {};
    HoekBrownTunnelSolution out;
    out.critical_pressure = hoek_brown_critical_pressure(spec);
    if (spec.pi >= out.critical_pressure) {  // elastic: Lamé for the infinite medium
        out.plastic_radius = R;
        out.wall_displacement = (p0 - spec.pi) * R / (2 * G);
        return out;
    }

    // Stresses, t = ln(r/R): dσr/dt = σθ − σr = σci (mb σr/σci + s)^a, from σr(0) = pi outward
    // until σr = σre. The last step is shortened (by bisection on its length) to land on σre.
    auto rate = [&](double sigma_r) { return strength(spec, sigma_r); };
    auto rk4 = [&](double y, double h) {
        const double k1 = rate(y), k2 = rate(y + 0.5 * h * k1), k3 = rate(y + 0.5 * h * k2), k4 = rate(y + h * k3);
        return y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    };
    const double h = 1.0 / steps, sigma_re = out.critical_pressure;
    double t = 0.0, sigma = spec.pi;
    for (;;) {
        const double next = rk4(sigma, h);
        if (next >= sigma_re) break;
        sigma = next;
        t += h;
        if (t > 50) throw std::runtime_error("hoek_brown_tunnel_integration: no elastic–plastic boundary within e^50 R");
    }
    double lo = 0.0, hi = h;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (rk4(sigma, mid) < sigma_re ? lo : hi) = mid;
    }
    const double t_pl = t + 0.5 * (lo + hi);
    out.plastic_radius = R * std::exp(t_pl);

    // Displacement, inward u = r εθ (compression-positive strains εr = du/dr, εθ = u/r).
    // Compatibility dεθ/dt = εr − εθ, with the flow rule εr − εr^e = −Kψ (εθ − εθ^e) and the
    // plane-strain elastic strains of the stress change (εz = εz^p = 0):
    //   εr^e = [(1 − ν) Δσr − ν Δσθ]/2G,  εθ^e = [(1 − ν) Δσθ − ν Δσr]/2G,  Δσ = σ − p0,
    // so dεθ/dt = εr^e + Kψ εθ^e − (1 + Kψ) εθ. From the elastic zone's εθ(R_pl) = (p0 − σre)/2G
    // inward to the wall, together with σr (back from σre), in equal steps of ln r.
    const int n = std::max(1, static_cast<int>(std::ceil(t_pl * steps)));
    const double dt = -t_pl / n;
    using State = std::array<double, 2>;  // σr, εθ
    auto derivative = [&](const State& y) -> State {
        const double dr = y[0] - p0, dtheta = y[0] + strength(spec, y[0]) - p0;
        const double er = ((1 - nu) * dr - nu * dtheta) / (2 * G), et = ((1 - nu) * dtheta - nu * dr) / (2 * G);
        return {strength(spec, y[0]), er + K * et - (1 + K) * y[1]};
    };
    auto axpy = [](const State& y, double c, const State& k) { return State{y[0] + c * k[0], y[1] + c * k[1]}; };
    State y{sigma_re, (p0 - sigma_re) / (2 * G)};
    auto record = [&](int i, const State& state) {
        if (!profile) return;
        const double r = R * std::exp(t_pl + i * dt);
        profile->r.push_back(r);
        profile->sigma_r.push_back(state[0]);
        profile->sigma_theta.push_back(state[0] + strength(spec, state[0]));
        profile->displacement.push_back(r * state[1]);
    };
    record(0, y);
    for (int i = 1; i <= n; ++i) {
        const State k1 = derivative(y), k2 = derivative(axpy(y, 0.5 * dt, k1)), k3 = derivative(axpy(y, 0.5 * dt, k2)),
                    k4 = derivative(axpy(y, dt, k3));
        for (int j = 0; j < 2; ++j) y[j] += dt / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
        record(i, y);
    }
    out.wall_displacement = R * y[1];
    if (profile) {  // from the wall outward
        std::reverse(profile->r.begin(), profile->r.end());
        std::reverse(profile->sigma_r.begin(), profile->sigma_r.end());
        std::reverse(profile->sigma_theta.begin(), profile->sigma_theta.end());
        std::reverse(profile->displacement.begin(), profile->displacement.end());
        profile->r.front() = R;  // exactly, not exp(t_pl − t_pl)
    }
    return out;
}

}  // namespace mcdda::test

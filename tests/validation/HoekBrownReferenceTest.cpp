// The two Hoek–Brown tunnel references (HoekBrownTunnel.hpp) against each other and against
// quadratures: (b), the radial integration, reproduces (a), the closed form of Carranza-Torres &
// Fairhurst (1999), for a = 1/2; for general a its plastic radius is the exact integral of the
// equilibrium equation and its wall displacement a quadrature of the flow rule in σr; without
// yield both are Lamé's.

#include "HoekBrownTunnel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace mcdda::test;

namespace {

const double deg = M_PI / 180.0;

/// The a = 1/2 cases: the default rock mass (GSI 50, mi 10 with a rounded), with dilation and a
/// support pressure, a very weak mass with a large plastic zone, and a strong one barely yielding.
std::vector<HoekBrownTunnelSpec> half_power_cases() {
    std::vector<HoekBrownTunnelSpec> cases(5);
    cases[1].dilation_angle = 30 * deg;
    cases[1].poisson_ratio = 0.3;
    cases[1].pi = 1e6;
    cases[2].sigma_ci = 20e6;
    cases[2].mb = 0.5;
    cases[2].s = 0.0005;
    cases[2].p0 = 20e6;
    cases[2].dilation_angle = 10 * deg;
    cases[3].sigma_ci = 100e6;
    cases[3].mb = 10;
    cases[3].s = 1;
    cases[3].p0 = 60e6;
    cases[3].radius = 3.0;
    cases[4].poisson_ratio = 0.0;  // ν = 0 and Kψ = 3 (ψ = 30°) exercise every term of the closed form
    cases[4].dilation_angle = 30 * deg;
    cases[4].p0 = 25e6;
    return cases;
}

double lame(const HoekBrownTunnelSpec& spec) {
    return (spec.p0 - spec.pi) * spec.radius * 2 * (1 + spec.poisson_ratio) / (2 * spec.young_modulus);
}

/// ln(R_pl/R) = ∫ dσ / σci (mb σ/σci + s)^a from pi to σre = [x^(1−a)]/(mb (1 − a)), x = mb σ/σci + s.
double log_plastic_radius(const HoekBrownTunnelSpec& spec, double sigma_re, double sigma) {
    auto x = [&](double v) { return std::pow(spec.mb * v / spec.sigma_ci + spec.s, 1 - spec.a); };
    return (x(sigma_re) - x(sigma)) / (spec.mb * (1 - spec.a));
}

/// The wall displacement by Simpson's rule in σr (not in r): with (r^Kψ u)' = r^Kψ (εr^e + Kψ εθ^e)
/// and dr = r dσ / (σθ − σr), u(R) R^Kψ = R_pl^Kψ u(R_pl) − ∫ r^(Kψ+1) (εr^e + Kψ εθ^e)/(σθ − σr) dσ,
/// r(σ) from the exact ln(r/R) above.
double wall_displacement_by_quadrature(const HoekBrownTunnelSpec& spec, double sigma_re) {
    const double G = spec.young_modulus / (2 * (1 + spec.poisson_ratio)), nu = spec.poisson_ratio;
    const double K = (1 + std::sin(spec.dilation_angle)) / (1 - std::sin(spec.dilation_angle)), R = spec.radius;
    auto integrand = [&](double sigma) {
        const double strength = spec.sigma_ci * std::pow(spec.mb * sigma / spec.sigma_ci + spec.s, spec.a);
        const double r = R * std::exp(log_plastic_radius(spec, sigma, spec.pi));
        const double dr = sigma - spec.p0, dtheta = sigma + strength - spec.p0;
        const double elastic = ((1 - nu) * dr - nu * dtheta + K * ((1 - nu) * dtheta - nu * dr)) / (2 * G);
        return std::pow(r, K + 1) * elastic / strength;
    };
    const int n = 20000;  // even
    const double h = (sigma_re - spec.pi) / n;
    double sum = integrand(spec.pi) + integrand(sigma_re);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * integrand(spec.pi + i * h);
    const double integral = sum * h / 3;
    const double R_pl = R * std::exp(log_plastic_radius(spec, sigma_re, spec.pi));
    return (std::pow(R_pl, K) * (spec.p0 - sigma_re) * R_pl / (2 * G) - integral) / std::pow(R, K);
}

}  // namespace

TEST(HoekBrownReference, CriticalPressureByBisectionIsTheClosedForm) {
    for (const HoekBrownTunnelSpec& spec : half_power_cases()) {
        const double closed = carranza_torres_fairhurst(spec).critical_pressure;
        EXPECT_NEAR(hoek_brown_critical_pressure(spec), closed, 1e-12 * spec.p0);
        // On the yield surface at the boundary, σθ = 2 p0 − σre.
        const double theta = 2 * spec.p0 - closed;
        EXPECT_NEAR(theta - closed, spec.sigma_ci * std::sqrt(spec.mb * closed / spec.sigma_ci + spec.s), 1e-9 * spec.p0);
    }
}

TEST(HoekBrownReference, IntegrationReproducesCarranzaTorresFairhurst) {
    // The brief's bound is 0.1 %; the two agree to RK4's accuracy (about 1e-12), asserted to 1e-6.
    int k = 0;
    for (const HoekBrownTunnelSpec& spec : half_power_cases()) {
        const HoekBrownTunnelSolution closed = carranza_torres_fairhurst(spec);
        HoekBrownTunnelProfile profile;
        const HoekBrownTunnelSolution integrated = hoek_brown_tunnel_integration(spec, 2000, &profile);
        std::printf("case %d: pi_cr = %.6f MPa, R_pl/R = %.8f (closed form %.8f, %+.2e), u = %.6f mm (closed form "
                    "%.6f, %+.2e)\n",
                    k++, 1e-6 * closed.critical_pressure, integrated.plastic_radius / spec.radius,
                    closed.plastic_radius / spec.radius, integrated.plastic_radius / closed.plastic_radius - 1,
                    1e3 * integrated.wall_displacement, 1e3 * closed.wall_displacement,
                    integrated.wall_displacement / closed.wall_displacement - 1);
        ASSERT_GT(closed.plastic_radius, 1.02 * spec.radius);  // every case yields
        EXPECT_NEAR(integrated.plastic_radius, closed.plastic_radius, 1e-6 * closed.plastic_radius);
        EXPECT_NEAR(integrated.wall_displacement, closed.wall_displacement, 1e-6 * closed.wall_displacement);
        // More than the elastic displacement (the plastic zone adds to it).
        EXPECT_GT(closed.wall_displacement, lame(spec));
        // The stress profile of the plastic zone, and back at the wall the support pressure.
        ASSERT_GT(profile.r.size(), 10u);
        EXPECT_EQ(profile.r.front(), spec.radius);
        EXPECT_NEAR(profile.sigma_r.front(), spec.pi, 1e-9 * spec.p0);
        EXPECT_NEAR(profile.displacement.front(), integrated.wall_displacement, 1e-15);
        for (std::size_t i = 0; i < profile.r.size(); i += profile.r.size() / 10) {
            const HoekBrownTunnelStresses s = carranza_torres_fairhurst_stresses(spec, profile.r[i]);
            EXPECT_NEAR(profile.sigma_r[i], s.sigma_r, 1e-9 * spec.p0);
            EXPECT_NEAR(profile.sigma_theta[i], s.sigma_theta, 1e-9 * spec.p0);
        }
        // The closed form's stresses are continuous at R_pl.
        const HoekBrownTunnelStresses in = carranza_torres_fairhurst_stresses(spec, closed.plastic_radius * (1 - 1e-12));
        const HoekBrownTunnelStresses out = carranza_torres_fairhurst_stresses(spec, closed.plastic_radius);
        EXPECT_NEAR(in.sigma_r, out.sigma_r, 1e-6 * spec.p0);
        EXPECT_NEAR(in.sigma_theta, out.sigma_theta, 1e-6 * spec.p0);
    }
}

TEST(HoekBrownReference, GeneralPowerAgainstQuadratures) {
    // a from GSI: 30 (a = 0.522), 10 (a = 0.584) and a mass at a = 0.65.
    struct Case {
        double mb, s, a, p0, psi;
    };
    for (const Case& c : {Case{1.1, 0.0004, 0.5223, 15e6, 0}, Case{0.55, 4.5e-5, 0.5843, 10e6, 20 * deg},
                          Case{0.3, 1e-5, 0.65, 8e6, 5 * deg}}) {
        HoekBrownTunnelSpec spec;
        spec.mb = c.mb;
        spec.s = c.s;
        spec.a = c.a;
        spec.p0 = c.p0;
        spec.dilation_angle = c.psi;
        spec.pi = 0.5e6;
        const HoekBrownTunnelSolution fine = hoek_brown_tunnel_integration(spec, 2000);
        const double sigma_re = fine.critical_pressure;
        ASSERT_GT(sigma_re, spec.pi);
        const double R_pl = spec.radius * std::exp(log_plastic_radius(spec, sigma_re, spec.pi));
        const double u = wall_displacement_by_quadrature(spec, sigma_re);
        std::printf("a = %.4f: R_pl/R = %.8f (integral %.8f, %+.2e), u = %.6f mm (quadrature %.6f, %+.2e)\n", spec.a,
                    fine.plastic_radius / spec.radius, R_pl / spec.radius, fine.plastic_radius / R_pl - 1,
                    1e3 * fine.wall_displacement, 1e3 * u, fine.wall_displacement / u - 1);
        EXPECT_NEAR(fine.plastic_radius, R_pl, 1e-9 * R_pl);
        EXPECT_NEAR(fine.wall_displacement, u, 1e-8 * u);
        // Converged in the step: a tenth of the steps changes nothing that matters.
        const HoekBrownTunnelSolution coarse = hoek_brown_tunnel_integration(spec, 200);
        EXPECT_NEAR(coarse.wall_displacement, fine.wall_displacement, 1e-8 * fine.wall_displacement);
        // The yield condition at the boundary.
        EXPECT_NEAR(2 * (spec.p0 - sigma_re), spec.sigma_ci * std::pow(spec.mb * sigma_re / spec.sigma_ci + spec.s, spec.a),
                    1e-9 * spec.p0);
    }
    HoekBrownTunnelSpec not_half;
    not_half.a = 0.55;
    EXPECT_THROW(carranza_torres_fairhurst(not_half), std::invalid_argument);
}

TEST(HoekBrownReference, WithoutYieldBothAreLame) {
    // A low in-situ stress (σre < pi: nothing yields) gives Lamé's u = (p0 − pi) R/2G exactly,
    // for a = 1/2 and for general a.
    for (double a : {0.5, 0.55}) {
        HoekBrownTunnelSpec spec;
        spec.p0 = 1e6;
        spec.pi = 0.2e6;
        spec.a = a;
        const HoekBrownTunnelSolution integrated = hoek_brown_tunnel_integration(spec);
        EXPECT_LT(integrated.critical_pressure, spec.pi);
        EXPECT_EQ(integrated.plastic_radius, spec.radius);
        EXPECT_EQ(integrated.wall_displacement, lame(spec));
        if (a == 0.5) {
            const HoekBrownTunnelSolution closed = carranza_torres_fairhurst(spec);
            EXPECT_EQ(closed.plastic_radius, spec.radius);
            EXPECT_EQ(closed.wall_displacement, lame(spec));
            const HoekBrownTunnelStresses wall = carranza_torres_fairhurst_stresses(spec, spec.radius);
            EXPECT_DOUBLE_EQ(wall.sigma_r, spec.pi);
            EXPECT_DOUBLE_EQ(wall.sigma_theta, 2 * spec.p0 - spec.pi);
        }
    }
    // Just below the critical pressure both solutions leave Lamé's continuously.
    HoekBrownTunnelSpec spec;
    spec.pi = carranza_torres_fairhurst(spec).critical_pressure * (1 - 1e-9);
    for (const HoekBrownTunnelSolution& s : {carranza_torres_fairhurst(spec), hoek_brown_tunnel_integration(spec)}) {
        EXPECT_NEAR(s.plastic_radius, spec.radius, 1e-6 * spec.radius);
        EXPECT_NEAR(s.wall_displacement, lame(spec), 1e-6 * lame(spec));
    }
}

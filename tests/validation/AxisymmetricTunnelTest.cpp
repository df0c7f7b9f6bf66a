// The 1-D axisymmetric reference for the Salençon tunnel (AxisymmetricTunnel.hpp): checked against
// Lamé (elastic) and against Salençon's closed form where its assumption (σz intermediate) holds;
// then the σz-aware references for the 2-D tests (paper's case, σz0 = P0).

#include "AxisymmetricTunnel.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace mcdda::test;

namespace {

const double deg = M_PI / 180.0;

AxisymmetricTunnelResult solve_timed(const AxisymmetricTunnelSpec& spec, double* seconds = nullptr) {
    const auto start = std::chrono::steady_clock::now();
    AxisymmetricTunnelResult result = solve_axisymmetric_tunnel(spec);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds) *seconds = s;
    return result;
}

const char* name(OuterBoundary o) { return o == OuterBoundary::Traction ? "traction" : "u(b)=0"; }

}  // namespace

// (a) Elastic: the wall displacement is Lamé's for either outer boundary.
TEST(AxisymmetricTunnel, ElasticMatchesLame) {
    for (OuterBoundary outer : {OuterBoundary::Traction, OuterBoundary::Fixed}) {
        AxisymmetricTunnelSpec spec;
        spec.cohesion = 1e12;
        spec.outer = outer;
        spec.increments = 5;
        const auto result = solve_timed(spec);
        const double lame = lame_wall_displacement(spec);
        std::printf("elastic, %s: u(a) = %.6f mm, Lamé %.6f mm\n", name(outer), 1e3 * result.wall_displacement,
                    1e3 * lame);
        EXPECT_NEAR(result.wall_displacement, lame, 1e-4 * lame);
        EXPECT_EQ(result.plastic_radius, spec.a);
    }
}

// (b) With σz0 = 5 MPa σz stays intermediate in the plastic zone (ψ = 0 or ψ = φ: εz^p = 0, so
// σz = σz0 + ν(Δσr + Δσθ), which lies between σr and σθ for σz0 in [σre, (1 − ν)q + 2νP0] =
// [4.57, 5.39] MPa); b = 200 m approximates the infinite medium. Closed form: R0 from Salençon,
// u(a) from the elastic zone's u(R0) plus the flow rule εr^p + Kψ εθ^p = 0 integrated exactly
// over the plastic zone (salencon_closed_form; 11.65 mm for ψ = 0 as in the paper).
TEST(AxisymmetricTunnel, SigmaZIntermediateMatchesSalencon) {
    for (double psi : {0.0, 30.0}) {
        AxisymmetricTunnelSpec spec;
        spec.sigma_z0 = 5e6;
        spec.b = 200.0;
        spec.dilation_angle = psi * deg;
        double seconds = 0.0;
        const auto result = solve_timed(spec, &seconds);
        const auto closed = salencon_closed_form(spec);
        std::printf("σz0 = 5 MPa, b = 200 m, ψ = %g°: R0 = %.4f m (closed form %.4f, %+.3f %%), u(a) = %.4f mm "
                    "(closed form %.4f, %+.3f %%), σz not intermediate up to r = %g m, %d Newton iterations, %.2f s\n",
                    psi, result.plastic_radius, closed.plastic_radius,
                    100 * (result.plastic_radius / closed.plastic_radius - 1), 1e3 * result.wall_displacement,
                    1e3 * closed.wall_displacement, 100 * (result.wall_displacement / closed.wall_displacement - 1),
                    sigma_z_not_intermediate_radius(result), result.newton_iterations, seconds);
        EXPECT_EQ(sigma_z_not_intermediate_radius(result), 0.0);
        EXPECT_NEAR(result.plastic_radius, closed.plastic_radius, 0.005 * closed.plastic_radius);
        EXPECT_NEAR(result.wall_displacement, closed.wall_displacement, 0.01 * closed.wall_displacement);
        if (psi == 0.0) {
            EXPECT_NEAR(closed.plastic_radius, 2.505, 0.001);
            EXPECT_NEAR(closed.wall_displacement, 11.65e-3, 0.005e-3);
        }
    }
}

// (c) The paper's case, σz0 = P0: σz is the major principal stress (tied with σθ, on an edge of
// the yield surface) near the wall. The in-plane stresses, and so R0, are Salençon's; the
// displacement is not. Converged in the mesh (1000 vs 2000 elements) and the increments.
// The edge reaches out to where σz = P0 + ν(Δσr + Δσθ) of the plane return meets σθ:
// σr = (P0(1 − 2ν) − (1 − ν)q) / (Kp − ν(1 + Kp)) = 2.097 MPa, r = 1.850 m, whatever b.
TEST(AxisymmetricTunnel, PaperCaseConvergesAndKeepsPlasticRadius) {
    const AxisymmetricTunnelSpec paper;
    const double sp = std::sin(paper.friction_angle), nu = paper.poisson_ratio;
    const double Kp = (1 + sp) / (1 - sp), q = 2 * paper.cohesion * std::cos(paper.friction_angle) / (1 - sp);
    const double sigma_edge = (paper.P0 * (1 - 2 * nu) - (1 - nu) * q) / (Kp - nu * (1 + Kp));
    const double r_edge = paper.a * std::sqrt((sigma_edge + q / (Kp - 1)) / (q / (Kp - 1)));
    for (double b : {20.0, 40.0}) {
        AxisymmetricTunnelSpec spec;
        spec.b = b;
        double seconds = 0.0;
        const auto fine = solve_timed(spec, &seconds);
        spec.elements = 1000;
        const auto coarse = solve_timed(spec);
        spec.elements = 2000;
        spec.increments = 200;
        const auto more_steps = solve_timed(spec);
        std::printf("paper case, b = %g m, traction: u(a) = %.4f mm (1000 elements %.4f, 200 increments %.4f), "
                    "R0 = %.4f m (1000 elements %.4f), σz not intermediate up to r = %.3f m (expected %.3f), "
                    "%d Newton iterations, %.2f s\n",
                    b, 1e3 * fine.wall_displacement, 1e3 * coarse.wall_displacement,
                    1e3 * more_steps.wall_displacement, fine.plastic_radius, coarse.plastic_radius,
                    sigma_z_not_intermediate_radius(fine), r_edge, fine.newton_iterations, seconds);
        EXPECT_NEAR(coarse.wall_displacement, fine.wall_displacement, 1e-3 * fine.wall_displacement);
        EXPECT_NEAR(coarse.plastic_radius, fine.plastic_radius, 1e-3 * fine.plastic_radius);
        EXPECT_NEAR(more_steps.wall_displacement, fine.wall_displacement, 1e-3 * fine.wall_displacement);
        EXPECT_NEAR(fine.plastic_radius, 2.505, 0.02 * 2.505);
        EXPECT_NEAR(sigma_z_not_intermediate_radius(fine), r_edge, 0.005 * r_edge);
    }
}

// (d) Dilatant, ψ = φ = 30°: the closed-form R0 does not depend on ψ.
TEST(AxisymmetricTunnel, DilatantPaperCaseKeepsPlasticRadius) {
    AxisymmetricTunnelSpec spec;
    spec.dilation_angle = 30.0 * deg;
    double seconds = 0.0;
    const auto result = solve_timed(spec, &seconds);
    const auto closed = salencon_closed_form(spec);
    std::printf("paper case ψ = 30°, b = 20 m, traction: u(a) = %.4f mm (closed form, σz intermediate, infinite "
                "medium: %.4f), R0 = %.4f m (%.4f), σz not intermediate up to r = %.3f m, %.2f s\n",
                1e3 * result.wall_displacement, 1e3 * closed.wall_displacement, result.plastic_radius,
                closed.plastic_radius, sigma_z_not_intermediate_radius(result), seconds);
    EXPECT_NEAR(result.plastic_radius, 2.505, 0.02 * 2.505);
}

// The references for the 2-D tests (20 m square quarter, outer edges loaded by P0: its boundary
// lies between the circles of 20 m and 28 m, so traction at b = 20 m and 40 m brackets it).
TEST(AxisymmetricTunnel, ReferenceTable) {
    std::printf("\nσz-aware references (σz0 = P0 = 10 MPa, 2000 elements, 100 increments):\n");
    std::printf("  %-9s %6s %6s %12s %10s %16s\n", "outer", "b (m)", "ψ (°)", "u(a) (mm)", "R0 (m)", "σz edge to (m)");
    for (OuterBoundary outer : {OuterBoundary::Traction, OuterBoundary::Fixed})
        for (double b : {20.0, 40.0})
            for (double psi : {0.0, 30.0}) {
                AxisymmetricTunnelSpec spec;
                spec.b = b;
                spec.outer = outer;
                spec.dilation_angle = psi * deg;
                const auto result = solve_timed(spec);
                std::printf("  %-9s %6g %6g %12.4f %10.4f %16.3f\n", name(outer), b, psi,
                            1e3 * result.wall_displacement, result.plastic_radius,
                            sigma_z_not_intermediate_radius(result));
                EXPECT_NEAR(result.plastic_radius, 2.505, 0.02 * 2.505);
            }
    AxisymmetricTunnelSpec spec;
    const auto closed0 = salencon_closed_form(spec);
    spec.dilation_angle = 30.0 * deg;
    const auto closed30 = salencon_closed_form(spec);
    std::printf("  Salençon closed form (σz intermediate, infinite medium): R0 = %.4f m, u(a) = %.4f mm (ψ = 0), "
                "%.4f mm (ψ = 30°)\n\n",
                closed0.plastic_radius, 1e3 * closed0.wall_displacement, 1e3 * closed30.wall_displacement);
}

// A circular tunnel in a Hoek–Brown rock mass through the whole solver (examples/hoek-brown-tunnel.json:
// quarter model, R = 1 m, p0 = 15 MPa, outer boundary at 50 m, σzz = 2ν p0, no support), against
// the references of HoekBrownTunnel.hpp: Carranza-Torres & Fairhurst's closed form for a = 1/2
// (GSI = 100) and the radial integration for a > 1/2 (GSI = 80). The plastic radius comes from the
// area of the yielded elements, the wall displacement from the springline and crown points.

#include "HoekBrownTunnel.hpp"
#include "RunModel.hpp"
#include "material/HoekBrown.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

using namespace mcdda;

namespace {

struct TunnelResult {
    double plastic_radius = 0.0, wall_displacement = 0.0;
};

/// Overrides that excavate gradually: a pressure on each of the wall's 64 segments starting at
/// p0 and falling linearly to 0 over `steps` steps (the far-field pressures kept).
std::vector<std::string> gradual_release(int steps) {
    std::string pressures = R"([{"name": "far field x", "from": [50, 0], "to": [50, 50], "pressure": 15e6},)"
                            R"( {"name": "far field y", "from": [0, 50], "to": [50, 50], "pressure": 15e6})";
    const int segments = 64;
    for (int k = 0; k < segments; ++k) {
        const double a0 = 0.5 * M_PI * k / segments, a1 = 0.5 * M_PI * (k + 1) / segments;
        char text[240];
        std::snprintf(text, sizeof text,
                      R"(, {"name": "wall %d", "from": [%.17g, %.17g], "to": [%.17g, %.17g], "pressure": 15e6, "table": "release"})",
                      k, std::cos(a0), std::sin(a0), std::cos(a1), std::sin(a1));
        pressures += text;
    }
    return {"/edge_pressures=" + pressures + "]",
            R"(/load_tables=[{"name": "release", "variable": "step", "points": [[0, 1], [)" + std::to_string(steps) + ", 0]]}]",
            "/analysis/steps=" + std::to_string(steps)};
}

TunnelResult run_tunnel(double gsi, double sigma_ci, std::vector<std::string> more = {}) {
    std::vector<std::string> overrides{"/materials/0/gsi=" + std::to_string(gsi),
                                       "/materials/0/uniaxial_strength=" + std::to_string(sigma_ci)};
    overrides.insert(overrides.end(), more.begin(), more.end());
    auto run = mcdda::test::run_example("hoek-brown-tunnel.json", overrides, more.empty() ? 3 : 0);
    EXPECT_TRUE(run.simulation);
    if (!run.simulation) return {};
    const Simulation& s = *run.simulation;
    double yielded_area = 0.0;  // a quarter annulus π/4 (R_pl² − R²)
    for (std::size_t e = 0; e < s.mesh().triangles.size(); ++e) {
        if (s.state().plastic_state[e] == 0) continue;
        const auto& t = s.mesh().triangles[e];
        const Point2 &p0 = s.mesh().nodes[t[0]], &p1 = s.mesh().nodes[t[1]], &p2 = s.mesh().nodes[t[2]];
        yielded_area += 0.5 * ((p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y));
    }
    const Point2 wall = run.history.points.back()[0], crown = run.history.points.back()[1];
    return {std::sqrt(1.0 + 4.0 * yielded_area / M_PI), 0.5 * (-wall.x - crown.y)};
}

mcdda::test::HoekBrownTunnelSpec spec_of(double gsi, double sigma_ci) {
    const HoekBrownParameters p = hoek_brown_parameters(gsi, 10.0, 0.0);
    mcdda::test::HoekBrownTunnelSpec spec;
    spec.p0 = 15e6;
    spec.sigma_ci = sigma_ci;
    spec.mb = p.mb;
    spec.s = p.s;
    spec.a = p.a;
    spec.young_modulus = 5e9;
    spec.poisson_ratio = 0.25;
    return spec;
}

/// The plastic radius and the wall displacement against the radial integration, within 2 %.
void expect_radial_integration(double gsi, double sigma_ci) {
    const auto reference = mcdda::test::hoek_brown_tunnel_integration(spec_of(gsi, sigma_ci));
    const TunnelResult fe = run_tunnel(gsi, sigma_ci);
    std::cout << "Hoek–Brown tunnel, GSI " << gsi << ": plastic radius " << fe.plastic_radius << " m (integration "
              << reference.plastic_radius << "), wall displacement " << fe.wall_displacement * 1e3 << " mm (integration "
              << reference.wall_displacement * 1e3 << ")\n";
    EXPECT_NEAR(fe.plastic_radius, reference.plastic_radius, 0.02 * reference.plastic_radius);
    EXPECT_NEAR(fe.wall_displacement, reference.wall_displacement, 0.02 * reference.wall_displacement);
}

}  // namespace

// GSI = 100 (a = 1/2, s = 1), σci = 3 MPa: Carranza-Torres & Fairhurst, within 1 %.
TEST(HoekBrownTunnel, IntactRockMatchesCarranzaTorresAndFairhurst) {
    const auto reference = mcdda::test::carranza_torres_fairhurst(spec_of(100, 3e6));
    const TunnelResult fe = run_tunnel(100, 3e6);
    std::cout << "Hoek–Brown tunnel, GSI 100: plastic radius " << fe.plastic_radius << " m (closed form "
              << reference.plastic_radius << "), wall displacement " << fe.wall_displacement * 1e3 << " mm (closed form "
              << reference.wall_displacement * 1e3 << ")\n";
    EXPECT_GT(reference.plastic_radius, 2.0);  // a plastic zone the mesh resolves
    EXPECT_NEAR(fe.plastic_radius, reference.plastic_radius, 0.01 * reference.plastic_radius);
    EXPECT_NEAR(fe.wall_displacement, reference.wall_displacement, 0.01 * reference.wall_displacement);
}


// GSI = 80 (a = 0.5006), σci = 6 MPa, as shipped.
TEST(HoekBrownTunnel, RockMassMatchesTheRadialIntegration) {
    ASSERT_GT(spec_of(80, 6e6).a, 0.5);
    expect_radial_integration(80, 6e6);
}

// GSI = 50 (a = 0.5057), σci = 20 MPa: a weak rock mass whose plastic zone reaches about 2.4
// radii. The wall elements are 1/60 of the far-field ones, so this needs the out-of-balance force
// measured as a stress (per length of its node): measured against the largest nodal force, far
// out, the iterations stopped at 22.0 mm with a ring of wall elements at the criterion's apex,
// out of balance by the apex's tension.
TEST(HoekBrownTunnel, WeakRockMassMatchesTheRadialIntegration) {
    ASSERT_GT(spec_of(50, 20e6).a, 0.505);
    expect_radial_integration(50, 20e6);
}

// The excavation released gradually through a falling wall pressure, over 10 and over 20 steps,
// ends where the single increment does (a curved surface makes plasticity path-dependent in
// general; here the unloading is monotonic and the result must not depend on the step count):
// the shipped rock mass (GSI 80) and the weak one (GSI 50, which released over 20 steps used to
// stop at a wall pressure of 0.23 MPa as a false collapse).
TEST(HoekBrownTunnel, GradualReleaseEndsWhereTheSingleIncrementDoes) {
    for (const auto& [gsi, sigma_ci] : {std::pair{80.0, 6e6}, std::pair{50.0, 20e6}}) {
        const auto reference = mcdda::test::hoek_brown_tunnel_integration(spec_of(gsi, sigma_ci));
        const TunnelResult at_once = run_tunnel(gsi, sigma_ci);
        for (int steps : {10, 20}) {
            const TunnelResult gradual = run_tunnel(gsi, sigma_ci, gradual_release(steps));
            std::cout << "Hoek–Brown tunnel, GSI " << gsi << ", released over " << steps << " steps: wall displacement "
                      << gradual.wall_displacement * 1e3 << " mm (at once " << at_once.wall_displacement * 1e3
                      << ", integration " << reference.wall_displacement * 1e3 << ")\n";
            EXPECT_NEAR(gradual.wall_displacement, at_once.wall_displacement, 0.005 * at_once.wall_displacement)
                << "GSI " << gsi << ", " << steps << " steps";
            EXPECT_NEAR(gradual.wall_displacement, reference.wall_displacement, 0.02 * reference.wall_displacement)
                << "GSI " << gsi << ", " << steps << " steps";
        }
    }
}

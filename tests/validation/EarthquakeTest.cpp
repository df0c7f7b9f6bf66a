// Earthquakes (docs/model-format.md, "Earthquakes") against closed forms:
//  - Newmark's (1965) sliding block: a block on an inclined joint on a rigid base shaken
//    horizontally; its permanent slip against the double integration of the relative motion,
//  - a shear pulse through an elastic column on a compliant base: arrival time H/Vs, doubling at
//    the free surface, and the pulse leaving through the base's dashpots,
//  - the pseudo-static planar wedge: F = (W cos α − kh W sin α) tan φ / (W sin α + kh W cos α).

#include "RunModel.hpp"

#include "material/Elasticity.hpp"
#include "io/ModelReader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace mcdda;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double g = 9.81;

/// The base acceleration of examples/records/sine-2hz-3-cycles.csv scaled to `amplitude` (g):
/// three cycles of a 2 Hz sine after 0.2 s at rest.
double sine_record(double t, double amplitude) {
    return t >= 0.2 && t <= 1.7 ? amplitude * g * std::sin(2.0 * pi * 2.0 * (t - 0.2)) : 0.0;
}

/// Newmark's sliding block: slip down an α joint of friction φ of a rigid block whose base
/// accelerates horizontally by a(t) (+x, the joint rising towards +x, so that a positive a drags
/// the base from under the block: down-slope). Integrated in both directions of sliding, with
/// the block stopping where its relative velocity changes sign. Returns the slip (m, down-slope).
double newmark_slip(double amplitude, double alpha, double phi, double duration) {
    const double dt = 1e-5, mu = std::tan(phi);
    double v = 0.0, x = 0.0;
    for (double t = 0.0; t < duration; t += dt) {
        const double a = sine_record(t + 0.5 * dt, amplitude);
        // Per unit mass: the inertial force −a (horizontal) and gravity, along the slope
        // (down-slope positive) and pressing on the joint.
        const double driving = a * std::cos(alpha) + g * std::sin(alpha);
        const double normal = g * std::cos(alpha) - a * std::sin(alpha);
        double acc = 0.0;
        if (v > 0.0) acc = driving - mu * normal;
        else if (v < 0.0) acc = driving + mu * normal;
        else if (driving > mu * normal) acc = driving - mu * normal;
        else if (driving < -mu * normal) acc = driving + mu * normal;
        double next = v + acc * dt;
        if ((v > 0.0 && next < 0.0) || (v < 0.0 && next > 0.0)) next = 0.0;  // it stops
        x += 0.5 * (v + next) * dt;
        v = next;
    }
    return x;
}

}  // namespace

TEST(Earthquake, NewmarkSlidingBlock) {
    const double alpha = 20.0 * pi / 180.0, phi = 30.0 * pi / 180.0;
    const Point2 down{-std::cos(alpha), -std::sin(alpha)};
    for (const double amplitude : {0.3, 0.5}) {
        std::ostringstream scale;
        scale << "/ground_motions/0/scale=" << amplitude;
        test::Run run = test::run_example("newmark-sliding-block.json", {scale.str()});
        ASSERT_TRUE(run.simulation);
        const test::History& h = run.history;
        // The block settles on its joint under gravity before the shaking starts at 0.2 s.
        const Point2 before = h.at(0.2, 0), after = h.points.back()[0];
        const double slip = (after.x - before.x) * down.x + (after.y - before.y) * down.y;
        const double expected = newmark_slip(amplitude, alpha, phi, h.time.back());
        EXPECT_GT(expected, 0.0);
        EXPECT_NEAR(slip, expected, 0.05 * expected) << "amplitude " << amplitude << " g";
        std::printf("Newmark sliding block, %.1f g: slip %.4f m, Newmark %.4f m (%+.2f %%)\n", amplitude, slip, expected,
                    100.0 * (slip / expected - 1.0));
        // The summary's permanent displacement is the same motion, relative to the base.
        const Eigen::VectorXd u = run.simulation->displacement_since_shaking();
        const int node = run.simulation->boundary_conditions().measurement_nodes.at(0);
        EXPECT_NEAR(std::hypot(u[2 * node], u[2 * node + 1]), std::hypot(after.x, after.y), 0.01 * std::fabs(expected));
    }
}

TEST(Earthquake, NewmarkSlidingBlockDoesNotDependOnTheTimeStep) {
    const double alpha = 20.0 * pi / 180.0, phi = 30.0 * pi / 180.0;
    const double expected = newmark_slip(0.3, alpha, phi, 2.2);
    // Half the time step (twice the steps): the record is sampled at 0.002 s, so finer is allowed.
    test::Run run = test::run_example("newmark-sliding-block.json", {"/analysis/time_step=0.001", "/analysis/steps=2200"});
    ASSERT_TRUE(run.simulation);
    const Point2 before = run.history.at(0.2, 0), after = run.history.points.back()[0];
    const double slip = -(after.x - before.x) * std::cos(alpha) - (after.y - before.y) * std::sin(alpha);
    EXPECT_NEAR(slip, expected, 0.05 * expected);
    std::printf("Newmark sliding block, 0.3 g, dt 0.001 s: slip %.4f m, Newmark %.4f m (%+.2f %%)\n", slip, expected,
                100.0 * (slip / expected - 1.0));
}

namespace {

// The column: H = 20 m, 1 m wide, Vs = 200 m/s (ρ = 2000 kg/m³, G = 80 MPa, ν = 0.25), on a
// compliant base; its sides held vertically so that it deforms in simple shear.
constexpr double column_height = 20.0, shear_speed = 200.0, density = 2000.0, poisson = 0.25;
constexpr double pulse = 0.04;       // s: v(t) = V0 sin²(π t / T), a wavelength of 8 m
constexpr double pulse_speed = 0.1;  // V0, m/s
constexpr double column_dt = 5e-4;
/// The energy the pulse carries in (per m thickness, the column 1 m wide): ρVs∫v²dt = ρVs·V0²·3T/8.
constexpr double pulse_energy = density * shear_speed * pulse_speed * pulse_speed * 3.0 * pulse / 8.0;

std::string column_model() {
    const double G = density * shear_speed * shear_speed, E = 2.0 * G * (1.0 + poisson);
    std::ostringstream points;
    points.precision(12);
    // The acceleration of the velocity pulse, dv/dt = V0 (π/T) sin(2π t/T), then rest.
    for (int k = 0; k <= 200; ++k) {
        const double t = k * column_dt;
        const double a = t <= pulse ? pulse_speed * pi / pulse * std::sin(2.0 * pi * t / pulse) : 0.0;
        points << (k ? ", " : "") << "[" << t << ", " << (std::fabs(a) < 1e-12 ? 0.0 : a) << "]";
    }
    std::ostringstream m;
    m.precision(12);
    m << R"({"format": "mcdda-model", "version": 2, "name": "shear column",
  "materials": [{"name": "soil", "law": "elastic", "young_modulus": )" << E << R"(, "poisson_ratio": 0.25, "density": 2000}],
  "regions": [{"name": "column", "material": "soil", "boundary": [[0, 0], [1, 0], [1, 20], [0, 20]]}],
  "rollers": [{"name": "left", "from": [0, 0], "to": [0, 20], "fixed": "y"}, {"name": "right", "from": [1, 0], "to": [1, 20], "fixed": "y"}],
  "measurement_points": [{"name": "surface", "point": [0.5, 20]}],
  "ground_motions": [{"name": "pulse", "points": [)" << points.str() << R"(], "units": "m/s2", "baseline_correction": false}],
  "base_motion": {"type": "compliant", "x": "pulse", "from": [0, 0], "to": [1, 0]},
  "mesh": {"size": 0.25, "element": "t6"},
  "analysis": {"type": "dynamic", "steps": 600, "time_step": 0.0005, "newmark_gamma": 0.5, "output_every": 100}})";
    return m.str();
}

/// Kinetic and strain energy of the model now (J per m thickness).
double energy(const Simulation& s) {
    const Mesh& mesh = s.mesh();
    const SimulationState& st = s.state();
    double kinetic = 0.0, strain = 0.0;
    const Material& m = s.model().materials.at(0);
    const Eigen::Matrix3d compliance = plane_strain_elasticity(m.young_modulus, m.poisson_ratio).inverse();
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const auto& t = mesh.triangles[e];
        const Point2 &a = mesh.nodes[t[0]], &b = mesh.nodes[t[1]], &c = mesh.nodes[t[2]];
        const double area = 0.5 * std::fabs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
        // Lumped on the six-node element's midside nodes (a third each, as its mass rows sum).
        for (int n : mesh.midside[e])
            kinetic += 0.5 * density * area / 3.0 * (st.velocity[2 * n] * st.velocity[2 * n] + st.velocity[2 * n + 1] * st.velocity[2 * n + 1]);
        const Eigen::Vector3d sigma = st.stress[e];
        strain += 0.5 * area * sigma.dot(compliance * sigma);
    }
    return kinetic + strain;
}

}  // namespace

namespace {

/// Runs the column with `overrides`; arrival time, surface peak velocity and the energy left
/// after the pulse has gone, against the most inside the column before it reached the surface.
struct ColumnResult {
    double arrival = 0.0, peak = 0.0, left = 0.0, most_energy = 0.0;
};

ColumnResult run_column(const std::vector<std::string>& overrides) {
    ColumnResult r;
    ReadResult read = read_model_text(column_model(), overrides);
    EXPECT_TRUE(read.model) << (read.diagnostics.empty() ? "" : format_diagnostic(read.diagnostics.front()));
    if (!read.model) return r;
    const Preprocessed p = preprocess_model(*read.model);
    EXPECT_TRUE(p.ok);
    if (!p.ok) return r;
    Simulation s(p);
    const int top = s.boundary_conditions().measurement_nodes.at(0);
    double peak_time = 0.0;
    while (!s.finished()) {
        s.advance();
        const double v = s.state().velocity[2 * top];
        if (v > r.peak) {
            r.peak = v;
            peak_time = s.state().time;
        }
        // The pulse wholly inside the column, before it reaches the surface.
        if (s.state().time > pulse && s.state().time < column_height / shear_speed)
            r.most_energy = std::max(r.most_energy, energy(s));
    }
    // The input's peak is at T/2; the surface's comes H/Vs later.
    r.arrival = peak_time - 0.5 * pulse;
    r.left = energy(s);
    return r;
}

}  // namespace

TEST(Earthquake, ShearPulseThroughAColumnOnACompliantBase) {
    const double expected = column_height / shear_speed;
    const std::vector<std::pair<std::string, std::vector<std::string>>> settings = {
        {"as given", {}},
        {"half the time step", {"/analysis/time_step=0.00025", "/analysis/steps=1200"}},
        {"elements twice as large", {"/mesh/size=0.5"}},
    };
    for (const auto& [name, overrides] : settings) {
        const ColumnResult r = run_column(overrides);
        EXPECT_NEAR(r.arrival, expected, 0.02 * expected) << name;
        EXPECT_NEAR(r.peak, 2.0 * pulse_speed, 0.05 * 2.0 * pulse_speed) << name;
        // After the reflected pulse has gone down and out through the base (0.3 s), what is left.
        EXPECT_NEAR(r.most_energy, pulse_energy, 0.05 * pulse_energy) << name;
        EXPECT_LT(r.left, 0.05 * r.most_energy) << name;
        std::printf("Shear column, %s: arrival %.4f s (H/Vs %.4f, %+.2f %%), surface peak %.4f m/s (2 V0 %.4f, %+.2f %%), "
                    "energy left %.3g J of the pulse's %.4g J (%.2g %%)\n",
                    name.c_str(), r.arrival, expected, 100.0 * (r.arrival / expected - 1.0), r.peak, 2 * pulse_speed,
                    100.0 * (r.peak / (2 * pulse_speed) - 1.0), r.left, r.most_energy, 100.0 * r.left / r.most_energy);
    }
}

TEST(Earthquake, ShearPulseOnARigidBaseStaysInTheColumn) {
    // The control: the same pulse shaking a rigid base (no dashpots) is reflected there and
    // rings on; what the compliant base lets out is the dashpots' doing.
    std::string text = column_model();
    const std::string compliant = R"("base_motion": {"type": "compliant", "x": "pulse", "from": [0, 0], "to": [1, 0]})";
    const auto at = text.find(compliant);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, compliant.size(), R"("base_motion": {"type": "rigid", "x": "pulse"})");
    const std::string rollers = R"("rollers": [)";
    text.insert(text.find(rollers) + rollers.size(), R"({"name": "base", "from": [0, 0], "to": [1, 0], "fixed": "xy"}, )");
    ReadResult read = read_model_text(text);
    ASSERT_TRUE(read.model) << (read.diagnostics.empty() ? "" : format_diagnostic(read.diagnostics.front()));
    const Preprocessed p = preprocess_model(*read.model);
    ASSERT_TRUE(p.ok);
    Simulation s(p);
    while (!s.finished()) s.advance();
    const double left = energy(s);
    EXPECT_GT(left, 0.5 * pulse_energy);
    std::printf("Shear column on a rigid base: energy left %.4g J (the pulse's %.4g J)\n", left, pulse_energy);
}

namespace {

/// The planar failure of examples/hoek-bray-planar-water.json, dry, with a pseudo-static
/// horizontal load kh·W out of the slope (towards −x there): Hoek & Bray's factor.
double pseudo_static_factor(double kh, double cohesion) {
    const double psi = pi / 6, phi = 35 * pi / 180;
    const double area = 63.41967361941667;  // of the block (12, 3)–(26, 11.083)–(26, 15)–(20, 15)
    const double W = 25e3 * area, A = 14.0 / std::cos(psi);
    return (cohesion * A + W * (std::cos(psi) - kh * std::sin(psi)) * std::tan(phi)) /
           (W * (std::sin(psi) + kh * std::cos(psi)));
}

}  // namespace

TEST(Earthquake, PseudoStaticPlanarWedge) {
    struct Case {
        double kh, cohesion;
    };
    for (const Case c : {Case{0.05, 0.0}, Case{0.1, 20e3}}) {
        std::ostringstream kh, cohesion;
        kh << "/seismic_coefficient={\"kh\": " << -c.kh << ", \"kv\": 0}";
        cohesion << "/joint_materials/0/cohesion=" << c.cohesion;
        const FactorOfSafety f = test::strength_reduction_of(
            "hoek-bray-planar-water.json", {"/water/piezometric_line=[]", kh.str(), cohesion.str()});
        ASSERT_TRUE(f.found) << "kh " << c.kh;
        const double expected = pseudo_static_factor(c.kh, c.cohesion);
        EXPECT_NEAR(f.value, expected, 0.01 * expected) << "kh " << c.kh << ", c " << c.cohesion;
        std::printf("Pseudo-static wedge, kh %.2f, c %.0f kPa: F = %.4f, closed form %.4f (%+.2f %%)\n", c.kh,
                    c.cohesion / 1e3, f.value, expected, 100.0 * (f.value / expected - 1.0));
    }
}

TEST(Earthquake, ACompliantBaseCarriesTheWeightItsSupportsCarried) {
    // A column stands on a roller in a static stage; the dynamic stage removes the roller and
    // puts a compliant base there, with no shaking. The roller's forces stay on the base: the
    // column must not sink through it (the dashpots alone carry no static load).
    const double G = density * shear_speed * shear_speed, E = 2.0 * G * (1.0 + poisson);
    std::ostringstream m;
    m << R"({"format": "mcdda-model", "version": 2, "name": "column under gravity",
  "materials": [{"name": "soil", "law": "elastic", "young_modulus": )" << E << R"(, "poisson_ratio": 0.25, "density": 2000}],
  "regions": [{"name": "column", "material": "soil", "boundary": [[0, 0], [1, 0], [1, 20], [0, 20]]}],
  "rollers": [{"name": "base", "from": [0, 0], "to": [1, 0], "fixed": "xy"}],
  "gravity": [0, -9.81],
  "measurement_points": [{"name": "surface", "point": [0.5, 20]}],
  "ground_motions": [{"name": "still", "points": [[0, 0], [1, 0]], "units": "m/s2"}],
  "base_motion": {"type": "compliant", "x": "still", "from": [0, 0], "to": [1, 0]},
  "mesh": {"size": 0.5},
  "analysis": {"type": "static", "steps": 1, "geometry": "initial"},
  "stages": [{"name": "gravity"},
             {"name": "earthquake", "remove": ["base"],
              "analysis": {"type": "dynamic", "steps": 200, "time_step": 0.001, "newmark_gamma": 0.5}}]})";
    test::Run run = test::run_text(m.str());
    ASSERT_TRUE(run.simulation);
    const test::History& h = run.history;
    // The settlement of the static stage (the column's elastic shortening, ρgH²/2M), then nothing.
    const double settled = h.points[1][0].y;
    EXPECT_LT(settled, 0.0);
    double sinking = 0.0;
    for (std::size_t i = 1; i < h.points.size(); ++i) sinking = std::max(sinking, std::fabs(h.points[i][0].y - settled));
    EXPECT_LT(sinking, 0.01 * std::fabs(settled));
    std::printf("Column on a compliant base: static settlement %.3g mm, largest change afterwards %.3g mm\n",
                -1e3 * settled, 1e3 * sinking);
}

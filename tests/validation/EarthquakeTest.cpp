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

namespace {

/// The column of column_model() standing on a rigid base, without dashpots, shaken by the same
/// pulse and then left to vibrate: its surface's motion relative to the base after the pulse.
std::vector<std::pair<double, double>> free_vibration(const std::vector<std::string>& overrides) {
    std::string text = column_model();
    const std::string compliant = R"("base_motion": {"type": "compliant", "x": "pulse", "from": [0, 0], "to": [1, 0]})";
    text.replace(text.find(compliant), compliant.size(), R"("base_motion": {"type": "rigid", "x": "pulse"})");
    const std::string rollers = R"("rollers": [)";
    text.insert(text.find(rollers) + rollers.size(), R"({"name": "base", "from": [0, 0], "to": [1, 0], "fixed": "xy"}, )");
    // A slower push than the wave pulse, sampled for the free vibration's time step: one
    // half-sine of base acceleration over 0.2 s, which excites the first mode mostly.
    std::ostringstream push;
    push << R"("points": [)";
    for (int k = 0; k <= 100; ++k)
        push << (k ? ", " : "") << "[" << k * 0.002 << ", " << (k == 0 || k == 100 ? 0.0 : std::sin(pi * k / 100.0)) << "]";
    push << "]";
    const auto first = text.find(R"("points": [[)"), last = text.find(R"(], "units": "m/s2")");
    text.replace(first, last + 1 - first, push.str());
    std::vector<std::string> all = {"/mesh/size=1", "/analysis/time_step=0.002", "/analysis/steps=1500"};
    all.insert(all.end(), overrides.begin(), overrides.end());
    test::Run run = test::run_text(text, all);
    std::vector<std::pair<double, double>> motion;
    if (!run.simulation) return motion;
    for (std::size_t i = 0; i < run.history.time.size(); ++i)
        motion.emplace_back(run.history.time[i], run.history.points[i][0].x);
    return motion;
}

/// The damping ratio of the decay between the first and the last of the positive peaks after
/// t0: ln(first/last)/(2π n) for n periods between them (the logarithmic decrement).
double decay_ratio(const std::vector<std::pair<double, double>>& motion, double t0, double* period) {
    std::vector<std::pair<double, double>> peaks;
    for (std::size_t i = 1; i + 1 < motion.size(); ++i)
        if (motion[i].first > t0 && motion[i].second > 0.0 && motion[i].second >= motion[i - 1].second &&
            motion[i].second > motion[i + 1].second)
            peaks.push_back(motion[i]);
    if (peaks.size() < 3) return -1.0;
    const double n = static_cast<double>(peaks.size() - 1);
    if (period) *period = (peaks.back().first - peaks.front().first) / n;
    const double delta = std::log(peaks.front().second / peaks.back().second) / n;
    return delta / std::sqrt(4.0 * pi * pi + delta * delta);
}

}  // namespace

TEST(Earthquake, RayleighDampingDecaysTheColumnAtItsRatio) {
    // The column's first shear mode: f1 = Vs/4H = 2.5 Hz. Rayleigh damping of 5 % there (its
    // least, α = ξω, β = ξ/ω); the higher modes the pulse excites die out faster.
    const double f1 = shear_speed / (4.0 * column_height);
    std::ostringstream frequency;
    frequency << "/analysis/damping_frequency=" << f1;
    double period = 0.0;
    const double damped = decay_ratio(free_vibration({"/analysis/damping_ratio=0.05", frequency.str()}), 0.5, &period);
    EXPECT_NEAR(period, 1.0 / f1, 0.02 / f1);
    EXPECT_NEAR(damped, 0.05, 0.0025);
    // Without Rayleigh damping and with Newmark's γ = ½ the column rings on undamped.
    const double undamped = decay_ratio(free_vibration({}), 0.5, nullptr);
    EXPECT_NEAR(undamped, 0.0, 0.002);
    std::printf("Rayleigh damping 5 %% at f1 = %.2f Hz: period %.4f s (1/f1 %.4f), decay ratio %.4f; undamped %.5f\n", f1,
                period, 1.0 / f1, damped, undamped);
}

TEST(Earthquake, ShearPulseInAWideLayerWithAbsorbingSides) {
    // No free-field columns: a layer wide against its depth with absorbing sides. At its centre
    // the surface sees the 1-D motion (twice the incident wave); the sides' dashpots let the
    // layer's waves out but distort the motion next to them.
    std::string text = column_model();
    auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace(R"([[0, 0], [1, 0], [1, 20], [0, 20]])", R"([[0, 0], [80, 0], [80, 20], [0, 20]])");
    replace(R"("rollers": [{"name": "left", "from": [0, 0], "to": [0, 20], "fixed": "y"}, {"name": "right", "from": [1, 0], "to": [1, 20], "fixed": "y"}],)",
            R"("fixed_points": [{"name": "corner", "point": [0, 0]}],
  "absorbing_boundaries": [{"name": "left", "from": [0, 0], "to": [0, 20]}, {"name": "right", "from": [80, 0], "to": [80, 20]}],)");
    replace(R"("from": [0, 0], "to": [1, 0]})", R"("from": [0, 0], "to": [80, 0]})");
    replace(R"([{"name": "surface", "point": [0.5, 20]}])", R"([{"name": "centre", "point": [40, 20]}, {"name": "edge", "point": [0, 20]}])");
    ReadResult read = read_model_text(text, {"/mesh/size=1.5"});
    ASSERT_TRUE(read.model) << (read.diagnostics.empty() ? "" : format_diagnostic(read.diagnostics.front()));
    const Preprocessed p = preprocess_model(*read.model);
    ASSERT_TRUE(p.ok);
    Simulation s(p);
    const int centre = s.boundary_conditions().measurement_nodes.at(0), edge = s.boundary_conditions().measurement_nodes.at(1);
    double peak = 0.0, peak_time = 0.0, edge_peak = 0.0;
    while (!s.finished()) {
        s.advance();
        const double v = s.state().velocity[2 * centre];
        if (v > peak) {
            peak = v;
            peak_time = s.state().time;
        }
        edge_peak = std::max(edge_peak, s.state().velocity[2 * edge]);
    }
    const double arrival = peak_time - 0.5 * pulse, expected = column_height / shear_speed;
    EXPECT_NEAR(arrival, expected, 0.02 * expected);
    EXPECT_NEAR(peak, 2.0 * pulse_speed, 0.05 * 2.0 * pulse_speed);
    std::printf("Wide layer with absorbing sides: centre arrival %.4f s (%+.2f %%), peak %.4f m/s (%+.2f %% of 2 V0); "
                "at the side %.4f m/s\n",
                arrival, 100.0 * (arrival / expected - 1.0), peak, 100.0 * (peak / (2 * pulse_speed) - 1.0), edge_peak);
}

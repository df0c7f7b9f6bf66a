// Ground water (fem/PorePressure.hpp) against closed forms:
//  - Hoek & Bray's planar failure with a water-filled tension crack (examples/hoek-bray-planar-water.json),
//  - a block on an inclined joint lifted by a water pressure of known resultant U,
//  - buoyancy: a slope under water with γsat and the dry slope with γ′ = γsat − γw.

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace mcdda;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double gamma_w = 9810.0;

std::string number(double v) {
    std::ostringstream out;
    out.precision(17);
    out << v;
    return out.str();
}

// The slope of examples/hoek-bray-planar-water.json: the joint from (12, 3) dips ψp = 30° to the
// foot of the tension crack at x = 26 m; the crack runs up to the crest at y = 15 m.
const double crack_foot = 3.0 + 14.0 * std::tan(pi / 6);  // 11.083 m
const double crack_depth = 15.0 - crack_foot;            // z = 3.917 m

/// Hoek & Bray's factor of safety of the planar failure with water zw deep in the crack.
double hoek_bray_factor(double zw) {
    const double psi = pi / 6, phi = 35 * pi / 180, c = 20e3;
    const double area = 63.41967361941667;  // of the block (12, 3)–(26, 11.083)–(26, 15)–(20, 15)
    const double W = 25e3 * area, A = 14.0 / std::cos(psi);
    const double U = 0.5 * gamma_w * zw * A, V = 0.5 * gamma_w * zw * zw;
    return (c * A + (W * std::cos(psi) - U - V * std::sin(psi)) * std::tan(phi)) /
           (W * std::sin(psi) + V * std::cos(psi));
}

/// The piezometric line of water zw deep in the crack: along the ground in front of the toe and the
/// face below the daylight point, straight to the crack's water level, level behind.
std::string planar_water(double zw) {
    const std::string level = number(crack_foot + zw);
    return "/water/piezometric_line=[[0, 0], [10, 0], [12, 3], [26, " + level + "], [40, " + level + "]]";
}

}  // namespace

TEST(Water, HoekBrayPlanarFailureWithAWaterFilledTensionCrack) {
    for (const double fraction : {0.0, 0.5, 1.0}) {
        const double zw = fraction * crack_depth;
        const FactorOfSafety f = test::strength_reduction_of("hoek-bray-planar-water.json", {planar_water(zw)});
        ASSERT_TRUE(f.found) << "zw = " << zw;
        const double expected = hoek_bray_factor(zw);
        EXPECT_NEAR(f.value, expected, 0.02 * expected) << "zw = " << zw << " m";
        std::printf("Hoek-Bray zw = %.3f m: F = %.4f, closed form %.4f (%+.2f %%)\n", zw, f.value, expected,
                    100.0 * (f.value / expected - 1.0));
    }
}

TEST(Water, HoekBrayFactorDoesNotDependOnTheSettings) {
    const double expected = hoek_bray_factor(crack_depth);
    const std::vector<std::pair<std::string, std::vector<std::string>>> variants = {
        {"finer mesh", {"/mesh/size=0.75"}},
        {"10 steps", {"/analysis/steps=10"}},
        {"equilibrium tolerance / 10", {"/analysis/plastic_tolerance=1e-5"}},
    };
    for (const auto& [name, more] : variants) {
        std::vector<std::string> o = {planar_water(crack_depth)};
        o.insert(o.end(), more.begin(), more.end());
        const FactorOfSafety f = test::strength_reduction_of("hoek-bray-planar-water.json", o);
        ASSERT_TRUE(f.found) << name;
        EXPECT_NEAR(f.value, expected, 0.02 * expected) << name;
        std::printf("Hoek-Bray, crack full, %s: F = %.4f (%+.2f %%)\n", name.c_str(), f.value, 100 * (f.value / expected - 1));
    }
}

// examples/incline-stable.json's block (1 m along a 40° joint, 0.5 m thick, 2600 kg/m³) with a
// piezometric line parallel to the joint 0.3 m above it: the joint carries u = γw·0.3 m all
// along, U = 2943 N/m, and the water on the block's two ends cancels. The block slides when
// W sin α = (W cos α − U) tan φ: F = (W cos α − U) tan φ / (W sin α).
TEST(Water, BlockOnAnInclinedJointLiftedByWater) {
    const double alpha = 40 * pi / 180, phi = 45 * pi / 180, h = 0.3;
    const double W = 2600 * 9.81 * 0.5, U = gamma_w * h * 1.0;
    const Point2 foot{4.596266658714, 3.856725658119};  // lower end of the joint
    auto level = [&](double x) { return number(foot.y + (x - foot.x) * std::tan(alpha) + h); };
    // A joint stiffness of 0.2 GN/m per metre: with the default penalty (4E, 20 GN/m) the
    // open–close iteration declares a false collapse of this small block at F = 1.105 even dry
    // (docs/plasticity.md, "Strength reduction"); softer joints, as real ones are, do not.
    const std::vector<std::string> common = {"/analysis/type=\"strength_reduction\"", "/analysis/steps=1",
                                             "/joint_materials/0/friction_angle=45",
                                             "/joint_materials/0/normal_stiffness=2e8",
                                             "/joint_materials/0/shear_stiffness=2e8"};
    std::vector<std::string> wet = common;
    wet.push_back("/water={\"piezometric_line\": [[0, " + level(0) + "], [12, " + level(12) + "]]}");
    const FactorOfSafety f = test::strength_reduction_of("incline-stable.json", wet);
    ASSERT_TRUE(f.found);
    const double expected = (W * std::cos(alpha) - U) * std::tan(phi) / (W * std::sin(alpha));
    EXPECT_NEAR(f.value, expected, 0.01 * expected);
    const FactorOfSafety dry = test::strength_reduction_of("incline-stable.json", common);
    ASSERT_TRUE(dry.found);
    EXPECT_NEAR(dry.value, std::tan(phi) / std::tan(alpha), 0.01 * std::tan(phi) / std::tan(alpha));
    std::printf("inclined block: F = %.4f with water (closed form %.4f, %+.2f %%), %.4f dry (%.4f)\n", f.value,
                expected, 100 * (f.value / expected - 1), dry.value, std::tan(phi) / std::tan(alpha));
}

// examples/homogeneous-slope.json under a lake 2 m above its crest, γsat = 20 kN/m³, against the
// same slope dry with γ′ = 20 − 9.81 kN/m³: the same effective stresses and factor of safety.
TEST(Water, SubmergedSlopeIsTheDrySlopeWithBuoyantUnitWeight) {
    const std::vector<std::string> wet = {R"(/water={"piezometric_line": [[0, 8.5], [18, 8.5]]})",
                                          "/materials/0/saturated_unit_weight=20000"};
    const std::vector<std::string> dry = {"/materials/0/unit_weight=" + number(20000 - gamma_w)};
    auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    // Gravity on in one static step, plasticity on: the effective stresses agree.
    const std::vector<std::string> static_step = {"/analysis/type=\"static\"", "/analysis/steps=1"};
    test::Run w = test::run_example("homogeneous-slope.json", with(static_step, wet));
    test::Run d = test::run_example("homogeneous-slope.json", with(static_step, dry));
    ASSERT_TRUE(w.simulation && d.simulation);
    const auto& sw = w.simulation->state().stress;
    const auto& sd = d.simulation->state().stress;
    ASSERT_EQ(sw.size(), sd.size());
    double largest = 0.0, difference = 0.0;
    for (std::size_t e = 0; e < sw.size(); ++e) {
        largest = std::max(largest, sd[e].cwiseAbs().maxCoeff());
        difference = std::max(difference, (sw[e] - sd[e]).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(difference, 1e-6 * largest) << "largest effective stress " << largest << " Pa";
    // The pore pressures the results report: γw times the depth below the lake's surface.
    const std::vector<double> u = w.simulation->pore_pressures();
    for (std::size_t e = 0; e < u.size(); ++e) {
        // On the undeformed mesh: the slope is a small-strain analysis ("geometry": "initial").
        const auto& t = w.model.mesh.triangles[e];
        const auto& n = w.model.mesh.nodes;
        const Point2 c{(n[t[0]].x + n[t[1]].x + n[t[2]].x) / 3, (n[t[0]].y + n[t[1]].y + n[t[2]].y) / 3};
        ASSERT_NEAR(u[e], gamma_w * (8.5 - c.y), 1e-9 * gamma_w * 8.5) << "element " << e;
    }
    // Strength reduction: the same factor of safety (water unchanged, strengths reduced).
    const FactorOfSafety fw = test::strength_reduction_of("homogeneous-slope.json", wet);
    const FactorOfSafety fd = test::strength_reduction_of("homogeneous-slope.json", dry);
    ASSERT_TRUE(fw.found && fd.found);
    EXPECT_NEAR(fw.value, fd.value, 0.005 * fd.value);
    std::printf("submerged slope: F = %.4f, dry with buoyant weight %.4f; effective stresses differ by %.2e of %.3e Pa\n",
                fw.value, fd.value, difference, largest);
}

// A K0 in-situ stress under a water table (in-situ stress "gravity"): effective stresses from
// the unit weight above the table and the saturated one below it, less the pore pressure, are in
// balance with the weight and the water at once — the first step moves next to nothing. (Not
// exactly nothing: an element the water table crosses weighs the mean of its integration points,
// and its stress has a kink at the table that its linear field cannot follow.)
TEST(Water, InSituStressUnderAWaterTableIsInBalance) {
    const std::string level_ground = R"({"format": "mcdda-model", "version": 1,
      "materials": [{"name": "soil", "young_modulus": 5e7, "poisson_ratio": 0.3, "unit_weight": 18000,
                     "saturated_unit_weight": 21000, "cohesion": 20000, "friction_angle": 30}],
      "regions": [{"name": "ground", "material": "soil", "boundary": [[0, 0], [20, 0], [20, 10], [0, 10]]}],
      "rollers": [{"name": "base", "from": [0, 0], "to": [20, 0], "fixed": "xy"},
                  {"name": "left", "from": [0, 0], "to": [0, 10], "fixed": "x"},
                  {"name": "right", "from": [20, 0], "to": [20, 10], "fixed": "x"}],
      "gravity": [0, -9.81],
      "initial_stress": {"type": "gravity", "surface_y": 10, "k0": 0.5},
      "water": {"piezometric_line": [[0, 6], [20, 6]]},
      "mesh": {"size": 1.0},
      "analysis": {"type": "static", "steps": 1, "geometry": "initial"}})";
    test::Run r = test::run_text(level_ground);
    ASSERT_TRUE(r.simulation);
    double largest = 0.0;
    for (Eigen::Index i = 0; i < r.simulation->state().displacement.size(); ++i)
        largest = std::max(largest, std::abs(r.simulation->state().displacement[i]));
    // The same ground without the in-situ stress settles by centimetres.
    test::Run settled = test::run_text(level_ground, {"/initial_stress={\"type\": \"none\"}"});
    ASSERT_TRUE(settled.simulation);
    double settlement = 0.0;
    for (Eigen::Index i = 0; i < settled.simulation->state().displacement.size(); ++i)
        settlement = std::max(settlement, std::abs(settled.simulation->state().displacement[i]));
    EXPECT_LT(largest, 2e-3 * settlement) << "moved " << largest << " m; without in-situ stress " << settlement << " m";
    // σ′v at a point 7 m deep: 4 m dry at 18 kN/m³, 3 m saturated at 21 kN/m³, less 3 m of water.
    const auto& mesh = r.model.mesh;
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const auto& t = mesh.triangles[e];
        const double y = (mesh.nodes[t[0]].y + mesh.nodes[t[1]].y + mesh.nodes[t[2]].y) / 3;
        const double depth = 10 - y, wet = std::max(0.0, 6 - y);
        const double effective = 18000 * (depth - wet) + 21000 * wet - gamma_w * wet;
        // Elements the water table crosses carry the mean of their points: checked off it only.
        bool crossed = false;
        for (int a = 0; a < 3; ++a) crossed = crossed || ((mesh.nodes[t[a]].y > 6) != (y > 6));
        if (crossed) continue;
        ASSERT_NEAR(r.simulation->state().stress[e][1], -effective, 1e-3 * 180000) << "element " << e << " at y = " << y;
        ASSERT_NEAR(r.simulation->state().stress[e][0], -0.5 * effective, 1e-3 * 180000) << "element " << e;
    }
}

// examples/reservoir-drawdown-staged.json: the drawdown stage changes the water (its pore
// pressures are those of its line) and lowers the slope's factor of safety below that of the slope
// with the reservoir held full.
TEST(Water, DrawdownStageLowersTheFactorOfSafety) {
    const FactorOfSafety drawdown = test::strength_reduction_of("reservoir-drawdown-staged.json");
    const FactorOfSafety full = test::strength_reduction_of(
        "reservoir-drawdown-staged.json", {"/stages/1/water/piezometric_line=[[0, 6], [18, 6]]"});
    ASSERT_TRUE(drawdown.found && full.found);
    EXPECT_LT(drawdown.value, 0.8 * full.value);
    EXPECT_GT(drawdown.value, 1.0);  // it still stands
    std::printf("reservoir slope: F = %.3f after the drawdown, %.3f with the reservoir held full\n", drawdown.value,
                full.value);
    test::Run r = test::run_example("reservoir-drawdown-staged.json", {}, 8);  // the first two stages
    ASSERT_TRUE(r.simulation);
    EXPECT_EQ(r.simulation->state().stage, 1);
    const Water& water = r.simulation->model().water;
    ASSERT_TRUE(water.present());
    EXPECT_DOUBLE_EQ(water.level(4.5), 2.0);
    const std::vector<double> u = r.simulation->pore_pressures();
    const auto& mesh = r.model.mesh;
    for (std::size_t e = 0; e < u.size(); ++e) {
        const auto& t = mesh.triangles[e];
        const Point2 c{(mesh.nodes[t[0]].x + mesh.nodes[t[1]].x + mesh.nodes[t[2]].x) / 3,
                       (mesh.nodes[t[0]].y + mesh.nodes[t[1]].y + mesh.nodes[t[2]].y) / 3};
        // Below the line and clear of its kinks (x = 4.5, 9, 13.5 m): the mean of the element's
        // points is the pore pressure at its centroid.
        bool kink = false;
        for (double x : {4.5, 9.0, 13.5}) {
            const double lo = std::min({mesh.nodes[t[0]].x, mesh.nodes[t[1]].x, mesh.nodes[t[2]].x});
            const double hi = std::max({mesh.nodes[t[0]].x, mesh.nodes[t[1]].x, mesh.nodes[t[2]].x});
            kink = kink || (lo < x && x < hi);
        }
        if (!kink && c.y < water.level(c.x) - 1.0)
            ASSERT_NEAR(u[e], gamma_w * (water.level(c.x) - c.y), 1e-6 * gamma_w * 6) << "element " << e;
    }
}

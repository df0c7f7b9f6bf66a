// Griffith's crack: a straight crack of length 2a inside an elastic plate (a joint that ends in
// the rock at both ends, so a crack inside its block), plane strain. Under a remote stress σ
// normal to it the faces open by 4σ(1 − ν²)/E · √(a² − x²) (Inglis; Tada, Paris & Irwin, The
// Stress Analysis of Cracks Handbook); under remote shear τ a frictionless crack slips by the
// same profile with τ in place of σ; under compression it stays closed. examples/griffith-crack.json:
// a = 1 m, plate 40 m wide, E = 1 GPa, ν = 0.25, σ = 1 MPa.

#include "RunModel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace mcdda;

namespace {

constexpr double a = 1.0, young = 1e9, poisson = 0.25, stress = 1e6;

/// The closed-form opening (or slip) at distance x from the centre.
double griffith(double x) { return 4.0 * stress * (1.0 - poisson * poisson) / young * std::sqrt(a * a - x * x); }

/// Relative displacement of the crack's faces at the node pairs along it (the crack runs through
/// the origin at angle `angle`): its component normal to the crack (`normal`) or along it.
std::map<double, double> face_profile(const Simulation& s, double angle, bool normal) {
    const double c = std::cos(angle), sn = std::sin(angle);
    std::map<double, std::vector<int>> pairs;  // position along the crack → nodes there
    const auto& nodes = s.mesh().nodes;
    for (int i = 0; i < static_cast<int>(nodes.size()); ++i) {
        const double t = nodes[i].x * c + nodes[i].y * sn, q = -nodes[i].x * sn + nodes[i].y * c;
        if (std::fabs(q) < 1e-9 && std::fabs(t) < a - 1e-9) pairs[std::round(t * 1e9) / 1e9].push_back(i);
    }
    std::map<double, double> profile;
    const Eigen::VectorXd& u = s.state().displacement;
    for (const auto& [t, ids] : pairs) {
        if (ids.size() != 2) continue;  // doubled: one node on each face
        const double dx = u[2 * ids[0]] - u[2 * ids[1]], dy = u[2 * ids[0] + 1] - u[2 * ids[1] + 1];
        profile[t] = std::fabs(normal ? -dx * sn + dy * c : dx * c + dy * sn);
    }
    return profile;
}

/// Largest relative error over the middle 80 % and the error at the centre, printed.
void expect_griffith_profile(const std::map<double, double>& profile, const char* what) {
    ASSERT_GE(profile.size(), 40u) << "the crack's nodes should be doubled along it";
    double worst = 0.0, centre_error = 1e300, centre_distance = 1e300;
    for (const auto& [t, value] : profile) {
        const double error = value / griffith(t) - 1.0;
        if (std::fabs(t) <= 0.8 * a) worst = std::max(worst, std::fabs(error));
        if (std::fabs(t) < centre_distance) {
            centre_distance = std::fabs(t);
            centre_error = error;
        }
    }
    std::cout << "Griffith crack, " << what << ": centre " << 100 * centre_error << " %, middle 80 % at most "
              << 100 * worst << " % (" << profile.size() << " node pairs)\n";
    EXPECT_LT(centre_distance, 0.05 * a);
    EXPECT_LT(std::fabs(centre_error), 0.03);
    EXPECT_LT(worst, 0.05);
}

}  // namespace

TEST(GriffithCrack, OpeningUnderTensionWithinThreePercentAtTheCentreAndFiveOverTheMiddle) {
    auto run = mcdda::test::run_example("griffith-crack.json");
    ASSERT_TRUE(run.simulation);
    expect_griffith_profile(face_profile(*run.simulation, 0.0, true), "opening under tension");
    // The faces are apart: every crack contact open.
    int open = 0;
    for (const Contact& c : run.simulation->state().contacts) open += c.state == ContactState::Open;
    EXPECT_EQ(open, static_cast<int>(run.simulation->state().contacts.size()));
    EXPECT_GT(open, 80);
}

TEST(GriffithCrack, ClosedUnderCompression) {
    auto run = mcdda::test::run_example("griffith-crack.json",
                                        {"/edge_pressures/0/pressure=1e6", "/edge_pressures/1/pressure=1e6"});
    ASSERT_TRUE(run.simulation);
    // The faces pass into each other no further than the penalty springs let them: far below
    // the opening the same stress pulls them apart by.
    double closest = 1e300;
    for (const auto& [t, value] : face_profile(*run.simulation, 0.0, true)) closest = std::min(closest, value);
    double penetration = 0.0, carried = 0.0;
    for (const Contact& c : run.simulation->state().contacts) {
        EXPECT_NE(c.state, ContactState::Open);
        penetration = std::max(penetration, -c.gap);
        carried += c.normal_force;
    }
    std::cout << "Griffith crack under compression: largest penetration " << penetration * 1e3
              << " mm (opening under the same tension " << griffith(0) * 1e3 << " mm), contact forces carry "
              << carried / (stress * 2 * a) * 100 << " % of σ·2a\n";
    EXPECT_LT(penetration, 0.01 * griffith(0.0));
    // The stress goes across the crack: the contacts of the two faces together carry σ · 2a.
    EXPECT_NEAR(carried, stress * 2 * a, 0.05 * stress * 2 * a);
}

TEST(GriffithCrack, SlipUnderShearOfAFrictionlessCrackWithinFivePercent) {
    // Remote shear τ on a crack at 45°: principal stresses τ (tension) along y and −τ along x,
    // plus a compression p = 0.2 τ on both that keeps the faces pressed together (normal stress
    // on the crack −p, shear τ; frictionless, so the slip is that of pure shear).
    const double r = std::sqrt(0.5), tau = stress, p = 0.2 * stress;
    auto number = [](double v) {
        std::ostringstream out;
        out.precision(17);
        out << v;
        return out.str();
    };
    const std::string from = "[" + number(-r) + "," + number(-r) + "]", to = "[" + number(r) + "," + number(r) + "]";
    auto run = mcdda::test::run_example(
        "griffith-crack.json",
        {"/joints/0/points=[" + from + "," + to + "]", "/mesh/local/0/from=" + from, "/mesh/local/0/to=" + to,
         "/edge_pressures/0/pressure=" + number(-tau + p), "/edge_pressures/1/pressure=" + number(-tau + p),
         "/edge_pressures/2/pressure=" + number(tau + p), "/edge_pressures/3/pressure=" + number(tau + p)});
    ASSERT_TRUE(run.simulation);
    expect_griffith_profile(face_profile(*run.simulation, M_PI / 4, false), "slip under shear");
}

// A bolt across the crack holds its faces: it is stretched by most of the opening at its place,
// and the crack opens less.
TEST(GriffithCrack, ABoltAcrossTheCrackCarriesItsOpening) {
    auto free = mcdda::test::run_example("griffith-crack.json");
    // EA / L = 2e8 N/m: a stiff bar over 1 m, about a sixth of what the rock around gives.
    auto bolted = mcdda::test::run_example(
        "griffith-crack.json",
        {"/version=2", R"(/bolts=[{"name": "across", "from": [0, -0.5], "to": [0, 0.5], "stiffness": 2e8}])"});
    ASSERT_TRUE(free.simulation && bolted.simulation);
    const double open_free = face_profile(*free.simulation, 0.0, true).lower_bound(-1e-9)->second;
    const double open_bolted = face_profile(*bolted.simulation, 0.0, true).lower_bound(-1e-9)->second;
    const double force = bolted.simulation->state().bolt_force.at(0);
    std::cout << "Griffith crack with a bolt across: centre opening " << open_bolted * 1e3 << " mm (without "
              << open_free * 1e3 << " mm), bolt force " << force / 1e3 << " kN/m\n";
    EXPECT_LT(open_bolted, 0.95 * open_free);
    EXPECT_GT(force, 0.0);
    // Its stretch is less than the opening at its place (the rock between its anchors and the
    // faces moves less than the faces) but most of it.
    EXPECT_LT(force / 2e8, open_bolted);
    EXPECT_GT(force / 2e8, 0.5 * open_bolted);
}

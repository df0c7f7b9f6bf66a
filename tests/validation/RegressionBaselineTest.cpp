// Regression baseline: every example of examples/ is run for a bounded number of steps and its
// results are compared with data recorded in tests/validation/baseline/<case>.json, so that a
// restructuring of the engine can be shown to change nothing (or to change deliberately).
//
// First recorded on the initial-stress engine (commit 2df2356), re-recorded on the present
// equilibrium-iteration engine (Newton with the consistent tangent for ψ = φ, Anderson-accelerated
// elastic iterations otherwise, load bisection, stricter contact detection), three-node triangles;
// the Prandtl case again when Newton began its increments with the last converged tangent (its
// stresses moved by less than the equilibrium tolerance); Lavarak (moved by ~1e-5 relative) when
// the Anderson mixing of models without closed contacts went on below the force tolerance, and
// Salençon when its example became small-strain (`"geometry": "initial"`), and again when pure
// equilibrium problems began to measure their out-of-balance force as a stress (its wall
// displacement moved by 0.4–0.6 %, the iterations now converged at the finely meshed wall too);
// the jointed tunnel when the relaxation increments of static DDA began to leave their contacts
// in the states they were solved with (its crown settlement moved by 0.07 %, 0.5 µm of 0.72 mm:
// the marginal contact changes those increments used to keep had left it out of balance); the two
// inclines and the jointed tunnel when elastic corrections began to be solved to the iteration's
// tolerance (conjugate gradients with a held factor stopping at 1e-4 of the right-hand side, not
// 1e-10) and plain elastic corrections to settle against the displacement so far (the sliding
// block's largest displacement after 100 steps moved by 6e-6 relative, the tunnel's stresses by
// less than 1e-5); the same three when a held factor began to be corrected for the contacts that
// changed (Sherman–Morrison–Woodbury) and kept while it costs less than a factorisation beyond
// the solves a fresh one would make (more corrections solved with a held factor to 1e-4 of the
// right-hand side: the sliding block's displacements moved by at most 3e-6 relative, the stable
// block's 6 µm by at most 3e-5, the tunnel's stresses by less than 1e-5); Salençon when a
// small-strain analysis stopped polishing with the unsymmetric tangent from farther than 100
// times the tolerance (its excavation's first try, stalled at 259 times, used to converge in a
// polish of 5 iterations; now its load is halved: the measurement points moved by up to 0.07 %,
// 9 µm of 12.1 mm, the plastic area not at all); the two Prandtl cases when the rigid footing's
// example was meshed afresh, refined at the footing's edge where the stress is singular, its
// footing block meshed at 1 m by the region's own mesh size (412 triangles instead of 2,667: a new
// mesh, so every recorded value moved); the jointed tunnel when a relaxation increment that moved
// less than a tenth of the displacement limit began to double Δt (one measurement point's 0.35 µm
// moved by 1.8e-12 m); Salençon when LU solves stopped being refined by UMFPACK (the equilibrium
// iterations refine them): every recorded value moved by less than 6e-13 relative, and one
// element of 13,415 whose stress sits on the yield surface counts as yielded before instead of
// yielding now (2,606 and 3,229 instead of 2,607 and 3,228); Kirsch, Lavarak and Salençon when a
// static step whose loads do not change, from a state within the equilibrium tolerance, began to
// solve nothing (their later steps used to iterate on from that state: Kirsch's displacements
// moved by up to 1.4e-4 of the largest, within the tolerance of 1e-4 its first step relaxed to,
// Lavarak's by about 1e-6 relative; the 3,229 elements of Salençon's that its third step counted
// as yielded before stay yielding, as its second step left them: nothing unloads in a step that
// does not move); the jointed tunnel when a vertex behind an edge began to take it only from
// inside the edge's block (vertices a few µm outside a block's acute corner at a joint junction,
// behind the edge beside the corner, no longer lock against it: the largest displacement moved
// by 2.5e-4 of itself, 0.19 µm of 0.75 mm); the stable incline when static DDA began to order its
// factor by nested dissection where that is smaller and to end open–close rounds whose contacts
// are about to change before they settle (its displacements moved by at most 2.0e-6 relative,
// 2e-10 m, below the equilibrium tolerance); the two inclines when the solves with a held factor,
// which only precondition conjugate gradients, began to use a copy of it in single precision (the
// iterations stop at their tolerance along another path: the sliding block's displacements moved
// by at most 1.3e-6 relative and one stress sample by 3.1e-5 of itself, the stable block's
// displacements by at most 1.7e-6 relative, 1.1e-11 m).
// After a deliberate change, rerun with MCDDA_RECORD_BASELINE=1 and state the reason in the commit.
//
//   MCDDA_RECORD_BASELINE=1 ./mcdda_validation_tests --gtest_filter='*RegressionBaseline*'
//
// writes the files into the source tree (MCDDA_BASELINE_DIR) instead of comparing.
//
// Recorded per case:
//   - history: the time and every measurement point's displacement after each step (step 0 = start);
//   - mesh: node and element counts, Σ x, Σ y, Σ |x|, Σ |y| of the initial node coordinates;
//   - displacement: max |u| over nodes, Σ ux, Σ uy, Σ |ux|, Σ |uy|, and (ux, uy) of ~20 nodes
//     chosen evenly by index;
//   - stress (σxx, σyy, τxy, σzz): per component the sum, Σ |·|, min and max over elements, and
//     the stress of ~20 elements chosen evenly by index;
//   - plasticity: elements per plastic_state (0, 1, 2) and the accumulated plastic strain sum;
//   - contacts: number of contacts open, sliding and locked after the last step.
// Compared: counts exactly; values with a relative tolerance (1e-6 unless a case says otherwise)
// plus an absolute floor of 1e-9 × the largest magnitude of the field (history, nodal
// displacement, stress); a sum is compared relative to the recorded sum of magnitudes.
//
// Each case carries a list of override strings (`--set` syntax, "/json/pointer=value"): a later
// variant of a case (e.g. another element type) is a new case with one more override.

#include "RunModel.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

using namespace mcdda;
using nlohmann::json;

namespace {

struct BaselineCase {
    std::string name;                    ///< file name of the record (baseline/<name>.json), test name
    std::string file;                    ///< examples/<file>
    std::vector<std::string> overrides;  ///< "/json/pointer=value", as `--set`
    int steps;                           ///< steps run (bounded so the whole suite stays fast)
    double relative = 1e-6;              ///< relative tolerance of values
    double floor = 1e-9;                 ///< absolute floor, as a fraction of the field's max magnitude
};

// Three-node triangles throughout: the first engine knew no others, and the six-node
// examples are checked against closed forms by the validation tests.
const std::string t3 = "/mesh/element=\"t3\"";

// Step counts keep the whole suite under 20 s of CPU time in Release (16 s measured).
const std::vector<BaselineCase> cases = {
    // Dynamic, one block on an incline, contacts sliding or locked: 100 steps of 5 ms.
    {"incline-sliding", "incline-sliding.json", {t3}, 100},
    {"incline-stable", "incline-stable.json", {t3}, 100},
    // 66 blocks around a tunnel (static, ~1800 contacts): step 1 elastic, step 2 with yielding
    // (most of this suite's time).
    {"jointed-tunnel", "jointed-tunnel.json", {t3}, 2},
    // Elastic plate with a hole: all 5 steps.
    {"kirsch", "kirsch.json", {t3}, 5},
    // Plastic cavern: all 3 steps.
    {"lavarak-cavern", "lavarak-cavern.json", {t3}, 3},
    // Footing, 1 kPa per step: 60 steps, nearly elastic.
    {"prandtl-footing", "prandtl-footing.json", {t3}, 60},
    // Footing, 50 kPa per step up to q/cu = 3: ~300 elements yielding in the last step.
    {"prandtl-footing-plastic", "prandtl-footing.json", {t3, "/edge_pressures/0/pressure=50000"}, 6},
    // Plastic tunnel: the first 3 of 20 steps.
    {"salencon-tunnel", "salencon-tunnel.json", {t3}, 3},
};

/// Names the case in test output (instead of its bytes).
void PrintTo(const BaselineCase& c, std::ostream* os) {
    *os << c.name << " (" << c.file << ", " << c.steps << " steps";
    for (const std::string& o : c.overrides) *os << ", " << o;
    *os << ")";
}

constexpr int samples = 20;

/// About `samples` indices spread evenly over [0, n).
std::vector<int> even_indices(int n) {
    std::vector<int> out;
    if (n <= 0) return out;
    const int k = std::min(n, samples);
    for (int i = 0; i < k; ++i) out.push_back(k == 1 ? 0 : static_cast<int>((static_cast<long long>(n - 1) * i) / (k - 1)));
    return out;
}

json record(const BaselineCase& c, const mcdda::test::Run& run) {
    const Simulation& sim = *run.simulation;
    const SimulationState& s = sim.state();
    const Mesh& mesh = run.model.mesh;
    const int nodes = static_cast<int>(mesh.nodes.size());
    const int elements = static_cast<int>(mesh.triangles.size());

    json j;
    j["case"] = c.name;
    j["file"] = c.file;
    j["overrides"] = c.overrides;
    j["steps"] = s.step;
    j["recorded_on"] = "equilibrium-iteration engine, three-node triangles";

    json h;
    h["time"] = run.history.time;
    json points = json::array();
    for (const auto& row : run.history.points) {
        json r = json::array();
        for (const Point2& p : row) r.push_back({p.x, p.y});
        points.push_back(r);
    }
    h["points"] = points;
    j["history"] = h;

    double sx = 0, sy = 0, ax = 0, ay = 0;
    for (const Point2& p : mesh.nodes) sx += p.x, sy += p.y, ax += std::fabs(p.x), ay += std::fabs(p.y);
    j["mesh"] = {{"nodes", nodes}, {"elements", elements}, {"coordinate_sum", {sx, sy}}, {"coordinate_sum_abs", {ax, ay}}};

    double max_u = 0, sum_x = 0, sum_y = 0, abs_x = 0, abs_y = 0;
    for (int n = 0; n < nodes; ++n) {
        const double ux = s.displacement[2 * n], uy = s.displacement[2 * n + 1];
        max_u = std::max(max_u, std::hypot(ux, uy));
        sum_x += ux, sum_y += uy, abs_x += std::fabs(ux), abs_y += std::fabs(uy);
    }
    json sampled_u = json::array();
    for (int n : even_indices(nodes)) sampled_u.push_back({s.displacement[2 * n], s.displacement[2 * n + 1]});
    j["displacement"] = {{"max_abs", max_u},
                         {"sum", {sum_x, sum_y}},
                         {"sum_abs", {abs_x, abs_y}},
                         {"sample_nodes", even_indices(nodes)},
                         {"samples", sampled_u}};

    auto component = [&](int e, int k) { return k < 3 ? s.stress[e][k] : s.stress_zz[e]; };
    std::array<double, 4> sum{}, sum_abs{}, lo, hi;
    for (int k = 0; k < 4; ++k) lo[k] = hi[k] = elements ? component(0, k) : 0.0;
    for (int e = 0; e < elements; ++e)
        for (int k = 0; k < 4; ++k) {
            const double v = component(e, k);
            sum[k] += v, sum_abs[k] += std::fabs(v);
            lo[k] = std::min(lo[k], v), hi[k] = std::max(hi[k], v);
        }
    json sampled_s = json::array();
    for (int e : even_indices(elements)) sampled_s.push_back({component(e, 0), component(e, 1), component(e, 2), component(e, 3)});
    j["stress"] = {{"components", {"sxx", "syy", "sxy", "szz"}},
                   {"sum", sum},
                   {"sum_abs", sum_abs},
                   {"min", lo},
                   {"max", hi},
                   {"sample_elements", even_indices(elements)},
                   {"samples", sampled_s}};

    std::array<int, 3> states{};
    double plastic_sum = 0;
    for (int e = 0; e < elements; ++e) {
        const int st = s.plastic_state[e];
        if (st >= 0 && st < 3) ++states[st];
        plastic_sum += s.plastic_strain[e];
    }
    j["plasticity"] = {{"elements_by_state", states}, {"plastic_strain_sum", plastic_sum}};

    int open = 0, sliding = 0, locked = 0;
    for (const Contact& ct : s.contacts) {
        if (ct.state == ContactState::Open) ++open;
        else if (ct.state == ContactState::Sliding) ++sliding;
        else ++locked;
    }
    j["contacts"] = {{"open", open}, {"sliding", sliding}, {"locked", locked}};
    return j;
}

/// Compares a recorded and a new record, collecting the differences.
class Comparison {
public:
    Comparison(double relative, double floor) : relative_(relative), floor_(floor) {}

    void count(const std::string& what, const json& recorded, const json& actual) {
        ++checked_;
        if (recorded != actual) fail(what + ": " + actual.dump() + ", recorded " + recorded.dump());
    }

    /// |actual − recorded| ≤ relative·|reference| + floor·scale; reference defaults to the recorded value.
    void value(const std::string& what, double recorded, double actual, double scale, double reference = NAN) {
        ++checked_;
        if (std::isnan(reference)) reference = recorded;
        const double tolerance = relative_ * std::fabs(reference) + floor_ * scale;
        if (!(std::fabs(actual - recorded) <= tolerance)) {
            std::ostringstream m;
            m << std::setprecision(17) << what << ": " << actual << ", recorded " << recorded << " (difference "
              << std::setprecision(3) << actual - recorded << ", tolerance " << tolerance << ")";
            fail(m.str());
        }
    }

    /// Arrays of equal shape, element by element.
    void values(const std::string& what, const json& recorded, const json& actual, double scale) {
        if (recorded.is_number()) {
            if (!actual.is_number()) return fail(what + ": not a number");
            return value(what, recorded.get<double>(), actual.get<double>(), scale);
        }
        if (!recorded.is_array() || !actual.is_array() || recorded.size() != actual.size())
            return fail(what + ": shape " + std::to_string(actual.size()) + ", recorded " + std::to_string(recorded.size()));
        for (std::size_t i = 0; i < recorded.size(); ++i)
            values(what + "[" + std::to_string(i) + "]", recorded[i], actual[i], scale);
    }

    void fail(const std::string& message) {
        if (failures_.size() < 30) failures_.push_back(message);
        ++failed_;
    }

    int failed() const { return failed_; }
    int checked() const { return checked_; }
    std::string report() const {
        std::string text;
        for (const std::string& f : failures_) text += "  " + f + "\n";
        if (failed_ > static_cast<int>(failures_.size()))
            text += "  … and " + std::to_string(failed_ - failures_.size()) + " more\n";
        return text;
    }

private:
    double relative_, floor_;
    int checked_ = 0, failed_ = 0;
    std::vector<std::string> failures_;
};

double num(const json& j) { return j.get<double>(); }

/// Largest absolute number in a (nested) array.
double max_magnitude(const json& j) {
    if (j.is_number()) return std::fabs(j.get<double>());
    double m = 0;
    if (j.is_array())
        for (const json& e : j) m = std::max(m, max_magnitude(e));
    return m;
}

void compare(const BaselineCase& c, const json& r, const json& a) {
    Comparison cmp(c.relative, c.floor);
    // Counts first: with another mesh or step count the values cannot be compared.
    cmp.count("steps", r.at("steps"), a.at("steps"));
    cmp.count("mesh.nodes", r.at("mesh").at("nodes"), a.at("mesh").at("nodes"));
    cmp.count("mesh.elements", r.at("mesh").at("elements"), a.at("mesh").at("elements"));
    cmp.count("history length", r.at("history").at("time").size(), a.at("history").at("time").size());
    ASSERT_EQ(cmp.failed(), 0) << c.name << ": the run is not comparable with the baseline\n" << cmp.report();

    for (int k = 0; k < 2; ++k) {
        const json& rm = r.at("mesh");
        const json& am = a.at("mesh");
        const std::string axis = k == 0 ? "x" : "y";
        const double magnitude = num(rm.at("coordinate_sum_abs").at(k));
        cmp.value("mesh.coordinate_sum." + axis, num(rm.at("coordinate_sum").at(k)), num(am.at("coordinate_sum").at(k)),
                  0.0, magnitude);
        cmp.value("mesh.coordinate_sum_abs." + axis, magnitude, num(am.at("coordinate_sum_abs").at(k)), 0.0);
    }

    const json& rh = r.at("history");
    const json& ah = a.at("history");
    cmp.values("history.time", rh.at("time"), ah.at("time"), max_magnitude(rh.at("time")));
    cmp.values("history.points", rh.at("points"), ah.at("points"), max_magnitude(rh.at("points")));

    const json& ru = r.at("displacement");
    const json& au = a.at("displacement");
    const double u = ru.at("max_abs").get<double>();
    cmp.value("displacement.max_abs", u, au.at("max_abs").get<double>(), u);
    for (int k = 0; k < 2; ++k) {
        const std::string axis = k == 0 ? "x" : "y";
        cmp.value("displacement.sum." + axis, num(ru.at("sum").at(k)), num(au.at("sum").at(k)), u,
                  num(ru.at("sum_abs").at(k)));
        cmp.value("displacement.sum_abs." + axis, num(ru.at("sum_abs").at(k)), num(au.at("sum_abs").at(k)), u);
    }
    cmp.count("displacement.sample_nodes", ru.at("sample_nodes"), au.at("sample_nodes"));
    cmp.values("displacement.samples", ru.at("samples"), au.at("samples"), u);

    const json& rs = r.at("stress");
    const json& as = a.at("stress");
    const double sigma = std::max(max_magnitude(rs.at("min")), max_magnitude(rs.at("max")));
    for (int k = 0; k < 4; ++k) {
        const std::string name = rs.at("components")[k].get<std::string>();
        auto v = [&](const json& record, const char* field) { return num(record.at(field).at(k)); };
        cmp.value("stress.sum." + name, v(rs, "sum"), v(as, "sum"), sigma, v(rs, "sum_abs"));
        cmp.value("stress.sum_abs." + name, v(rs, "sum_abs"), v(as, "sum_abs"), sigma);
        cmp.value("stress.min." + name, v(rs, "min"), v(as, "min"), sigma);
        cmp.value("stress.max." + name, v(rs, "max"), v(as, "max"), sigma);
    }
    cmp.count("stress.sample_elements", rs.at("sample_elements"), as.at("sample_elements"));
    cmp.values("stress.samples", rs.at("samples"), as.at("samples"), sigma);

    cmp.count("plasticity.elements_by_state", r.at("plasticity").at("elements_by_state"), a.at("plasticity").at("elements_by_state"));
    const double ep = r.at("plasticity").at("plastic_strain_sum").get<double>();
    cmp.value("plasticity.plastic_strain_sum", ep, a.at("plasticity").at("plastic_strain_sum").get<double>(), ep);
    cmp.count("contacts", r.at("contacts"), a.at("contacts"));

    EXPECT_EQ(cmp.failed(), 0) << c.name << ": " << cmp.failed() << " of " << cmp.checked()
                               << " recorded values differ from this run\n"
                               << cmp.report();
}

std::string baseline_path(const BaselineCase& c) { return std::string(MCDDA_BASELINE_DIR) + "/" + c.name + ".json"; }

bool recording() {
    const char* v = std::getenv("MCDDA_RECORD_BASELINE");
    return v && std::string(v) == "1";
}

class RegressionBaseline : public ::testing::TestWithParam<BaselineCase> {};

}  // namespace

TEST_P(RegressionBaseline, MatchesTheRecordedRun) {
    const BaselineCase& c = GetParam();
    const auto run = mcdda::test::run_example(c.file, c.overrides, c.steps);
    ASSERT_TRUE(run.simulation) << c.name;
    ASSERT_EQ(run.simulation->state().step, c.steps) << c.name;
    const json actual = record(c, run);

    if (recording()) {
        std::ofstream out(baseline_path(c));
        ASSERT_TRUE(out) << "cannot write " << baseline_path(c);
        out << actual.dump(1) << "\n";
        ASSERT_TRUE(out.good()) << "writing " << baseline_path(c) << " failed";
        std::cout << "[ RECORDED ] " << c.name << ": " << c.steps << " steps -> " << baseline_path(c) << "\n";
        return;
    }

    std::ifstream in(baseline_path(c));
    ASSERT_TRUE(in) << "no baseline " << baseline_path(c) << " (record it with MCDDA_RECORD_BASELINE=1)";
    json recorded;
    ASSERT_NO_THROW(recorded = json::parse(in)) << baseline_path(c);
    try {
        compare(c, recorded, actual);
    } catch (const json::exception& e) {
        FAIL() << baseline_path(c) << " lacks a recorded field: " << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Examples, RegressionBaseline, ::testing::ValuesIn(cases),
                         [](const ::testing::TestParamInfo<BaselineCase>& info) {
                             std::string name = info.param.name;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

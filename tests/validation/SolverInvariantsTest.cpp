// Invariants of the solver: no spurious motion or energy, exact supports, the factorisation
// reused as designed.

#include "RunModel.hpp"
#include "parallel/ParallelFor.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;

namespace {

const char* free_blocks = R"({
  "format": "mcdda-model", "version": 1, "name": "free blocks",
  "materials": [ { "name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25, "density": 2500, "plastic": false } ],
  "regions": [ { "name": "a", "material": "rock", "boundary": [[0,0],[2,0],[2,1],[0,1]] },
               { "name": "b", "material": "rock", "boundary": [[0,1],[2,1],[2,2],[0,2]] } ],
  "mesh": { "size": 0.3 },
  "analysis": { "type": "dynamic", "steps": 40, "time_step": 0.01 }
})";

}  // namespace

TEST(SolverInvariants, FreeBlocksUnderNoLoadStayStillAndUnstressed) {
    auto run = mcdda::test::run_text(free_blocks);
    ASSERT_TRUE(run.simulation);
    const SimulationState& s = run.simulation->state();
    EXPECT_EQ(s.step, 40);
    EXPECT_LT(s.displacement.cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT(s.velocity.cwiseAbs().maxCoeff(), 1e-12);
    double largest_stress = 0.0;
    for (const auto& sigma : s.stress) largest_stress = std::max(largest_stress, sigma.cwiseAbs().maxCoeff());
    EXPECT_LT(largest_stress, 1e-3);  // Pa
}

TEST(SolverInvariants, SupportsAreExactAndTheSymbolicAnalysisIsKept) {
    // The far-field pressures grow by a percent a step, so that every step has something to solve.
    auto run = mcdda::test::run_example(
        "kirsch.json", {"/load_tables=[{\"name\": \"ramp\", \"variable\": \"step\", \"points\": [[0, 0.95], [5, 1]]}]",
                        "/edge_pressures/0/table=\"ramp\"", "/edge_pressures/1/table=\"ramp\""});
    ASSERT_TRUE(run.simulation);
    const Simulation& s = *run.simulation;
    // Rollers: x fixed on x = 0, y fixed on y = 0, exactly; the other direction of those nodes
    // moves (the symmetry planes are rollers, not fixed points).
    int on_x0 = 0, on_y0 = 0, x0_moving = 0, y0_moving = 0;
    for (std::size_t i = 0; i < s.mesh().nodes.size(); ++i) {
        const Point2 p = s.mesh().nodes[i];
        if (std::fabs(p.x) < 1e-12) {
            ++on_x0;
            EXPECT_EQ(s.state().displacement[2 * i], 0.0);
            x0_moving += s.state().displacement[2 * i + 1] != 0.0;
        }
        if (std::fabs(p.y) < 1e-12) {
            ++on_y0;
            EXPECT_EQ(s.state().displacement[2 * i + 1], 0.0);
            y0_moving += s.state().displacement[2 * i] != 0.0;
        }
    }
    // Both symmetry planes carry nodes (a model moved off them would check nothing).
    EXPECT_GE(on_x0, 10);
    EXPECT_GE(on_y0, 10);
    EXPECT_GE(x0_moving, on_x0 - 2);
    EXPECT_GE(y0_moving, on_y0 - 2);
    // One block, no contacts: one symbolic analysis, and one matrix per step, factorised or (the
    // geometry moved little) solved with the factor held from an earlier step.
    EXPECT_EQ(s.timings().symbolic_analyses, 1);
    EXPECT_EQ(s.timings().steps_at_rest, 0);
    EXPECT_EQ(s.timings().factorizations + s.timings().reused_factors, s.state().step);
    EXPECT_GE(s.timings().reused_factors, 1);
}

TEST(SolverInvariants, InSituStressWithoutOpeningsIsInEquilibrium) {
    // A plate carrying a uniform in-situ stress, with the boundary pressures that balance it:
    // nothing may move.
    auto run = mcdda::test::run_example("kirsch.json",
        {"/regions/0/boundary=[[0,0],[20,0],[20,20],[0,20]]", "/rollers/0/from=[0,0]", "/rollers/1/from=[0,0]",
         "/initial_stress={\"type\": \"uniform\", \"sxx\": 10e6, \"syy\": 5e6, \"sxy\": 0}", "/mesh/local=[]"}, 3);
    ASSERT_TRUE(run.simulation);
    EXPECT_LT(run.simulation->state().displacement.cwiseAbs().maxCoeff(), 1e-9);
}

// A static DDA step whose loads do not change, from a state in equilibrium under them, is a
// relaxation that stops at once: it solves nothing and moves nothing. A state out of balance (a
// block that must slide) and loads that change (gravity ramped) are still tried.
TEST(SolverInvariants, AStaticStepAtUnchangedLoadsFromEquilibriumSolvesNothing) {
    struct Case {
        const char* what;
        int friction_angle;
        bool ramped;
        bool held;
    };
    for (const Case& c : {Case{"standing block", 45, false, true}, Case{"sliding block", 30, false, false},
                          Case{"standing block, gravity ramped", 45, true, false}}) {
        std::vector<std::string> o = {"/analysis/type=\"static\"", "/analysis/steps=5",
                                      "/joint_materials/0/friction_angle=" + std::to_string(c.friction_angle)};
        if (c.ramped) {
            o.push_back("/load_tables=[{\"name\": \"ramp\", \"variable\": \"step\", \"points\": [[0, 0.5], [5, 1]]}]");
            o.push_back("/gravity_table=\"ramp\"");
        }
        auto run = mcdda::test::run_example("incline-stable.json", o, 2);
        ASSERT_TRUE(run.simulation) << c.what;
        Simulation& s = *run.simulation;
        EXPECT_EQ(s.state().unbalanced_ratio <= s.analysis().plastic_tolerance, c.friction_angle == 45) << c.what;
        const Eigen::VectorXd before = s.state().displacement;
        const int iterations = s.timings().iterations, at_rest = s.timings().steps_at_rest;
        for (int step = 3; step <= 5; ++step) {
            const StepReport r = s.advance();
            EXPECT_EQ(r.step, step) << c.what;
            EXPECT_EQ(r.load_increments == 0, c.held) << c.what << ", step " << step;
            if (c.held) EXPECT_EQ(r.plastic_iterations, 0) << c.what;
        }
        EXPECT_NEAR(s.state().time, 5 * s.analysis().time_step, 1e-12) << c.what;
        EXPECT_EQ(s.timings().steps_at_rest - at_rest, c.held ? 3 : 0) << c.what;
        if (c.held) {
            EXPECT_EQ(s.timings().iterations, iterations);
            for (Eigen::Index i = 0; i < before.size(); ++i) ASSERT_EQ(s.state().displacement[i], before[i]) << i;
        } else {
            EXPECT_GT(s.timings().iterations, iterations) << c.what;
            EXPECT_GT((s.state().displacement - before).cwiseAbs().maxCoeff(), 0.0) << c.what;
        }
    }
}

namespace mcdda {
namespace {

/// The element loops run on worker threads (parallel/ParallelFor.hpp) and reduce in element
/// order: one thread and two give the same run, bit for bit.
void expect_same_run_on_one_and_two_threads(const std::string& example, const std::vector<std::string>& overrides,
                                            int steps) {
    std::vector<mcdda::test::Run> runs;
    for (int threads : {1, 2}) {
        set_thread_count(threads);
        runs.push_back(mcdda::test::run_example(example, overrides, steps));
    }
    set_thread_count(0);
    ASSERT_TRUE(runs[0].simulation && runs[1].simulation);
    const SimulationState& one = runs[0].simulation->state();
    const SimulationState& two = runs[1].simulation->state();
    ASSERT_EQ(one.step, steps);
    ASSERT_EQ(two.step, steps);
    EXPECT_EQ(runs[0].simulation->timings().iterations, runs[1].simulation->timings().iterations);
    ASSERT_EQ(one.displacement.size(), two.displacement.size());
    for (Eigen::Index i = 0; i < one.displacement.size(); ++i)
        ASSERT_EQ(one.displacement[i], two.displacement[i]) << example << ", degree of freedom " << i;
    ASSERT_EQ(one.stress.size(), two.stress.size());
    for (std::size_t e = 0; e < one.stress.size(); ++e)
        ASSERT_EQ(one.stress[e], two.stress[e]) << example << ", element " << e;
}

TEST(SolverInvariants, OneAndTwoThreadsGiveTheSameBitsPlastic) {
    // Salençon's excavation: 10,513 six-node elements, more than one chunk of the loops.
    expect_same_run_on_one_and_two_threads("salencon-tunnel.json", {"/mesh/local/0/size=0.07"}, 2);
}

TEST(SolverInvariants, OneAndTwoThreadsGiveTheSameBitsWithContacts) {
    expect_same_run_on_one_and_two_threads("jointed-tunnel.json", {}, 3);
}

}  // namespace
}  // namespace mcdda

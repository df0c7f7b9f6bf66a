// Ground water (model/Model.hpp Water, fem/PorePressure.hpp): the piezometric line, the loads
// of the pore pressure on the mesh, and what the reader and the checker say about bad water.

#include "ModelCompare.hpp"
#include "TestModels.hpp"
#include "check/ModelValidator.hpp"
#include "fem/BoundaryConditions.hpp"
#include "fem/MeshTopology.hpp"
#include "fem/PorePressure.hpp"
#include "io/ModelReader.hpp"
#include "io/ModelWriter.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::has_diagnostic;
using mcdda::test::preprocess_text;
using mcdda::test::square_model_json;

namespace {

constexpr double gamma_w = 9810.0;

Water line_of(std::vector<Point2> points) {
    Water w;
    w.piezometric_line = std::move(points);
    return w;
}

/// Resultant (fx, fy) and moment about the origin of nodal forces `f` on the nodes of `blocks`
/// (all blocks when empty).
struct Resultant {
    double fx = 0.0, fy = 0.0, moment = 0.0;
};
Resultant resultant(const Mesh& mesh, const Eigen::VectorXd& f, int block = -1) {
    Resultant r;
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
        if (block >= 0 && mesh.node_block[n] != block) continue;
        r.fx += f[2 * n];
        r.fy += f[2 * n + 1];
        r.moment += mesh.nodes[n].x * f[2 * n + 1] - mesh.nodes[n].y * f[2 * n];
    }
    return r;
}

}  // namespace

TEST(PorePressure, HydrostaticBelowTheLineZeroAboveLevelBeyondItsEnds) {
    const Water w = line_of({{0, 4}, {10, 8}, {20, 8}});
    EXPECT_DOUBLE_EQ(w.level(5), 6.0);
    EXPECT_DOUBLE_EQ(w.level(-100), 4.0);  // held level beyond the ends
    EXPECT_DOUBLE_EQ(w.level(100), 8.0);
    EXPECT_DOUBLE_EQ(w.pore_pressure({5, 1}), gamma_w * 5.0);
    EXPECT_DOUBLE_EQ(w.pore_pressure({5, 6.5}), 0.0);
    EXPECT_DOUBLE_EQ(Water{}.pore_pressure({0, -100}), 0.0);  // dry
}

// The pore pressure's loads on a block, ∫Bᵀ m u dV plus the water pressure on its faces, add up
// to −∫∇u dV over its wet part: for a horizontal water table Archimedes' buoyancy γw·V acting at
// the wet part's centroid; for the sloping line of RS2's convention γw·V·(−slope, 1). Exact on
// both elements, block by block, with a joint cutting the square and the line crossing elements.
TEST(PorePressure, LoadsOfEachBlockAreItsBuoyancy) {
    for (const char* element : {"t3", "t6"}) {
        const Preprocessed p = preprocess_text(
            square_model_json(), {"/joints=[{\"name\": \"j\", \"points\": [[0, 3], [10, 7]]}]",
                                  std::string("/mesh/element=\"") + element + "\""});
        ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
        ASSERT_EQ(p.mesh.block_count(), 2);
        const MeshTopology topology = build_topology(p.mesh, p.blocks);
        // Under a lake 2 m deep: each block's loads are γw times its area, upwards, through its centroid.
        Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(p.mesh.nodes.size()));
        add_water_forces(line_of({{0, 12}, {10, 12}}), p.mesh, p.mesh.nodes, topology, {}, 1.0, f);
        // Block areas and centroids from the cut: below the joint (0,0)–(10,0)–(10,7)–(0,3).
        for (int b = 0; b < 2; ++b) {
            const Ring& ring = p.blocks[b].outer;
            double area = 0.0, cx = 0.0;
            for (std::size_t i = 0; i < ring.size(); ++i) {
                const Point2 a = ring[i], c = ring[(i + 1) % ring.size()];
                const double cross = a.x * c.y - c.x * a.y;
                area += 0.5 * cross;
                cx += (a.x + c.x) * cross / 6.0;
            }
            cx /= area;
            const Resultant r = resultant(p.mesh, f, b);
            EXPECT_NEAR(r.fx, 0.0, 1e-9 * gamma_w * area) << element << " block " << b;
            EXPECT_NEAR(r.fy, gamma_w * area, 1e-9 * gamma_w * area) << element << " block " << b;
            EXPECT_NEAR(r.moment, gamma_w * area * cx, 1e-9 * gamma_w * area * 10) << element << " block " << b;
        }
        // A sloping line from (0, 4) to (10, 8) crosses the square: the wet part is 60 m² and the
        // loads are γw·60·(−0.4, 1), whatever elements and faces it cuts.
        f.setZero();
        add_water_forces(line_of({{0, 4}, {10, 8}}), p.mesh, p.mesh.nodes, topology, {}, 1.0, f);
        const Resultant r = resultant(p.mesh, f);
        EXPECT_NEAR(r.fx, -0.4 * gamma_w * 60.0, 1e-9 * gamma_w * 60) << element;
        EXPECT_NEAR(r.fy, gamma_w * 60.0, 1e-9 * gamma_w * 60) << element;
        // The loads scale with gravity's table factor; absent elements get none.
        Eigen::VectorXd half = Eigen::VectorXd::Zero(f.size());
        add_water_forces(line_of({{0, 4}, {10, 8}}), p.mesh, p.mesh.nodes, topology, {}, 0.5, half);
        EXPECT_NEAR((half - 0.5 * f).norm(), 0.0, 1e-12 * f.norm());
        std::vector<char> active(p.mesh.triangles.size(), 0);
        Eigen::VectorXd none = Eigen::VectorXd::Zero(f.size());
        add_water_forces(line_of({{0, 4}, {10, 8}}), p.mesh, p.mesh.nodes, topology, active, 1.0, none);
        EXPECT_EQ(none.norm(), 0.0);
    }
}

// Gravity weighs the saturated unit weight below the line and the unit weight above it.
TEST(PorePressure, SaturatedUnitWeightBelowTheLine) {
    const Preprocessed p = preprocess_text(
        square_model_json(), {"/gravity=[0, -10]", "/materials/0/saturated_unit_weight=25506",
                              "/joints=[{\"name\": \"water table\", \"points\": [[0, 5], [10, 5]]}]",
                              R"(/water={"piezometric_line": [[0, 5], [10, 5]]})", "/mesh/size=0.5"});
    ASSERT_TRUE(p.ok) << all_messages(p.diagnostics);
    EXPECT_DOUBLE_EQ(p.model.materials[0].saturated_density, 25506.0 / 9.81);
    const MeshTopology topology = build_topology(p.mesh, p.blocks);
    std::vector<Diagnostic> d;
    const BoundaryConditions bc = locate_boundary_conditions(p.model, p.mesh, topology, d);
    Model dry = p.model;
    dry.water = Water{};
    const Eigen::VectorXd weight = external_forces(dry, p.mesh, p.mesh.nodes, topology, bc, 0, 0);
    const Eigen::VectorXd wet = external_forces(p.model, p.mesh, p.mesh.nodes, topology, bc, 0, 0);
    Eigen::VectorXd water = Eigen::VectorXd::Zero(wet.size());
    add_water_forces(p.model.water, p.mesh, p.mesh.nodes, topology, {}, 1.0, water);
    // 50 m² at 2500 kg/m³ above, 50 m² at 2600 kg/m³ below, then the water's own loads.
    const Resultant dry_weight = resultant(p.mesh, weight), wet_weight = resultant(p.mesh, wet - water);
    EXPECT_NEAR(dry_weight.fy, -2500.0 * 10 * 100, 1e-9 * 2.5e6);
    EXPECT_NEAR(wet_weight.fy, -(2500.0 * 50 + 2600.0 * 50) * 10, 1e-9 * 2.5e6);
}

TEST(PorePressure, ReaderAndCheckerRefuseBadWater) {
    auto diagnostics = [](const std::vector<std::string>& overrides) {
        ReadResult r = read_model_text(square_model_json(), overrides);
        std::vector<Diagnostic> d = r.diagnostics;
        if (r.model) validate_model(*r.model, d);
        return d;
    };
    using S = Diagnostic::Severity;
    auto d = diagnostics({R"(/water={"piezometric_line": [[0, 5], [6, 6], [4, 7], [10, 5]]})"});
    EXPECT_TRUE(has_diagnostic(d, S::Error, "/water/piezometric_line/2", "left of point 2")) << all_messages(d);
    d = diagnostics({R"(/water={"piezometric_line": [[0, 5], [0, 6]]})"});
    EXPECT_TRUE(has_diagnostic(d, S::Error, "/water/piezometric_line/1", "straight above or below")) << all_messages(d);
    d = diagnostics({R"(/water={"piezometric_line": [[0, 5], [10, 5]], "unit_weight": 0})"});
    EXPECT_TRUE(has_diagnostic(d, S::Error, "/water/unit_weight", "must be positive")) << all_messages(d);
    d = diagnostics({R"(/water={"piezometric_line": [[0, 5], [10, 5]], "unit_weight": -9810})"});
    EXPECT_TRUE(has_diagnostic(d, S::Error, "/water/unit_weight", "must be positive")) << all_messages(d);
    d = diagnostics({R"(/water={"piezometric_line": [[0, 5], [10000, 5]]})"});
    EXPECT_TRUE(has_diagnostic(d, S::Error, "/water/piezometric_line/1", "far outside the model")) << all_messages(d);
    d = diagnostics({R"(/water={"piezometric_line": [[0, 5]]})"});
    EXPECT_TRUE(has_diagnostic(d, S::Error, "/water/piezometric_line", "at least two points")) << all_messages(d);
    d = diagnostics({R"(/water={"level": 5})"});
    EXPECT_TRUE(has_diagnostic(d, S::Error, "/water/level", "unknown key")) << all_messages(d);
    EXPECT_TRUE(has_diagnostic(d, S::Error, "/water/piezometric_line", "missing")) << all_messages(d);
    d = diagnostics({R"(/water={"piezometric_line": [[0, 5], [10, 5]]})", "/materials/0/saturated_unit_weight=20000"});
    EXPECT_TRUE(has_diagnostic(d, S::Warning, "/materials/0/saturated_density", "lighter saturated than dry"))
        << all_messages(d);
    // Good water passes without a word (the square has gravity).
    d = diagnostics({R"(/water={"piezometric_line": [[-5, 5], [15, 6]]})", "/gravity=[0, -9.81]"});
    EXPECT_TRUE(d.empty()) << all_messages(d);
}

TEST(PorePressure, StageWaterHoldsUntilAnotherStageChangesIt) {
    const std::string staged = R"({"format": "mcdda-model", "version": 2,
      "materials": [{"name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25, "density": 2500, "law": "elastic"}],
      "regions": [{"name": "square", "material": "rock", "boundary": [[0,0],[10,0],[10,10],[0,10]]}],
      "rollers": [{"name": "base", "from": [0,0], "to": [10,0], "fixed": "xy"}],
      "gravity": [0, -9.81],
      "water": {"piezometric_line": [[0, 8], [10, 8]]},
      "stages": [{"name": "initial"}, {"name": "drawdown", "water": {"piezometric_line": [[0, 2], [10, 3]]}},
                 {"name": "later"}, {"name": "dry", "water": {"piezometric_line": []}}]})";
    const ReadResult r = read_model_text(staged);
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    const Model& m = *r.model;
    EXPECT_DOUBLE_EQ(water_of_stage(m, 0).level(5), 8.0);
    EXPECT_DOUBLE_EQ(water_of_stage(m, 1).level(5), 2.5);
    EXPECT_DOUBLE_EQ(water_of_stage(m, 2).level(5), 2.5);
    EXPECT_FALSE(water_of_stage(m, 3).present());
    EXPECT_TRUE(has_water(m));
    // Written and read back: the same water in every stage.
    const ReadResult again = read_model_text(write_model_text(m));
    ASSERT_TRUE(again.model) << all_messages(again.diagnostics);
    EXPECT_EQ(mcdda::test::model_differences(m, *again.model), "");
}

// Bad input: impossible materials, degenerate and self-intersecting geometry, overlaps, joints
// outside every region, nothing fixed. Every problem must name the item by its JSON pointer.

#include "TestModels.hpp"
#include "check/ModelValidator.hpp"

#include <gtest/gtest.h>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::has_diagnostic;
using mcdda::test::preprocess_text;
using mcdda::test::square_model_json;
using Severity = Diagnostic::Severity;

namespace {

/// Runs the square model with `overrides` up to block cutting and expects an error at `path`.
void expect_error(const std::vector<std::string>& overrides, const std::string& path, const std::string& fragment) {
    EXPECT_EQ(mcdda::test::refusal_mismatch(overrides, path, fragment), "");
}

}  // namespace

TEST(ModelValidation, TheBaseModelIsValid) {
    const Preprocessed p = preprocess_text(square_model_json());
    EXPECT_TRUE(p.ok) << all_messages(p.diagnostics);
    EXPECT_TRUE(p.diagnostics.empty()) << all_messages(p.diagnostics);
}

TEST(ModelValidation, ImpossibleMaterialValues) {
    expect_error({"/materials/0/young_modulus=0"}, "/materials/0/young_modulus", "must be positive");
    expect_error({"/materials/0/young_modulus=-5e9"}, "/materials/0/young_modulus", "must be positive");
    expect_error({"/materials/0/poisson_ratio=0.5"}, "/materials/0/poisson_ratio", "(-1, 0.5)");
    expect_error({"/materials/0/poisson_ratio=-1"}, "/materials/0/poisson_ratio", "(-1, 0.5)");
    expect_error({"/materials/0/friction_angle=90"}, "/materials/0/friction_angle", "[0°, 90°)");
    expect_error({"/materials/0/friction_angle=-1"}, "/materials/0/friction_angle", "[0°, 90°)");
    expect_error({"/materials/0/dilation_angle=35"}, "/materials/0/dilation_angle", "exceeds the friction angle");
    expect_error({"/materials/0/cohesion=-1"}, "/materials/0/cohesion", "must not be negative");
    expect_error({"/materials/0/tensile_strength=-1"}, "/materials/0/tensile_strength", "must not be negative");
    expect_error({"/joint_materials/0/friction_angle=95"}, "/joint_materials/0/friction_angle", "[0°, 90°)");
    expect_error({"/joint_materials/0/cohesion=-3"}, "/joint_materials/0/cohesion", "must not be negative");
}

TEST(ModelValidation, NothingFixed) {
    expect_error({"/rollers=[]"}, "", "nothing is fixed");
    // A dynamic analysis of free blocks is solvable (inertia): only a warning.
    const Preprocessed p = preprocess_text(square_model_json(), {"/rollers=[]", "/analysis={\"type\": \"dynamic\"}"},
                                           PreprocessStage::Cut);
    EXPECT_TRUE(p.ok) << all_messages(p.diagnostics);
    EXPECT_TRUE(has_diagnostic(p.diagnostics, Severity::Warning, "", "nothing is fixed"));
}

TEST(ModelValidation, AnEmptyModelOnlyLacksARegion) {
    // A new model in the desktop program, before anything is drawn: the
    // missing region is the one thing to say, not "nothing is fixed".
    Model empty;
    empty.materials.push_back(Material{});
    empty.materials[0].young_modulus = 1e9;
    empty.materials[0].poisson_ratio = 0.25;
    std::vector<Diagnostic> found;
    validate_model(empty, found);
    EXPECT_TRUE(has_diagnostic(found, Severity::Error, "/regions", "at least one region")) << all_messages(found);
    for (const Diagnostic& d : found) EXPECT_EQ(d.message.find("nothing is fixed"), std::string::npos) << d.message;
}

TEST(ModelValidation, DegenerateAndSelfIntersectingPolygons) {
    expect_error({"/regions/0/boundary=[[0,0],[10,10],[10,0],[0,10]]"}, "/regions/0/boundary", "intersects itself");
    expect_error({"/regions/0/boundary=[[0,0],[5,5],[10,10]]"}, "/regions/0/boundary", "zero area");
    expect_error({"/regions/0/boundary=[[0,0],[10,0]]"}, "/regions/0/boundary", "at least 3 vertices");
    expect_error({"/regions/0/boundary=[[0,0],[10,0],[10,0],[0,10]]"}, "/regions/0/boundary", "repeats");
    expect_error({"/regions/0/holes=[[[8,8],[12,8],[12,12],[8,12]]]"}, "/regions/0/holes/0", "not strictly inside");
    expect_error({"/regions/0/holes=[[[1,1],[3,1],[3,3],[1,3]], [[2,2],[4,2],[4,4],[2,4]]]"}, "/regions/0/holes/1",
                 "overlaps");
    expect_error({"/regions/0/holes=[[[1,1],[3,3],[3,1],[1,3]]]"}, "/regions/0/holes/0", "intersects itself");
}

TEST(ModelValidation, OverlappingRegions) {
    expect_error({"/regions/-={\"name\": \"intruder\", \"material\": \"rock\", \"boundary\": [[5,5],[15,5],[15,15],[5,15]]}"},
                 "/regions/1", "overlaps region \"square\"");
    // Sharing an edge is not an overlap: two blocks result.
    const Preprocessed p = preprocess_text(
        square_model_json(),
        {"/regions/-={\"name\": \"neighbour\", \"material\": \"rock\", \"boundary\": [[10,0],[20,0],[20,10],[10,10]]}"},
        PreprocessStage::Cut);
    EXPECT_TRUE(p.ok) << all_messages(p.diagnostics);
    EXPECT_EQ(p.blocks.size(), 2u);
    // A region filling another region's hole is no overlap either.
    const Preprocessed island = preprocess_text(
        square_model_json(),
        {"/regions/0/holes=[[[2,2],[8,2],[8,8],[2,8]]]",
         "/regions/-={\"name\": \"plug\", \"material\": \"rock\", \"boundary\": [[2,2],[8,2],[8,8],[2,8]]}"},
        PreprocessStage::Cut);
    EXPECT_TRUE(island.ok) << all_messages(island.diagnostics);
    EXPECT_EQ(island.blocks.size(), 2u);
}

TEST(ModelValidation, JointOutsideEveryRegion) {
    expect_error({"/joints=[{\"name\": \"stray\", \"points\": [[20,20],[30,25]]}]"}, "/joints/0", "outside every region");
    expect_error({"/joints=[{\"name\": \"dot\", \"points\": [[2,2],[2,2]]}]"}, "/joints/0/points/1", "zero-length");
    expect_error({"/joints=[{\"name\": \"short\", \"points\": [[2,2]]}]"}, "/joints/0/points", "at least 2 points");
    expect_error({"/joints=[{\"name\": \"j\", \"points\": [[0,5],[10,5]], \"joint_material\": \"glue\"}]"},
                 "/joints/0/joint_material", "no joint material named \"glue\"");
}

TEST(ModelValidation, JointSetPersistenceTraceLengthAndStagger) {
    const std::string set = "/joint_sets=[{\"angle\": 30, \"spacing\": 2, ";
    expect_error({set + "\"persistence\": 0, \"trace_length\": 1}]"}, "/joint_sets/0/persistence", "(0, 1] (got 0)");
    expect_error({set + "\"persistence\": -0.5, \"trace_length\": 1}]"}, "/joint_sets/0/persistence", "(0, 1]");
    expect_error({set + "\"persistence\": 1.5}]"}, "/joint_sets/0/persistence", "(0, 1] (got 1.5)");
    expect_error({set + "\"persistence\": 0.5}]"}, "/joint_sets/0/trace_length", "needs a positive trace length");
    expect_error({set + "\"persistence\": 0.5, \"trace_length\": 0}]"}, "/joint_sets/0/trace_length",
                 "needs a positive trace length");
    expect_error({set + "\"trace_length\": -2}]"}, "/joint_sets/0/trace_length", "must not be negative");
    expect_error({set + "\"persistence\": 0.5, \"trace_length\": 1, \"stagger\": 1}]"}, "/joint_sets/0/stagger",
                 "[0, 1) (got 1)");
    expect_error({set + "\"persistence\": 0.5, \"trace_length\": 1, \"stagger\": -0.1}]"}, "/joint_sets/0/stagger",
                 "[0, 1)");
    // 71 traces of 7071 segments each: far beyond the limit, refused before any is generated.
    expect_error({"/joint_sets=[{\"angle\": 0, \"spacing\": 0.2, \"persistence\": 0.5, \"trace_length\": 0.001}]"},
                 "/joint_sets/0/trace_length", "would generate more than 50000 joint segments");
    // The trace guard still applies to persistent sets.
    expect_error({"/joint_sets=[{\"angle\": 0, \"spacing\": 0.001}]"}, "/joint_sets/0/spacing",
                 "would generate more than 5000 joints");
    // Valid non-persistent sets pass: fully persistent with a trace length is fine too.
    for (const std::string& ok : {set + "\"persistence\": 0.5, \"trace_length\": 1, \"stagger\": 0}]",
                                  set + "\"persistence\": 1, \"trace_length\": 3}]"}) {
        const Preprocessed p = preprocess_text(square_model_json(), {ok}, PreprocessStage::Validate);
        EXPECT_TRUE(p.ok) << ok << "\n" << all_messages(p.diagnostics);
    }
}

TEST(ModelValidation, ControlsOutOfRange) {
    expect_error({"/mesh/min_angle=40"}, "/mesh/min_angle", "34°");
    expect_error({"/mesh/size=-1"}, "/mesh/size", "positive");
    expect_error({"/regions/0/mesh_size=-0.5"}, "/regions/0/mesh_size", "the region's mesh size must be positive");
    expect_error({"/analysis={\"time_step\": 0}"}, "/analysis/time_step", "must be positive");
    expect_error({"/analysis={\"steps\": 0}"}, "/analysis/steps", "at least one step");
    expect_error({"/analysis={\"type\": \"dynamic\"}", "/materials/0/density=0"}, "/materials/0/density",
                 "dynamic analysis needs a positive density");
    expect_error({"/load_tables=[{\"name\": \"t\", \"points\": [[0,0],[0,1]]}]"}, "/load_tables/0/points/1",
                 "increase strictly");
    expect_error({"/rollers/0/to=[0,0]"}, "/rollers/0", "same point");
    expect_error({"/rollers/0/fixed=\"z\""}, "/rollers/0/fixed", "\"x\", \"y\" or \"xy\"");
    expect_error({"/regions/0/boundary/1=[1e12, 0]"}, "/regions/0/boundary/1", "beyond");
}

TEST(ModelValidation, TooFineAMeshIsRefusedBeforeMeshing) {
    const Preprocessed p = preprocess_text(square_model_json(), {"/mesh/size=1e-5"});
    EXPECT_FALSE(p.ok);
    EXPECT_TRUE(has_diagnostic(p.diagnostics, Severity::Error, "/mesh", "above the limit")) << all_messages(p.diagnostics);
    EXPECT_TRUE(p.mesh.triangles.empty());
}

// Load tables as an editor can leave them in memory (the reader refuses them in a file first).
TEST(ModelValidation, LoadTablesNeedNamesPointsAndExistingReferences) {
    Model m;
    m.load_tables.resize(3);
    m.load_tables[0].name = "ramp";
    m.load_tables[0].points = {{0.0, 0.0}, {1.0, 1.0}};
    m.load_tables[1].name = "ramp";
    m.load_tables[1].points = {{0.0, 1.0}};
    m.load_tables[2].points = {};
    m.point_loads.resize(2);
    m.point_loads[0].table = 2;
    m.point_loads[1].table = 3;
    m.edge_pressures.resize(1);
    m.edge_pressures[0].from = {0.0, 0.0};
    m.edge_pressures[0].to = {1.0, 0.0};
    m.edge_pressures[0].table = -2;
    std::vector<Diagnostic> d;
    validate_model(m, d);
    EXPECT_TRUE(has_diagnostic(d, Severity::Error, "/load_tables/0/name", "another load table")) << all_messages(d);
    EXPECT_TRUE(has_diagnostic(d, Severity::Error, "/load_tables/1/name", "another load table")) << all_messages(d);
    EXPECT_TRUE(has_diagnostic(d, Severity::Error, "/load_tables/2/name", "needs a name")) << all_messages(d);
    EXPECT_TRUE(has_diagnostic(d, Severity::Error, "/load_tables/2/points", "at least one")) << all_messages(d);
    EXPECT_FALSE(has_diagnostic(d, Severity::Error, "/point_loads/0/table", "")) << all_messages(d);
    EXPECT_TRUE(has_diagnostic(d, Severity::Error, "/point_loads/1/table", "missing load table")) << all_messages(d);
    EXPECT_TRUE(has_diagnostic(d, Severity::Error, "/edge_pressures/0/table", "missing load table")) << all_messages(d);
}

// Absurd magnitudes (a typo, a unit error) used to be accepted and then ran for minutes or
// reported nonsense collapses: they are refused with the value and the limit.
TEST(ModelValidation, AbsurdMagnitudesAreRefused) {
    expect_error({"/gravity=[0, -9.2e18]"}, "/gravity", "beyond any physical value");
    expect_error({"/materials/0/young_modulus=1e20"}, "/materials/0/young_modulus", "check the units");
    expect_error({"/materials/0/density=2.5e9"}, "/materials/0/density", "beyond any physical value");
    expect_error({"/materials/0/cohesion=1e15"}, "/materials/0/cohesion", "beyond any physical value");
    expect_error({"/gravity=[0, -9.81]", R"(/initial_stress={"type": "gravity", "surface_y": 1e30, "k0": 0.5})"},
                 "/initial_stress/surface_y", "beyond ±1e7 m");
    expect_error({"/gravity=[0, -9.81]", R"(/initial_stress={"type": "gravity", "surface_y": 9e6, "k0": 0.5})",
                  "/materials/0/density=90000"},
                 "/initial_stress/surface_y", "in-situ vertical stress at the model's base");
    expect_error({R"(/initial_stress={"type": "uniform", "sxx": 1e13, "syy": 1e6})"}, "/initial_stress/sxx",
                 "beyond any physical value");
    // A contact spring a thousand times stiffer than the stiffest rock (E = 1 GPa here) adds
    // nothing but ill-conditioning (1.8e19 N/m on the jointed tunnel: 230 s for one step).
    expect_error({"/joint_materials/0/shear_stiffness=18446744073709551617"}, "/joint_materials/0/shear_stiffness",
                 "more than 1000 times the stiffest material's Young's modulus (1e+09 Pa): use at most 1e+12 N/m");
    expect_error({"/joint_materials/0/normal_stiffness=2e12"}, "/joint_materials/0/normal_stiffness", "use at most 1e+12 N/m");
    expect_error({R"(/analysis={"type": "static", "penalty": 5e12})"}, "/analysis/penalty", "or 0 (automatic: 4e+09 N/m)");
    // Large but physical values pass: 200 g, a 10 km overburden, a "rigid" plate, stiff springs.
    const Preprocessed p = preprocess_text(
        square_model_json(),
        {"/gravity=[0, -1962]", R"(/initial_stress={"type": "gravity", "surface_y": 10000, "k0": 0.5})",
         "/materials/0/young_modulus=1e13", "/joint_materials/0/normal_stiffness=1e16", R"(/analysis={"type": "static", "penalty": 1e16})"},
        PreprocessStage::Cut);
    EXPECT_TRUE(p.ok) << all_messages(p.diagnostics);
}

// The model file reader: structure, types, units and signs, overrides, messages with locations.

#include "TestModels.hpp"
#include "io/ModelReader.hpp"
#include "check/ModelValidator.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::has_diagnostic;
using mcdda::test::square_model_json;
using Severity = Diagnostic::Severity;

namespace {
constexpr double pi = 3.14159265358979323846;
}

TEST(ModelReader, ReadsEveryExample) {
    for (const std::string& file : mcdda::test::example_files()) {
        const ReadResult r = read_model_file(file);
        EXPECT_TRUE(r.model.has_value()) << file << "\n" << all_messages(r.diagnostics);
        EXPECT_FALSE(has_errors(r.diagnostics)) << file << "\n" << all_messages(r.diagnostics);
    }
}

TEST(ModelReader, ConvertsDegreesUnitWeightAndCompressionPositiveStress) {
    const std::string text = R"({"format": "mcdda-model", "version": 1,
      "materials": [{"name": "m", "young_modulus": 1e9, "poisson_ratio": 0.2, "unit_weight": 24525,
                     "cohesion": 1e5, "friction_angle": 30, "dilation_angle": 10}],
      "regions": [{"material": "m", "boundary": [[0,0],[1,0],[1,1]]}],
      "fixed_points": [{"point": [0,0]}],
      "initial_stress": {"type": "uniform", "sxx": 3e6, "syy": 4e6, "sxy": 1e6}})";
    const ReadResult r = read_model_text(text);
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    const Model& m = *r.model;
    EXPECT_NEAR(m.materials[0].parameter("friction_angle"), pi / 6, 1e-12);
    EXPECT_NEAR(m.materials[0].parameter("dilation_angle"), pi / 18, 1e-12);
    EXPECT_NEAR(m.materials[0].density, 2500.0, 1e-9);  // γ / 9.81
    // Entered compression positive, stored tension positive.
    EXPECT_EQ(m.initial_stress.kind, InitialStress::Kind::Uniform);
    EXPECT_DOUBLE_EQ(m.initial_stress.stress[0], -3e6);
    EXPECT_DOUBLE_EQ(m.initial_stress.stress[1], -4e6);
    EXPECT_DOUBLE_EQ(m.initial_stress.stress[2], -1e6);
    // No joint materials given: a default exists for region interfaces.
    ASSERT_EQ(m.joint_materials.size(), 1u);
    EXPECT_EQ(m.default_joint_material, 0);
}

TEST(ModelReader, MalformedJsonReportsLineAndColumn) {
    const std::string text = "{\n  \"format\": \"mcdda-model\",\n  \"version\": 1,,\n}";
    const ReadResult r = read_model_text(text, {}, "bad.json");
    ASSERT_FALSE(r.model);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_NE(r.diagnostics[0].message.find("bad.json:3:"), std::string::npos) << r.diagnostics[0].message;
    EXPECT_NE(r.diagnostics[0].message.find("malformed JSON"), std::string::npos);
}

// Any format but "mcdda-model" is refused, the empty one too.
TEST(ModelReader, FormatMustBeTheModelFormat) {
    for (const std::string& format : {std::string(""), std::string("mcdda-study"), std::string("MCDDA-MODEL")}) {
        const ReadResult r = read_model_text(square_model_json(), {"/format=\"" + format + "\""});
        EXPECT_FALSE(r.model) << format;
        const std::string words = "must be \"mcdda-model\", got \"" + format + "\"";
        EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/format", words)) << all_messages(r.diagnostics);
    }
}

// A directory or device is refused by what it is, before reading (/dev/zero never ends).
TEST(ModelReader, WhatIsNotAFileIsRefusedUnread) {
    for (const char* path : {"/dev/zero", "/tmp"}) {
        const ReadResult r = read_model_file(path);
        EXPECT_FALSE(r.model);
        EXPECT_NE(all_messages(r.diagnostics).find(std::string(path) + " is a "), std::string::npos)
            << all_messages(r.diagnostics);
    }
}

// A --set value that is not valid JSON is text, which JSON holds in UTF-8 only: other bytes are
// refused there, not left for writing the results to fail on.
TEST(ModelReader, OverrideTextMustBeUtf8) {
    const ReadResult r = read_model_text(square_model_json(), {"/name=ro\xff" "ck"});
    EXPECT_FALSE(r.model);
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/name", "not UTF-8")) << all_messages(r.diagnostics);
}

// A 10 MB key was printed in full twice (pointer and message); '/' and '~' in a key
// must be escaped in its pointer.
TEST(ModelReader, AVeryLongOrOddUnknownKeyIsShownShortAndEscaped) {
    std::string text = square_model_json();
    const std::string key(1 << 20, 'x');
    text.insert(text.find("\"name\": \"rock\""), "\"" + key + "\": 1, ");
    const ReadResult r = read_model_text(text, {"/materials/0/a~0b~1c=1"});
    EXPECT_FALSE(r.model);
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/materials/0", "(1048576 characters;"))
        << all_messages(r.diagnostics).substr(0, 2000);
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/materials/0/a~0b~1c", "unknown key \"a~b/c\""))
        << all_messages(r.diagnostics).substr(0, 2000);
    for (const Diagnostic& d : r.diagnostics) EXPECT_LT(d.path.size() + d.message.size(), 1000u);
}

TEST(ModelReader, UnknownKeysMissingFieldsAndWrongTypesAreNamed) {
    const ReadResult r = read_model_text(square_model_json(),
                                         {"/materials/0/youngs_modulus=1e9", "/regions/0/material=\"granite\"",
                                          "/mesh/size=\"fine\"", "/analysis={\"steps\": 2.5}"});
    EXPECT_FALSE(r.model);
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/materials/0/youngs_modulus", "unknown key"))
        << all_messages(r.diagnostics);
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/regions/0/material", "no material named \"granite\""));
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/mesh/size", "must be a number, got a string"));
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/analysis/steps", "whole number"));

    const ReadResult missing = read_model_text(square_model_json(), {"/materials/0={\"name\": \"rock\"}"});
    EXPECT_TRUE(has_diagnostic(missing.diagnostics, Severity::Error, "/materials/0/young_modulus", "missing"));
    EXPECT_TRUE(has_diagnostic(missing.diagnostics, Severity::Error, "/materials/0/poisson_ratio", "missing"));
}

TEST(ModelReader, JointSetPersistenceFields) {
    const ReadResult r = read_model_text(square_model_json(),
                                         {"/joint_sets=[{\"angle\": 10, \"spacing\": 1},"
                                          " {\"angle\": 20, \"spacing\": 2, \"persistence\": 0.6, \"trace_length\": 3.5,"
                                          "  \"stagger\": 0.125}]"});
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    const JointSet& plain = r.model->joint_sets[0];
    EXPECT_EQ(plain.persistence, 1.0);  // fully persistent unless told otherwise
    EXPECT_EQ(plain.trace_length, 0.0);
    EXPECT_EQ(plain.stagger, 0.5);
    const JointSet& bridged = r.model->joint_sets[1];
    EXPECT_EQ(bridged.persistence, 0.6);
    EXPECT_EQ(bridged.trace_length, 3.5);
    EXPECT_EQ(bridged.stagger, 0.125);

    const ReadResult bad = read_model_text(square_model_json(),
                                           {"/joint_sets=[{\"angle\": 0, \"spacing\": 1, \"persistence\": \"half\","
                                            " \"trace_length\": [1], \"persistance\": 0.5}]"});
    EXPECT_FALSE(bad.model);
    EXPECT_TRUE(has_diagnostic(bad.diagnostics, Severity::Error, "/joint_sets/0/persistence", "must be a number, got a string"))
        << all_messages(bad.diagnostics);
    EXPECT_TRUE(has_diagnostic(bad.diagnostics, Severity::Error, "/joint_sets/0/trace_length", "must be a number, got an array"));
    EXPECT_TRUE(has_diagnostic(bad.diagnostics, Severity::Error, "/joint_sets/0/persistance", "unknown key"));
}

TEST(ModelReader, FormatAndVersionAreChecked) {
    const ReadResult wrong = read_model_text(square_model_json(), {"/version=3", "/format=\"dda\""});
    EXPECT_TRUE(has_diagnostic(wrong.diagnostics, Severity::Error, "/version", "versions 1 to 2, the file is version 3"))
        << all_messages(wrong.diagnostics);
    EXPECT_TRUE(has_diagnostic(wrong.diagnostics, Severity::Error, "/format", "mcdda-model"));
}

TEST(ModelReader, OverridesChangeFieldsAndReportBadPointers) {
    const ReadResult r = read_model_text(square_model_json(), {"/materials/0/cohesion=3.45e6", "/name=study 7"});
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    EXPECT_DOUBLE_EQ(r.model->materials[0].parameter("cohesion"), 3.45e6);
    EXPECT_EQ(r.model->name, "study 7");  // not valid JSON, so taken as a string

    const ReadResult bad = read_model_text(square_model_json(), {"/materials/7/cohesion=1", "cohesion", "/regions/0/boundary/9=[1,2]"});
    EXPECT_TRUE(has_diagnostic(bad.diagnostics, Severity::Error, "/materials/7/cohesion", "no field /materials/7"));
    EXPECT_TRUE(has_diagnostic(bad.diagnostics, Severity::Error, "cohesion", "POINTER=VALUE"));
    EXPECT_TRUE(has_diagnostic(bad.diagnostics, Severity::Error, "/regions/0/boundary/9", "past the end"));
}

TEST(ModelReader, NonAssociatedFlowOfAStrengthReduction) {
    const ReadResult defaults = read_model_text(square_model_json(), {"/analysis={\"type\":\"strength_reduction\"}"});
    ASSERT_TRUE(defaults.model) << all_messages(defaults.diagnostics);
    EXPECT_EQ(defaults.model->analysis.non_associated_flow, AnalysisSettings::NonAssociatedFlow::Davis);
    const ReadResult direct = read_model_text(square_model_json(), {"/analysis={\"non_associated_flow\":\"direct\"}"});
    ASSERT_TRUE(direct.model) << all_messages(direct.diagnostics);
    EXPECT_EQ(direct.model->analysis.non_associated_flow, AnalysisSettings::NonAssociatedFlow::Direct);
    const ReadResult bad = read_model_text(square_model_json(), {"/analysis={\"non_associated_flow\":\"Davies\"}"});
    EXPECT_TRUE(has_diagnostic(bad.diagnostics, Severity::Error, "/analysis/non_associated_flow",
                               "must be \"davis\" or \"direct\", got \"Davies\""));
}

TEST(ModelReader, CirclesAndArcsBecomeRingsThatCloseExactly) {
    const ReadResult r = read_model_text(square_model_json(),
        {"/regions/0/boundary=[[10,0],[10,10],[0,10],{\"arc\":{\"center\":[0,0],\"radius\":2,\"start\":90,\"end\":0,\"segments\":8}}]",
         "/regions/0/holes=[{\"circle\":{\"center\":[6,6],\"radius\":1,\"segments\":16}}]"});
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    const Region& region = r.model->regions[0];
    // 3 corners + 9 arc points (both ends), none repeated.
    ASSERT_EQ(region.boundary.size(), 12u);
    EXPECT_EQ(region.boundary[3].x, 0.0);  // arc start snapped onto the axis
    EXPECT_EQ(region.boundary[3].y, 2.0);
    EXPECT_EQ(region.boundary.back().x, 2.0);
    EXPECT_EQ(region.boundary.back().y, 0.0);
    ASSERT_EQ(region.holes.size(), 1u);
    EXPECT_EQ(region.holes[0].size(), 16u);
    for (const Point2& p : region.holes[0]) EXPECT_NEAR(std::hypot(p.x - 6, p.y - 6), 1.0, 1e-12);
}

TEST(ModelReader, LoadTableExpressesFiveKilopascalsPerStep) {
    const ReadResult r = read_model_file(mcdda::test::example_path("prandtl-footing.json"));
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    const Model& m = *r.model;
    ASSERT_EQ(m.edge_pressures.size(), 1u);
    const EdgePressure& load = m.edge_pressures[0];
    ASSERT_GE(load.table, 0);
    const LoadTable& table = m.load_tables[load.table];
    for (int step : {0, 1, 2, 10, 103, 150})
        EXPECT_NEAR(load.pressure * table.factor(step), 5000.0 * step, 1e-6) << "step " << step;
}

TEST(ModelReader, LoadTableInterpolatesAndHolds) {
    LoadTable t;
    t.points = {{0.0, 0.0}, {10.0, 1.0}, {20.0, 1.0}};
    EXPECT_DOUBLE_EQ(t.factor(-1.0), 0.0);
    EXPECT_DOUBLE_EQ(t.factor(5.0), 0.5);
    EXPECT_DOUBLE_EQ(t.factor(15.0), 1.0);
    EXPECT_DOUBLE_EQ(t.factor(100.0), 1.0);  // held beyond the table
    t.points = {{0.0, 0.0}, {10.0, 2.0}};
    t.extrapolate = true;
    EXPECT_DOUBLE_EQ(t.factor(30.0), 6.0);
}

TEST(ModelReader, MissingFileIsAnErrorNotAnException) {
    const ReadResult r = read_model_file("/nonexistent/model.json");
    EXPECT_FALSE(r.model);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_NE(r.diagnostics[0].message.find("cannot open"), std::string::npos);
}

TEST(ModelReader, MovingRollerPrescribesDisplacementOfItsFixedDirections) {
    const std::string ramp = R"(/load_tables=[{"name": "mm", "variable": "step", "points": [[0, 0], [1, 1]],
                                               "extrapolate": true}])";
    const ReadResult r = read_model_text(
        square_model_json(),
        {ramp, R"(/rollers/-={"name": "jack", "from": [0, 10], "to": [10, 10], "fixed": "y",
                               "displacement": [0, -0.001], "table": "mm"})"});
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    const Roller& jack = r.model->rollers.back();
    EXPECT_TRUE(jack.moves());
    EXPECT_EQ(jack.displacement.y, -0.001);
    EXPECT_EQ(jack.table, 0);
    EXPECT_FALSE(r.model->rollers.front().moves());

    // A displacement in a direction the roller leaves free is refused, naming the field.
    const ReadResult bad = read_model_text(
        square_model_json(),
        {ramp, R"(/rollers/-={"name": "jack", "from": [0, 10], "to": [10, 10], "fixed": "x",
                               "displacement": [0, -0.001]})"});
    ASSERT_TRUE(bad.model) << all_messages(bad.diagnostics);  // well-formed; the validator refuses it
    std::vector<Diagnostic> d;
    validate_model(*bad.model, d);
    EXPECT_TRUE(has_diagnostic(d, Severity::Error, "/rollers/1/displacement", "does not fix")) << all_messages(d);
}

TEST(ModelReader, NumberTooLargeForADoubleNamesLineAndColumn) {
    std::string text = square_model_json();
    const std::size_t at = text.find("\"young_modulus\"");
    ASSERT_NE(at, std::string::npos);
    const std::size_t value = text.find(':', at) + 2;
    const std::size_t end = text.find_first_of(",}", value);
    text.replace(value, end - value, "1e400");
    const ReadResult r = read_model_text(text, {}, "big.json");
    EXPECT_FALSE(r.model);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    const std::string& m = r.diagnostics[0].message;
    EXPECT_NE(m.find("number 1e400 is too large"), std::string::npos) << m;
    // The position is the literal's: line and column of "1e400" in the text.
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < value; ++i) {
        if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
    }
    EXPECT_NE(m.find("big.json:" + std::to_string(line) + ":" + std::to_string(column) + ":"), std::string::npos) << m;
}

TEST(ModelReader, BadOverridePointersAreExplainedInWords) {
    const ReadResult r = read_model_text(square_model_json(), {"materials/0/cohesion=1", "/materials/~2/x=1"});
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "materials/0/cohesion", "a pointer starts with '/'"))
        << all_messages(r.diagnostics);
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/materials/~2/x", "must be followed by 0"))
        << all_messages(r.diagnostics);
    for (const Diagnostic& d : r.diagnostics) EXPECT_EQ(d.message.find("json.exception"), std::string::npos) << d.message;
}

// Format 2: construction stages and bolts (docs/model-format.md).
namespace {

std::vector<std::string> staged(std::vector<std::string> more) {
    std::vector<std::string> o{
        "/version=2",
        R"(/regions/-={"name": "core", "material": "rock", "boundary": [[4,4],[6,4],[6,6],[4,6]]})",
        R"(/regions/0/boundary=[[0,0],[10,0],[10,10],[0,10]])",
        R"(/regions/0/holes=[[[4,4],[4,6],[6,6],[6,4]]])",
        R"(/bolts=[{"name": "b1", "from": [2,2], "to": [3,8], "stiffness": 1e8, "strength": 2e5, "pretension": 1e4}])",
        R"(/stages=[{"name": "in situ", "analysis": {"steps": 2}},
                    {"name": "dig", "excavate": ["core"], "install": ["b1"], "release": {"steps": 3},
                     "analysis": {"steps": 4, "plastic_tolerance": 1e-5}, "target_ratio": 1e-6}])"};
    o.insert(o.end(), more.begin(), more.end());
    return o;
}

std::string errors_of(const ReadResult& r) {
    std::vector<Diagnostic> all = r.diagnostics;
    if (r.model) validate_model(*r.model, all);
    return all_messages(all);
}

}  // namespace

TEST(ModelReader, StagesAndBoltsRead) {
    const ReadResult r = read_model_text(square_model_json(), staged({}));
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    const Model& m = *r.model;
    ASSERT_EQ(m.bolts.size(), 1u);
    EXPECT_EQ(m.bolts[0].name, "b1");
    EXPECT_DOUBLE_EQ(m.bolts[0].stiffness, 1e8);
    EXPECT_DOUBLE_EQ(m.bolts[0].strength, 2e5);
    EXPECT_DOUBLE_EQ(m.bolts[0].pretension, 1e4);
    ASSERT_EQ(m.stages.size(), 2u);
    EXPECT_EQ(m.stages[0].analysis.steps, 2);
    EXPECT_EQ(m.stages[1].excavate, std::vector<int>{1});
    EXPECT_EQ(m.stages[1].install, std::vector<std::string>{"b1"});
    EXPECT_EQ(m.stages[1].release_steps, 3);
    EXPECT_EQ(m.stages[1].analysis.steps, 4);
    EXPECT_DOUBLE_EQ(m.stages[1].analysis.plastic_tolerance, 1e-5);
    EXPECT_DOUBLE_EQ(m.stages[1].target_ratio, 1e-6);
    // A stage's settings start from the model's.
    EXPECT_DOUBLE_EQ(m.stages[1].analysis.time_step, m.analysis.time_step);
    EXPECT_DOUBLE_EQ(m.stages[1].released(1.5, m.load_tables), 0.5);
    EXPECT_DOUBLE_EQ(m.stages[1].released(7.0, m.load_tables), 1.0);
    EXPECT_EQ(errors_of(r), "(no diagnostics)");
}

// What stands in each stage (the desktop program's Stages dock draws it): the core is there until
// "dig" excavates it; bolt b1 is absent until "dig" installs it, and gone again once removed.
TEST(ModelReader, RegionsAndItemsAbsentPerStage) {
    const ReadResult r = read_model_text(square_model_json(),
                                         staged({R"(/stages/-={"name": "unbolt", "remove": ["b1"]})"}));
    ASSERT_TRUE(r.model.has_value()) << all_messages(r.diagnostics);
    const Model& m = *r.model;
    EXPECT_TRUE(regions_absent(m, 0).empty());
    EXPECT_EQ(regions_absent(m, 1), std::vector<int>{1});
    EXPECT_EQ(items_absent(m, -1), std::vector<std::string>{"b1"});
    EXPECT_EQ(items_absent(m, 0), std::vector<std::string>{"b1"});
    EXPECT_TRUE(items_absent(m, 1).empty());
    EXPECT_EQ(items_absent(m, 2), std::vector<std::string>{"b1"});
}

TEST(ModelReader, StagesAndBoltsNeedVersion2) {
    const ReadResult r = read_model_text(square_model_json(), {R"(/stages=[{"name": "a"}])"});
    EXPECT_FALSE(r.model);
    EXPECT_TRUE(has_diagnostic(r.diagnostics, Severity::Error, "/stages", "need format version 2")) << all_messages(r.diagnostics);
}

TEST(ModelReader, StageAndBoltMistakesAreNamed) {
    const auto unknown = read_model_text(square_model_json(),
                                         staged({R"(/stages/1/excavate=["nowhere"])", R"(/stages/1/release={"steps": 1, "table": "t"})"}));
    EXPECT_TRUE(has_diagnostic(unknown.diagnostics, Severity::Error, "/stages/1/excavate/0", "no region named \"nowhere\""))
        << all_messages(unknown.diagnostics);
    EXPECT_TRUE(has_diagnostic(unknown.diagnostics, Severity::Error, "/stages/1/release", "not both"));

    auto invalid = [&](std::vector<std::string> more) {
        ReadResult r = read_model_text(square_model_json(), staged(std::move(more)));
        std::vector<Diagnostic> all = r.diagnostics;
        if (r.model) validate_model(*r.model, all);
        return all;
    };
    auto twice = invalid({R"(/stages/-={"name": "again", "excavate": ["core"]})"});
    EXPECT_TRUE(has_diagnostic(twice, Severity::Error, "/stages/2/excavate/0", "is not there to excavate")) << all_messages(twice);
    auto nothing = invalid({R"(/stages/-={"name": "gone", "excavate": ["square"]})"});
    EXPECT_TRUE(has_diagnostic(nothing, Severity::Error, "/stages/2", "leaves no region")) << all_messages(nothing);
    auto install = invalid({R"(/stages/1/install=["b2"])"});
    EXPECT_TRUE(has_diagnostic(install, Severity::Error, "/stages/1/install/0", "no support, load or bolt named \"b2\""))
        << all_messages(install);
    auto removed = invalid({R"(/stages/1/remove=["base", "base"])"});
    EXPECT_TRUE(has_diagnostic(removed, Severity::Error, "/stages/1/remove/1", "is not there")) << all_messages(removed);
    auto bolt = invalid({R"(/bolts/0/to=[30,30])", R"(/bolts/0/stiffness=0)"});
    EXPECT_TRUE(has_diagnostic(bolt, Severity::Error, "/bolts/0/to", "outside every region")) << all_messages(bolt);
    EXPECT_TRUE(has_diagnostic(bolt, Severity::Error, "/bolts/0/stiffness", "must be positive"));
    auto steps = invalid({R"(/stages/0/analysis/steps=0)", R"(/stages/0/analysis/equilibrium_ratio=0)"});
    EXPECT_TRUE(has_diagnostic(steps, Severity::Error, "/stages/0/analysis/steps", "at least one step")) << all_messages(steps);
    EXPECT_TRUE(has_diagnostic(steps, Severity::Error, "/stages/0/analysis/equilibrium_ratio", "must be positive"));
}

// Earthquake input: record files (CSV, PEER .AT2) and their bad forms, the record as the analysis
// uses it (units, scale, baseline correction, exact integration), and the model checks of
// ground motions, bases, dashpots and seismic coefficients.

#include "ModelCompare.hpp"
#include "TestModels.hpp"
#include "check/ModelValidator.hpp"
#include "io/AccelerationRecord.hpp"
#include "io/ModelReader.hpp"
#include "io/ModelWriter.hpp"
#include "run/GroundShaking.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::has_diagnostic;
using mcdda::test::preprocess_text;
using mcdda::test::square_model_json;
using Severity = Diagnostic::Severity;

namespace {

/// The message read_* throws for `text`, or "" when it reads.
template <class Parse>
std::string failure(Parse parse, const std::string& text) {
    try {
        parse(text, "record.csv");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

std::string csv_failure(const std::string& text) { return failure(parse_acceleration_csv, text); }
std::string at2_failure(const std::string& text) { return failure(parse_acceleration_at2, text); }

const char* at2_header = "PEER NGA STRONG MOTION DATABASE RECORD\nA RECORD, STATION, 0\nACCELERATION TIME SERIES IN UNITS OF G\n";

}  // namespace

TEST(AccelerationRecord, ReadsCsvWithAHeaderCommentsAndAnySeparator) {
    const AccelerationRecord r =
        parse_acceleration_csv("# a comment\ntime;acceleration\n0, 0\n0.01\t0.5\n\n0.02 -0.25\r\n0.03;1e-2\n", "r.csv");
    ASSERT_EQ(r.points.size(), 4u);
    EXPECT_DOUBLE_EQ(r.points[1][0], 0.01);
    EXPECT_DOUBLE_EQ(r.points[1][1], 0.5);
    EXPECT_DOUBLE_EQ(r.points[2][1], -0.25);
    EXPECT_DOUBLE_EQ(r.points[3][1], 0.01);
    EXPECT_FALSE(r.peer_at2);
}

TEST(AccelerationRecord, BadCsvIsRefusedWithItsLine) {
    EXPECT_NE(csv_failure("0,0\n0.1,abc\n").find("record.csv:2: expected two numbers"), std::string::npos)
        << csv_failure("0,0\n0.1,abc\n");
    EXPECT_NE(csv_failure("0,0\n0.1,0.2,0.3\n").find("record.csv:2"), std::string::npos);
    EXPECT_NE(csv_failure("0,0\n0.2,1\n0.1,2\n").find("record.csv:3: times must increase: 0.1 s follows 0.2 s"),
              std::string::npos)
        << csv_failure("0,0\n0.2,1\n0.1,2\n");
    EXPECT_NE(csv_failure("0,0\n0,1\n").find("times must increase"), std::string::npos);
    EXPECT_NE(csv_failure("0,0\n0.1,nan\n").find("record.csv:2"), std::string::npos);
    EXPECT_NE(csv_failure("0,0\n0.1,inf\n").find("record.csv:2"), std::string::npos);
    EXPECT_NE(csv_failure("0,0\n").find("at least two points"), std::string::npos);
    EXPECT_NE(csv_failure("").find("at least two points"), std::string::npos);
    // Only one header line: a second line of text is an error, not a header.
    EXPECT_NE(csv_failure("time,a\nsecond,header\n0,0\n").find("record.csv:2"), std::string::npos);
}

TEST(AccelerationRecord, ReadsPeerAt2InBothHeaderForms) {
    const AccelerationRecord r = parse_acceleration_at2(std::string(at2_header) + "NPTS=    5, DT=   .0100 SEC\n"
                                                                                  "  .1E-01  -.2E-01   .3E-01\n  .0   -.5E-02\n",
                                                        "r.AT2");
    ASSERT_EQ(r.points.size(), 5u);
    EXPECT_TRUE(r.peer_at2);
    EXPECT_DOUBLE_EQ(r.points[4][0], 0.04);
    EXPECT_DOUBLE_EQ(r.points[1][1], -0.02);
    EXPECT_DOUBLE_EQ(r.points[4][1], -0.005);
    const AccelerationRecord old = parse_acceleration_at2(std::string(at2_header) + "3   0.005   NPTS, DT\n1 2 3\n", "r.AT2");
    ASSERT_EQ(old.points.size(), 3u);
    EXPECT_DOUBLE_EQ(old.points[2][0], 0.01);
}

TEST(AccelerationRecord, BadAt2IsRefusedWithItsLine) {
    const std::string h = at2_header;
    EXPECT_NE(at2_failure(h).find("record.csv:4"), std::string::npos);
    EXPECT_NE(at2_failure(h + "NPTS= x, DT= 0.01 SEC\n1 2\n").find("record.csv:4: expected the number of points"),
              std::string::npos);
    EXPECT_NE(at2_failure(h + "NPTS= 3, DT= -0.01 SEC\n1 2 3\n").find("record.csv:4"), std::string::npos);
    EXPECT_NE(at2_failure(h + "NPTS= 3, DT= 0.01 SEC\n1 2\n").find("declares 3 accelerations (NPTS), the file holds 2"),
              std::string::npos);
    EXPECT_NE(at2_failure(h + "NPTS= 2, DT= 0.01 SEC\n1 2 3\n").find("record.csv:5: more accelerations than the 2"),
              std::string::npos);
    EXPECT_NE(at2_failure(h + "NPTS= 2, DT= 0.01 SEC\n1 abc\n").find("record.csv:5: not a number"), std::string::npos);
    // A huge declared count costs nothing: the points are counted as read.
    EXPECT_NE(at2_failure(h + "NPTS= 1000000000000, DT= 0.01 SEC\n1 2\n").find("the file holds 2"), std::string::npos);
}

TEST(AccelerationRecord, FilesThatAreNotRecords) {
    namespace fs = std::filesystem;
    auto message = [](const std::string& path) {
        try {
            read_acceleration_record(path);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message("/no/such/record.csv").find("no such file"), std::string::npos);
    EXPECT_NE(message(fs::temp_directory_path().string()).find("not a regular file"), std::string::npos);
    const fs::path file = fs::temp_directory_path() / "mcdda-record-test.AT2";
    {
        std::ofstream out(file);
        out << at2_header << "NPTS= 2, DT= 0.02 SEC\n0.1 0.2\n";
    }
    const AccelerationRecord r = read_acceleration_record(file.string());
    EXPECT_TRUE(r.peer_at2);
    EXPECT_DOUBLE_EQ(r.points[1][0], 0.02);
    fs::remove(file);
}

TEST(GroundShaking, UnitsScaleAndExactIntegration) {
    GroundMotion g;
    g.points = {{0.0, 0.5}, {2.0, 0.5}};  // a constant 0.5 g
    g.scale = 2.0;
    g.baseline_correction = false;
    const GroundShaking s(g);
    EXPECT_DOUBLE_EQ(s.acceleration(1.0), 9.81);
    EXPECT_DOUBLE_EQ(s.velocity(1.5), 9.81 * 1.5);
    EXPECT_NEAR(s.displacement(1.5), 0.5 * 9.81 * 1.5 * 1.5, 1e-12);
    EXPECT_DOUBLE_EQ(s.acceleration(2.5), 0.0);                        // after the record: no more shaking
    EXPECT_NEAR(s.displacement(3.0), 0.5 * 9.81 * 4.0 + 9.81 * 2.0, 1e-12);  // moving on at its last velocity
    g.units = GroundMotion::Units::MetresPerSecondSquared;
    EXPECT_DOUBLE_EQ(GroundShaking(g).acceleration(1.0), 1.0);
}

TEST(GroundShaking, BaselineCorrectionBringsTheBaseBackToRest) {
    GroundMotion g;
    // A sine record of three cycles: its velocity averages A/ω, so the base drifts by metres.
    for (int k = 0; k <= 300; ++k) g.points.push_back({k * 0.01, 0.3 * std::sin(2.0 * 3.14159265358979 * k * 0.01)});
    g.baseline_correction = false;
    EXPECT_GT(std::fabs(GroundShaking(g).displacement(3.0)), 0.5);
    g.baseline_correction = true;
    const GroundShaking s(g);
    EXPECT_NEAR(s.velocity(3.0), 0.0, 1e-12);
    EXPECT_NEAR(s.displacement(3.0), 0.0, 1e-12);
    EXPECT_NEAR(s.displacement(10.0), 0.0, 1e-12);
    EXPECT_NE(s.correction_constant(), 0.0);
}

namespace {

const std::string shaken = R"(/ground_motions=[{"name": "quake", "points": [[0, 0], [0.01, 0.1], [0.02, -0.1], [0.03, 0]]}])";

void expect_error(const std::vector<std::string>& overrides, const std::string& path, const std::string& fragment) {
    EXPECT_EQ(mcdda::test::refusal_mismatch(overrides, path, fragment), "");
}

}  // namespace

TEST(EarthquakeInput, AShakenModelIsValid) {
    const Preprocessed p = preprocess_text(
        square_model_json(),
        {shaken, R"(/base_motion={"type": "rigid", "x": "quake"})", R"(/analysis={"type": "dynamic", "time_step": 0.01})"},
        PreprocessStage::Cut);
    EXPECT_TRUE(p.ok) << all_messages(p.diagnostics);
}

TEST(EarthquakeInput, BadRecordsBasesAndDashpots) {
    const std::string dynamic = R"(/analysis={"type": "dynamic", "time_step": 0.01})";
    const std::string rigid = R"(/base_motion={"type": "rigid", "x": "quake"})";
    expect_error({R"(/ground_motions=[{"name": "q", "points": [[0, 0], [0.2, 1], [0.1, 0]]}])"}, "/ground_motions/0/points/2",
                 "times must increase: 0.1 s follows 0.2 s");
    expect_error({R"(/ground_motions=[{"name": "q", "points": [[0, 0]]}])"}, "/ground_motions/0/points", "at least two points");
    expect_error({R"(/ground_motions=[{"name": "q", "points": [[0, 0], [1, 20]]}])"}, "/ground_motions/0/points",
                 "the peak acceleration is 20 g");
    expect_error({R"(/ground_motions=[{"name": "q", "file": "/no/such/record.csv"}])"}, "/ground_motions/0/file",
                 "no such file");
    expect_error({R"(/ground_motions=[{"name": "q"}])"}, "/ground_motions/0", "either \"file\"");
    expect_error({R"(/ground_motions=[{"name": "q", "points": [[0, 0], [1, 0.1]], "units": "gal"}])"},
                 "/ground_motions/0/units", "must be \"g\" or \"m/s2\"");
    expect_error({shaken, R"(/base_motion={"type": "rigid", "x": "other"})"}, "/base_motion/x", "other");
    expect_error({shaken, R"(/base_motion={"type": "shaking table", "x": "quake"})"}, "/base_motion/type", "\"rigid\" or \"compliant\"");
    expect_error({shaken, R"(/base_motion={"type": "rigid"})"}, "/base_motion", "name the ground motion");
    expect_error({shaken, R"(/base_motion={"type": "rigid", "x": "quake", "from": [0, 0], "to": [1, 0]})"}, "/base_motion",
                 "belong to a compliant base");
    expect_error({shaken, rigid, dynamic, "/rollers=[]"}, "/base_motion", "nothing is fixed");
    // The time step against the record's sampling (0.01 s here).
    expect_error({shaken, rigid, R"(/analysis={"type": "dynamic", "time_step": 0.04})"}, "/analysis/time_step",
                 "is 4 times the sampling interval of \"quake\" (0.01 s)");
    // Dashpots where a support holds the boundary.
    expect_error({shaken, dynamic, R"(/absorbing_boundaries=[{"name": "bottom", "from": [0, 0], "to": [10, 0]}])"},
                 "/absorbing_boundaries/0", "dashpots on a boundary that also has a fixed support (roller \"base\")");
    // A compliant base under gravity from the start would sink.
    expect_error({shaken, dynamic, "/gravity=[0, -9.81]", R"(/rollers=[{"name": "side", "from": [0, 0], "to": [0, 10], "fixed": "x"}])",
                  R"(/base_motion={"type": "compliant", "x": "quake", "from": [0, 0], "to": [10, 0]})"},
                 "/base_motion", "cannot carry the model's weight");
    // Waves crossing elements in one step: Vs = sqrt(G/ρ) = 400 m/s, elements of 1 m.
    expect_error({shaken, R"(/analysis={"type": "dynamic", "time_step": 0.01})",
                  R"(/absorbing_boundaries=[{"name": "side", "from": [10, 0], "to": [10, 10]}])"},
                 "/analysis/time_step", "crosses 4 elements");
    // Dashpots that lie along no boundary would silently do nothing.
    expect_error({shaken, R"(/analysis={"type": "dynamic", "time_step": 0.001})",
                  R"(/absorbing_boundaries=[{"name": "inside", "from": [5, 0], "to": [5, 10]}])"},
                 "/absorbing_boundaries/0", "absorbing boundary \"inside\" lies along no block boundary");
    expect_error({R"(/seismic_coefficient={"kh": 3, "kv": 0})"}, "/seismic_coefficient/kh", "between -2 and 2");
    expect_error({R"(/seismic_coefficient={"kh": 0.1, "kz": 0})"}, "/seismic_coefficient/kz", "unknown key");
}

TEST(EarthquakeInput, AnEditedBaseWithoutARecordIsAnError) {
    // What the desktop program or the API can make and a file cannot say.
    ReadResult r = read_model_text(square_model_json(), {shaken, R"(/base_motion={"type": "rigid", "x": "quake"})"});
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    Model m = *r.model;
    m.base_motion.x = -1;
    std::vector<Diagnostic> d;
    validate_model(m, d);
    EXPECT_TRUE(has_diagnostic(d, Severity::Error, "/base_motion", "name the ground motion")) << all_messages(d);
    m.base_motion.x = 3;
    d.clear();
    validate_model(m, d);
    EXPECT_TRUE(has_diagnostic(d, Severity::Error, "/base_motion/x", "names no ground motion")) << all_messages(d);
}

TEST(EarthquakeInput, StagesAndRecordFilesRoundTrip) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / "mcdda-earthquake-round-trip";
    fs::create_directories(folder / "records");
    {
        std::ofstream out(folder / "records" / "quake.csv");
        out << "time,acceleration\n0,0\n0.01,0.2\n0.02,0\n";
    }
    const std::string text = R"({"format": "mcdda-model", "version": 2, "name": "staged",
      "materials": [{"name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25, "density": 2500}],
      "regions": [{"name": "ground", "material": "rock", "boundary": [[0, 0], [10, 0], [10, 10], [0, 10]]}],
      "rollers": [{"name": "base", "from": [0, 0], "to": [10, 0], "fixed": "xy"}],
      "gravity": [0, -9.81],
      "ground_motions": [{"name": "quake", "file": "records/quake.csv", "scale": 0.5}],
      "base_motion": {"type": "rigid", "x": "quake"},
      "stages": [{"name": "gravity"},
                 {"name": "pseudo-static", "seismic_coefficient": {"kh": 0.1, "kv": -0.05}},
                 {"name": "shaking", "analysis": {"type": "dynamic", "time_step": 0.01}}]})";
    const fs::path file = folder / "model.json";
    {
        std::ofstream out(file);
        out << text;
    }
    const ReadResult r = read_model_file(file.string());
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    ASSERT_EQ(r.model->ground_motions.size(), 1u);
    EXPECT_EQ(r.model->ground_motions[0].points.size(), 3u);  // read from the file beside the model
    EXPECT_DOUBLE_EQ(seismic_of_stage(*r.model, 0).kh, 0.0);
    EXPECT_DOUBLE_EQ(seismic_of_stage(*r.model, 1).kh, 0.1);
    EXPECT_DOUBLE_EQ(seismic_of_stage(*r.model, 2).kv, -0.05);  // holds on
    const std::string written = write_model_text(*r.model);
    EXPECT_NE(written.find("\"file\": \"records/quake.csv\""), std::string::npos);  // the name, not the points
    const ReadResult again = read_model_text(written, {}, file.string());
    ASSERT_TRUE(again.model) << all_messages(again.diagnostics);
    EXPECT_EQ(mcdda::test::model_differences(*r.model, *again.model), "");
    fs::remove_all(folder);
}

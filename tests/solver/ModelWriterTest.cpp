// The model file writer: read → write → read gives the same model; atomic, failing writes.

#include "ModelCompare.hpp"
#include "TestModels.hpp"
#include "io/ModelReader.hpp"
#include "io/ModelWriter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace mcdda;
using mcdda::test::all_messages;
using mcdda::test::model_differences;

namespace fs = std::filesystem;

namespace {

constexpr double pi = 3.14159265358979323846;

/// A fresh empty folder under the system's temporary folder, removed at the end.
struct TemporaryFolder {
    fs::path path;
    TemporaryFolder() {
        path = fs::temp_directory_path() /
               ("mcdda-writer-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TemporaryFolder() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

/// A model touching every field the file format has.
Model everything_model() {
    const std::string text = R"({"format": "mcdda-model", "version": 1, "name": "all \"fields\"", "description": "Ünïcode ok",
      "materials": [{"name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.2, "unit_weight": 24525, "saturated_unit_weight": 25506,
                     "cohesion": 1e5, "friction_angle": 30, "dilation_angle": 10, "tensile_strength": 1e4},
                    {"name": "steel", "young_modulus": 2.1e11, "poisson_ratio": 0.3, "density": 7850, "plastic": false}],
      "joint_materials": [{"name": "smooth", "friction_angle": 20},
                          {"name": "rough", "friction_angle": 40.1, "cohesion": 1, "tensile_strength": 2,
                           "normal_stiffness": 3e9, "shear_stiffness": 1e9}],
      "default_joint_material": "rough",
      "regions": [{"name": "ground", "material": "rock",
                   "boundary": [[-10, -10], [10, -10], [10, 10], [-10, 10]],
                   "holes": [{"circle": {"center": [0, 0], "radius": 3, "segments": 32}}]},
                  {"material": "steel", "mesh_size": 0.25, "boundary": [[10, -10], [12, -10],
                    {"arc": {"center": [11, 10], "radius": 1, "start": 0, "end": 180, "segments": 7}}]}],
      "joints": [{"name": "fault", "points": [[-10, 0.1], [0.3, 5], [10, 7.77]], "joint_material": "smooth"},
                 {"points": [[-5, -10], [-5, 10]]}],
      "joint_sets": [{"name": "bedding", "angle": 12.5, "spacing": 0.7, "origin": [1, 2],
                      "extent": [-10, -10, 0, 0], "joint_material": "smooth",
                      "persistence": 0.65, "trace_length": 2.5, "stagger": 0.3},
                     {"angle": 100, "spacing": 3}],
      "load_tables": [{"name": "ramp", "variable": "time", "points": [[0, 0], [1, 0.5], [2, 1]], "extrapolate": true},
                      {"name": "hold", "points": [[0, 1]]}],
      "fixed_points": [{"name": "a", "point": [-10, -10]}],
      "rollers": [{"name": "base", "from": [-10, -10], "to": [10, -10], "fixed": "y"},
                  {"from": [-10, -10], "to": [-10, 10], "fixed": "x"},
                  {"from": [10, -10], "to": [10, 10], "fixed": "xy"}],
      "point_loads": [{"name": "P", "point": [0, 10], "force": [1e3, -2e3], "table": "hold"}, {"point": [1, 10], "force": [0, -1]}],
      "edge_pressures": [{"name": "q", "from": [-10, 10], "to": [0, 10], "pressure": 2e6, "table": "ramp"},
                         {"from": [0, 10], "to": [10, 10], "pressure": -0.1}],
      "gravity": [0.5, -9.81],
      "initial_stress": {"type": "uniform", "sxx": 10e6, "syy": 5e6, "sxy": -1e6, "szz": 7e6},
      "water": {"piezometric_line": [[-10, 5], [0.5, 4.25], [10, 2]], "unit_weight": 10050},
      "measurement_points": [{"name": "crown", "point": [0, 3]}],
      "mesh": {"size": 0.5, "min_angle": 28, "grading": 0.2, "max_elements": 12345,
               "local": [{"point": [0, 0], "size": 0.1, "radius": 3}, {"from": [0, 0], "to": [1, 1], "size": 0.2}]},
      "ground_motions": [{"name": "pulse", "points": [[0, 0], [0.1, 0.25], [0.2, -0.1], [0.3, 0]], "units": "g",
                          "scale": 1.5, "baseline_correction": false},
                         {"name": "vertical", "points": [[0, 0], [0.5, 1.5]], "units": "m/s2"}],
      "base_motion": {"type": "compliant", "x": "pulse", "y": "vertical", "from": [-10, -10], "to": [10, -10]},
      "absorbing_boundaries": [{"name": "left", "from": [-10, -10], "to": [-10, 10]}],
      "seismic_coefficient": {"kh": -0.15, "kv": 0.05},
      "analysis": {"type": "dynamic", "steps": 7, "time_step": 0.003, "max_displacement_ratio": 0.001,
                   "penalty": 1e10, "dynamic_ratio": 0.9, "open_close_iterations": 6, "plastic_iterations": 50,
                   "plastic_tolerance": 1e-5, "output_every": 3, "plasticity": false, "newmark_gamma": 0.55,
                   "damping_ratio": 0.05, "damping_frequency": 2, "damping_frequency_2": 8}})";
    const ReadResult r = read_model_text(text);
    EXPECT_TRUE(r.model) << all_messages(r.diagnostics);
    return r.model ? *r.model : Model{};
}

void expect_round_trip(const Model& model, const std::string& what) {
    const std::string text = write_model_text(model);
    const ReadResult again = read_model_text(text, {}, what);
    ASSERT_TRUE(again.model) << what << "\n" << all_messages(again.diagnostics) << "\n" << text;
    EXPECT_TRUE(again.diagnostics.empty()) << what << "\n" << all_messages(again.diagnostics);
    EXPECT_EQ(model_differences(model, *again.model), "") << what << "\n" << text;
    // Writing is deterministic: the second generation's text is the first's.
    EXPECT_EQ(write_model_text(*again.model), text) << what;
}

}  // namespace

TEST(ModelWriter, EveryExampleRoundTrips) {
    const auto files = mcdda::test::example_files();
    ASSERT_FALSE(files.empty());
    for (const std::string& file : files) {
        const ReadResult r = read_model_file(file);
        ASSERT_TRUE(r.model) << file << "\n" << all_messages(r.diagnostics);
        expect_round_trip(*r.model, file);
    }
}

TEST(ModelWriter, EveryFieldRoundTrips) {
    const Model m = everything_model();
    ASSERT_FALSE(m.materials.empty());
    expect_round_trip(m, "everything");
}

TEST(ModelWriter, ConvertsUnitsAndSignsBack) {
    const Model m = everything_model();
    const std::string text = write_model_text(m);
    const auto has = [&](const std::string& fragment) { return text.find(fragment) != std::string::npos; };
    EXPECT_TRUE(has("\"format\": \"mcdda-model\"")) << text;
    EXPECT_TRUE(has("\"version\": 2")) << text;
    EXPECT_TRUE(has("\"density\": 2500")) << text;        // unit weight 24525 N/m³ / 9.81
    EXPECT_FALSE(has("\"unit_weight\": 24525")) << text;  // the only unit weight written is the water's
    EXPECT_TRUE(has("\"saturated_density\": 2600")) << text;  // saturated unit weight 25506 N/m³ / 9.81
    EXPECT_TRUE(has("\"unit_weight\": 10050")) << text;      // of the water
    EXPECT_TRUE(has("\"sxx\": 10000000")) << text;         // compression positive again
    EXPECT_TRUE(has("\"sxy\": -1000000")) << text;
    EXPECT_TRUE(has("\"default_joint_material\": \"rough\"")) << text;
    EXPECT_TRUE(has("\"material\": \"steel\"")) << text;
    EXPECT_TRUE(has("\"table\": \"ramp\"")) << text;
    EXPECT_TRUE(has("\"friction_angle\": 30")) << text;    // degrees (up to the last bits)
}

TEST(ModelWriter, JointsGeneratedFromSetsAreNotWritten) {
    Model m = everything_model();
    const std::size_t explicit_joints = m.joints.size();
    Joint generated;
    generated.name = "bedding #1";
    generated.points = {{-10, 0}, {0, 2}};
    generated.joint_set = 0;
    m.joints.push_back(generated);
    const std::string text = write_model_text(m);
    EXPECT_EQ(text.find("bedding #1"), std::string::npos) << text;
    const ReadResult again = read_model_text(text);
    ASSERT_TRUE(again.model) << all_messages(again.diagnostics);
    EXPECT_EQ(again.model->joints.size(), explicit_joints);
    EXPECT_EQ(again.model->joint_sets.size(), m.joint_sets.size());
}

TEST(ModelWriter, JointSetPersistenceIsWrittenOnlyWhenNotTheDefault) {
    Model m = everything_model();
    ASSERT_EQ(m.joint_sets.size(), 2u);
    const std::string text = write_model_text(m);
    EXPECT_NE(text.find("\"persistence\": 0.65"), std::string::npos) << text;
    EXPECT_NE(text.find("\"trace_length\": 2.5"), std::string::npos) << text;
    EXPECT_NE(text.find("\"stagger\": 0.3"), std::string::npos) << text;
    // The second set is fully persistent: written as files were before persistence existed.
    m.joint_sets.erase(m.joint_sets.begin());
    const std::string persistent = write_model_text(m);
    EXPECT_EQ(persistent.find("persistence"), std::string::npos) << persistent;
    EXPECT_EQ(persistent.find("trace_length"), std::string::npos) << persistent;
    EXPECT_EQ(persistent.find("stagger"), std::string::npos) << persistent;
    // A single field off its default is written alone, and read back.
    m.joint_sets[0].stagger = 0.0;
    const std::string staggered = write_model_text(m);
    EXPECT_NE(staggered.find("\"stagger\": 0"), std::string::npos) << staggered;
    EXPECT_EQ(staggered.find("persistence"), std::string::npos) << staggered;
    expect_round_trip(m, "stagger only");
}

TEST(ModelWriter, AnglesAreDegreesInTheFile) {
    Model m = everything_model();
    m.materials[0].parameters["friction_angle"] = pi / 4;
    const ReadResult again = read_model_text(write_model_text(m));
    ASSERT_TRUE(again.model);
    EXPECT_NEAR(again.model->materials[0].parameter("friction_angle"), pi / 4, 1e-15);
    EXPECT_NE(write_model_text(m).find("\"friction_angle\": 45"), std::string::npos);
}

TEST(ModelWriter, WritesAFileAtomically) {
    TemporaryFolder folder;
    const Model m = everything_model();
    const std::string path = (folder.path / "model.json").string();
    write_model_file(path, m);
    const ReadResult r = read_model_file(path);
    ASSERT_TRUE(r.model) << all_messages(r.diagnostics);
    EXPECT_EQ(model_differences(m, *r.model), "");
    // Overwriting replaces the file; nothing else is left in the folder.
    write_model_file(path, m);
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(folder.path)) ++entries;
    EXPECT_EQ(entries, 1u);
}

TEST(ModelWriter, MissingFolderThrowsAndCreatesNothing) {
    TemporaryFolder folder;
    const fs::path missing = folder.path / "no-such-folder";
    const std::string path = (missing / "model.json").string();
    EXPECT_THROW(write_model_file(path, everything_model()), std::runtime_error);
    EXPECT_FALSE(fs::exists(missing));
    EXPECT_TRUE(fs::is_empty(folder.path));
}

TEST(ModelWriter, ABrokenReferenceThrowsBeforeTouchingTheFile) {
    TemporaryFolder folder;
    Model m = everything_model();
    m.regions[0].material = 99;
    const std::string path = (folder.path / "model.json").string();
    EXPECT_THROW(write_model_file(path, m), std::invalid_argument);
    EXPECT_TRUE(fs::is_empty(folder.path));
}

// The public library interface <mcdda/Analysis.hpp>: reading, changing fields by JSON pointer,
// checking, meshing as arrays, running with progress and cancellation, results as arrays.

#include "TestModels.hpp"
#include "mcdda/Analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <thread>

using namespace mcdda;

namespace {

const std::string incline = mcdda::test::example_path("incline-stable.json");

}  // namespace

TEST(Analysis, ReadsChangesAndMeshes) {
    Analysis a = Analysis::from_file(incline, {"/analysis/steps=3"});
    EXPECT_EQ(a.model().analysis.steps, 3);
    a.set({"/joint_materials/0/friction_angle=20"});
    EXPECT_NEAR(a.model().joint_materials[0].friction_angle, 20.0 * M_PI / 180.0, 1e-12);
    EXPECT_TRUE(a.check().empty() || !has_errors(a.diagnostics()));
    EXPECT_TRUE(a.ok());
    const MeshArrays mesh = a.mesh_arrays();
    ASSERT_GT(mesh.element_count(), 0);
    EXPECT_EQ(mesh.triangles.size(), 3u * mesh.element_count());
    EXPECT_EQ(mesh.region.size(), mesh.block.size());
    double area = 0.0;
    for (double e : mesh.area) {
        EXPECT_GT(e, 0.0);  // counter-clockwise
        area += e;
    }
    for (int n : mesh.triangles) EXPECT_LT(n, mesh.node_count());
    EXPECT_GT(area, 0.0);
    // The JSON text of the changed model reads back with the change.
    EXPECT_NE(a.to_json().find("\"friction_angle\": 20"), std::string::npos);
}

TEST(Analysis, BadInputIsAModelErrorNamingThePlace) {
    try {
        Analysis::from_text("{\"format\": \"mcdda-model\", \"version\": 1, \"materials\": []}");
        FAIL() << "no error";
    } catch (const ModelError& e) {
        EXPECT_NE(std::string(e.what()).find("/materials"), std::string::npos) << e.what();
        EXPECT_TRUE(has_errors(e.diagnostics));
    }
    Analysis a = Analysis::from_file(incline);
    const double before = a.model().materials[0].parameter("cohesion");
    EXPECT_THROW(a.set({"/materials/0/cohesion=\"strong\""}), ModelError);
    EXPECT_EQ(a.model().materials[0].parameter("cohesion"), before);  // unchanged
    a.set({"/materials/0/poisson_ratio=0.5"});             // readable, but impossible:
    EXPECT_TRUE(has_errors(a.check()));
    EXPECT_FALSE(a.ok());
    EXPECT_THROW(a.run(), ModelError);
    EXPECT_THROW(Analysis::from_file("/nonexistent/model.json"), ModelError);
}

TEST(Analysis, RunsWithProgressAndKeepsFields) {
    // Static: each step ends at rest, so ten steps end in equilibrium.
    Analysis a = Analysis::from_file(
        incline, {"/analysis/steps=10", "/analysis/output_every=5", "/analysis/type=\"static\"", "/analysis/time_step=1"});
    std::vector<int> heard;
    RunOptions options;
    options.on_step = [&](const StepProgress& p) {
        heard.push_back(p.step);
        EXPECT_EQ(p.planned_steps, 10);
        return true;
    };
    const RunResult r = a.run(options);
    EXPECT_EQ(r.status, "completed") << r.message;
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.steps, 10);
    EXPECT_EQ(heard.size(), 10u);
    ASSERT_EQ(r.history.size(), 10u);
    EXPECT_EQ(r.history.back().step, 10);
    ASSERT_EQ(r.saved.size(), 2u);  // steps 5 and 10
    EXPECT_EQ(r.saved[0].step, 5);
    const MeshArrays mesh = a.mesh_arrays();
    const StepFields& last = r.saved.back();
    EXPECT_EQ(last.displacement.size(), mesh.nodes.size());
    EXPECT_EQ(last.stress.size(), 4u * mesh.element_count());
    EXPECT_EQ(last.plastic_state.size(), static_cast<std::size_t>(mesh.element_count()));
    // The block rests: its largest displacement is that of the history's last row, below 1 mm.
    double largest = 0.0;
    for (std::size_t i = 0; i + 1 < last.displacement.size(); i += 2)
        largest = std::max(largest, std::hypot(last.displacement[i], last.displacement[i + 1]));
    EXPECT_DOUBLE_EQ(largest, r.history.back().max_displacement);
    EXPECT_LT(largest, 1e-3);
}

TEST(Analysis, StopsWhenToldAndWritesFilesWhenAsked) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "mcdda-analysis-test";
    std::filesystem::remove_all(folder);
    Analysis a = Analysis::from_file(incline, {"/analysis/steps=50"});
    RunOptions options;
    options.output_folder = folder.string();
    options.name = "incline";
    options.on_step = [](const StepProgress& p) { return p.step < 3; };  // stop after step 3
    const RunResult r = a.run(options);
    EXPECT_EQ(r.status, "cancelled");
    EXPECT_EQ(r.exit_code, 130);
    EXPECT_EQ(r.steps, 3);
    EXPECT_TRUE(std::filesystem::exists(folder / "incline.pvd"));
    EXPECT_TRUE(std::filesystem::exists(folder / "summary.json"));
    EXPECT_TRUE(std::filesystem::exists(folder / "history.csv"));
    std::filesystem::remove_all(folder);

    // cancel() from another thread.
    Analysis b = Analysis::from_file(incline, {"/analysis/steps=100000"});
    RunOptions slow;
    slow.on_step = [&](const StepProgress& p) {
        if (p.step == 2) std::thread([&] { b.cancel(); }).join();
        return true;
    };
    const RunResult c = b.run(slow);
    EXPECT_EQ(c.status, "cancelled");
    EXPECT_EQ(c.steps, 2);
}

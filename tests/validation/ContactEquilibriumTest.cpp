// A block resting on a fixed base under gravity: the contacts carry exactly its weight, in the
// solver and in the contacts files a run writes (read back as a user would), and the history
// and summary carry the stage and the unbalanced-force ratio.

#include "RunModel.hpp"
#include "io/ModelReader.hpp"
#include "run/RunLoop.hpp"
#include "run/RunOutput.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

using namespace mcdda;
namespace fs = std::filesystem;

namespace {

const char* resting_block = R"({
  "format": "mcdda-model", "version": 1, "name": "resting block",
  "materials": [ { "name": "rock", "young_modulus": 1e9, "poisson_ratio": 0.25, "density": 2500, "plastic": false } ],
  "joint_materials": [ { "name": "interface", "friction_angle": 30 } ],
  "regions": [ { "name": "base", "material": "rock", "boundary": [[0,0],[4,0],[4,1],[0,1]] },
               { "name": "block", "material": "rock", "boundary": [[1,1],[3,1],[3,2],[1,2]] } ],
  "rollers": [ { "name": "bottom", "from": [0,0], "to": [4,0], "fixed": "xy" } ],
  "gravity": [0, -9.81],
  "mesh": { "size": 0.25, "min_angle": 30 },
  "analysis": { "type": "static", "steps": 30, "time_step": 1.0, "max_displacement_ratio": 0.01 }
})";

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The numbers of the ASCII DataArray named `name` in VTK XML text.
std::vector<double> data_array(const std::string& xml, const std::string& name) {
    const std::size_t at = xml.find("Name=\"" + name + "\"");
    if (at == std::string::npos) return {};
    const std::size_t begin = xml.find('>', at) + 1, end = xml.find("</DataArray>", begin);
    std::istringstream in(xml.substr(begin, end - begin));
    std::vector<double> values;
    for (double v; in >> v;) values.push_back(v);
    return values;
}

/// The file names listed in a .pvd collection, in order.
std::vector<std::string> collection_files(const fs::path& pvd) {
    const std::string text = slurp(pvd);
    std::vector<std::string> files;
    for (std::size_t at = text.find("file=\""); at != std::string::npos; at = text.find("file=\"", at + 1)) {
        const std::size_t begin = at + 6;
        files.push_back(text.substr(begin, text.find('"', begin) - begin));
    }
    return files;
}

}  // namespace

TEST(ContactEquilibrium, RestingBlockContactsCarryItsWeight) {
    auto run = mcdda::test::run_text(resting_block);
    ASSERT_TRUE(run.simulation);
    const Simulation& s = *run.simulation;
    double total = 0.0;
    int closed = 0;
    for (const Contact& c : s.state().contacts) {
        if (c.state == ContactState::Open) continue;
        ++closed;
        // Contacts here are horizontal: the normal force is vertical.
        total += c.normal_force;
    }
    const double weight = 2500.0 * 9.81 * 2.0;  // ρ g A of the 2 m × 1 m block, N/m
    std::cout << "resting block: " << closed << " closed contacts carry " << total << " N/m, weight " << weight
              << " N/m, error " << 100.0 * (total - weight) / weight << " %\n";
    EXPECT_GT(closed, 4);
    EXPECT_NEAR(total, weight, 0.01 * weight);
    for (const Contact& c : s.state().contacts) EXPECT_NE(c.state, ContactState::Sliding);
}

TEST(ContactEquilibrium, RestingBlockContactForcesInTheFilesSumToItsWeight) {
    const auto read = read_model_text(resting_block, {}, "resting block");
    ASSERT_TRUE(read.model);
    const Preprocessed p = preprocess_model(*read.model);
    ASSERT_TRUE(p.ok);
    Simulation simulation(p);
    const fs::path dir = fs::temp_directory_path() / ("mcdda-output-files-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    {
        RunOutput output(dir.string(), "resting");
        const RunEnd end = run_steps(simulation, &output, nullptr, nullptr);
        output.write_summary(&simulation, end.status, end.message);
        EXPECT_EQ(end.status, RunStatus::Completed) << end.message;
    }
    // The contacts collection lists every saved step; the last file holds the last step.
    const auto files = collection_files(dir / "resting_contacts.pvd");
    ASSERT_EQ(files.size(), 4u);  // steps 0, 10, 20, 30
    const std::string xml = slurp(dir / files.back());
    const auto force = data_array(xml, "force"), vertex_block = data_array(xml, "vertex_block"),
               edge_block = data_array(xml, "edge_block"), state = data_array(xml, "state");
    ASSERT_FALSE(force.empty());
    ASSERT_EQ(force.size(), 3 * vertex_block.size());
    ASSERT_EQ(edge_block.size(), vertex_block.size());
    // The block is region 1's only block: the force on it is what its vertices receive minus
    // what its edges give to the base's vertices.
    const int block = p.blocks[0].region == 1 ? 0 : 1;
    double fx = 0.0, fy = 0.0;
    int closed = 0;
    for (std::size_t i = 0; i < vertex_block.size(); ++i) {
        const double sign = vertex_block[i] == block ? 1.0 : edge_block[i] == block ? -1.0 : 0.0;
        fx += sign * force[3 * i];
        fy += sign * force[3 * i + 1];
        closed += state[i] != 0.0;
    }
    const double weight = 2500.0 * 9.81 * 2.0;  // ρ g A of the 2 m × 1 m block, N/m
    std::cout << "resting block from the files: " << closed << " closed contacts, force on the block (" << fx << ", "
              << fy << ") N/m, weight " << weight << " N/m, error " << 100.0 * (fy - weight) / weight << " %\n";
    EXPECT_GT(closed, 4);
    EXPECT_NEAR(fy, weight, 1e-3 * weight);
    EXPECT_NEAR(fx, 0.0, 1e-3 * weight);

    // History: stage and unbalanced-force ratio columns; summary: the one stage, in equilibrium.
    std::istringstream history(slurp(dir / "history.csv"));
    std::string header, row, last;
    std::getline(history, header);
    EXPECT_EQ(header.rfind("step,time,stage,unbalanced_ratio", 0), 0u) << header;
    while (std::getline(history, row)) last = row;
    EXPECT_EQ(last.rfind("30,", 0), 0u) << last;
    const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"));
    EXPECT_EQ(summary["status"], "completed");
    ASSERT_EQ(summary["stages"].size(), 1u);
    EXPECT_EQ(summary["stages"][0]["status"], "completed");
    EXPECT_LT(summary["unbalanced_ratio"].get<double>(), 1e-2);
    fs::remove_all(dir);
}

// Parameter studies (study/Study.hpp): reading study files with their errors, expanding grids
// and sampled designs (deterministic per seed, Latin hypercube strata each used once), and
// turning a run's files into a row of study.csv.

#include "study/Study.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

using namespace mcdda;

namespace {

StudyDefinition read(const std::string& text) {
    std::vector<Diagnostic> d;
    const auto s = read_study_text(text, "/studies", d);
    EXPECT_TRUE(s.has_value());
    for (const Diagnostic& x : d) ADD_FAILURE() << format_diagnostic(x);
    return s.value_or(StudyDefinition{});
}

const char* grid = R"({"format": "mcdda-study", "version": 1, "model": "../m.json", "set": ["/analysis/steps=3"],
    "parameters": [{"name": "c", "path": "/materials/0/cohesion", "values": [1, 2]},
                   {"name": "E", "path": "/materials/0/young_modulus", "range": [10, 30, 3]}],
    "outputs": [{"name": "q", "summary": "/collapse/carried/loads/footing"}, {"name": "u", "history": "top:uy"}]})";

}  // namespace

TEST(Study, GridHasEveryCombinationLastParameterFastest) {
    const StudyDefinition s = read(grid);
    EXPECT_EQ(s.model, "/m.json");  // relative to the study file's folder
    const std::vector<StudyRun> runs = expand_study(s);
    ASSERT_EQ(runs.size(), 6u);
    EXPECT_EQ(runs[0].values, (std::vector<double>{1, 10}));
    EXPECT_EQ(runs[1].values, (std::vector<double>{1, 20}));
    EXPECT_EQ(runs[5].values, (std::vector<double>{2, 30}));
    EXPECT_EQ(runs[4].overrides,
              (std::vector<std::string>{"/analysis/steps=3", "/materials/0/cohesion=2", "/materials/0/young_modulus=20"}));
    EXPECT_EQ(runs[4].folder_name(), "run_0005");
}

TEST(Study, LatinHypercubeUsesEachStratumOnceAndRepeatsForASeed) {
    const std::string text = R"({"format": "mcdda-study", "version": 1, "model": "m.json",
        "design": {"type": "latin_hypercube", "samples": 40, "seed": 7},
        "parameters": [{"name": "a", "path": "/x", "uniform": [0, 4]}, {"name": "b", "path": "/y", "uniform": [-1, 1]}]})";
    const StudyDefinition s = read(text);
    const std::vector<StudyRun> runs = expand_study(s);
    ASSERT_EQ(runs.size(), 40u);
    for (int k = 0; k < 2; ++k) {
        const double low = k == 0 ? 0.0 : -1.0, width = k == 0 ? 4.0 : 2.0;
        std::set<int> strata;
        for (const StudyRun& r : runs) {
            const double u = (r.values[static_cast<std::size_t>(k)] - low) / width;
            ASSERT_GE(u, 0.0);
            ASSERT_LT(u, 1.0);
            strata.insert(static_cast<int>(u * 40));
        }
        EXPECT_EQ(strata.size(), 40u) << "parameter " << k;
    }
    EXPECT_EQ(expand_study(s)[17].values, runs[17].values);  // the same draws again
    StudyDefinition other = s;
    other.seed = 8;
    EXPECT_NE(expand_study(other)[17].values, runs[17].values);
    // Monte Carlo: independent draws in the range, also repeatable.
    other.design = StudyDefinition::Design::MonteCarlo;
    const auto mc = expand_study(other);
    EXPECT_EQ(mc.size(), 40u);
    for (const StudyRun& r : mc) EXPECT_TRUE(r.values[0] >= 0.0 && r.values[0] < 4.0);
    EXPECT_EQ(expand_study(other)[3].values, mc[3].values);
}

TEST(Study, ProblemsNameTheirPlace) {
    std::vector<Diagnostic> d;
    const auto s = read_study_text(R"({"format": "mcdda-study", "model": "m.json", "design": {"type": "grid"},
        "parameters": [{"path": "materials/0/cohesion", "uniform": [1, 0]}, {"path": "/x"}],
        "outputs": [{"name": "q", "summary": "/a", "history": "b"}], "extra": 1})", ".", d);
    EXPECT_FALSE(s.has_value());
    auto has = [&](const std::string& path, const std::string& words) {
        return std::any_of(d.begin(), d.end(), [&](const Diagnostic& x) {
            return x.path == path && x.message.find(words) != std::string::npos;
        });
    };
    EXPECT_TRUE(has("/parameters/0/path", "JSON pointer"));
    EXPECT_TRUE(has("/parameters/0/uniform", "low ≤ high"));
    EXPECT_TRUE(has("/parameters/1", "give the values"));
    EXPECT_TRUE(has("/outputs/0", "either"));
    EXPECT_TRUE(has("/extra", "unknown key"));
    d.clear();
    EXPECT_FALSE(read_study_text("{not json", ".", d).has_value());
    EXPECT_TRUE(has("", "not valid JSON"));
}

TEST(Study, RowsFromRunFilesAndBackThroughJson) {
    const StudyDefinition s = read(grid);
    const StudyRun run = expand_study(s)[2];
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "mcdda-study-test";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    // No summary: the run did not end.
    StudyRow failed = read_run_row(s, run, folder.string(), "killed by signal 9");
    EXPECT_EQ(failed.status, "failed");
    EXPECT_EQ(failed.message, "killed by signal 9");
    EXPECT_FALSE(row_is_finished(failed));
    std::ofstream(folder / "summary.json")
        << R"({"status": "collapsed", "message": "collapse, at \"step 3\"", "collapse": {"carried": {"loads": {"footing": 5140.5}}}})";
    std::ofstream(folder / "history.csv") << "step,time,top:ux,top:uy\n0,0,0,0\n1,1,0.5,-0.25\n";
    const StudyRow row = read_run_row(s, run, folder.string());
    EXPECT_EQ(row.status, "collapsed");
    EXPECT_TRUE(row_is_finished(row));
    ASSERT_EQ(row.outputs.size(), 2u);
    EXPECT_EQ(row.outputs[0], 5140.5);
    EXPECT_EQ(row.outputs[1], -0.25);
    const std::string csv = study_csv(s, {row, failed});
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "run,status,c,E,q,u,message");
    EXPECT_NE(csv.find("3,collapsed,1,30,5140.5,-0.25,\"collapse, at \"\"step 3\"\"\""), std::string::npos) << csv;
    const auto back = row_from_json(row_to_json(row));
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(study_csv(s, {*back}), study_csv(s, {row}));
    std::filesystem::remove_all(folder);
}

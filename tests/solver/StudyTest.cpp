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
    EXPECT_FALSE(read_study_text("{not json", ".", d, "s.json").has_value());
    EXPECT_TRUE(has("", "s.json:1:2: malformed JSON"));
}

// Malformed JSON and numbers beyond a double are said with file, line and column as the model
// reader says them, never in the JSON library's words (an overflow was an "unexpected failure").
TEST(Study, MalformedJsonIsSaidWithLineAndColumn) {
    const std::string text = R"({"format": "mcdda-study", "version": 1, "model": "m.json",
        "parameters": [{"name": "a", "path": "/x", "values": [VALUE]}]})";
    using Case = std::pair<std::string, std::string>;  // value, the message's beginning
    for (const auto& [value, words] : {Case{"NaN", "s.json:2:63: malformed JSON: NaN is not a number"},
                                       Case{"1e400", "s.json:2:63: number 1e400 is too large"}}) {
        std::string t = text;
        t.replace(t.find("VALUE"), 5, value);
        std::vector<Diagnostic> d;
        EXPECT_FALSE(read_study_text(t, ".", d, "s.json").has_value());
        ASSERT_EQ(d.size(), 1u);
        EXPECT_EQ(d[0].message.find(words), 0u) << d[0].message;
        EXPECT_EQ(d[0].message.find("json.exception"), std::string::npos) << d[0].message;
    }
}

// The version is the integer 1 (a later format must not be read as this one); the message says
// what is accepted.
TEST(Study, VersionMustBeOne) {
    for (const std::string version : {"0", "2", "\"1\"", "1.5", "true", "null"}) {
        std::vector<Diagnostic> d;
        const std::string text = R"({"format": "mcdda-study", "version": )" + version +
                                 R"(, "model": "m.json", "parameters": [{"path": "/x", "values": [1]}]})";
        EXPECT_FALSE(read_study_text(text, ".", d).has_value()) << version;
        ASSERT_EQ(d.size(), 1u) << version;
        EXPECT_EQ(d[0].path, "/version");
        EXPECT_NE(d[0].message.find("must be 1, the version of the study format this program reads"), std::string::npos)
            << d[0].message;
    }
    std::vector<Diagnostic> d;
    const std::string none = R"({"format": "mcdda-study", "model": "m.json", "parameters": [{"path": "/x", "values": [1]}]})";
    EXPECT_FALSE(read_study_text(none, ".", d).has_value());
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].path, "/version");
}

// The study file and its model must be regular files, refused by what they are before anything
// reads them: a model /dev/zero was read for 23 s before "malformed JSON".
TEST(Study, StudyAndModelMustBeFiles) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "mcdda-study-files";
    std::filesystem::create_directories(folder);
    auto problems_with_model = [&](const std::string& model) {
        std::ofstream(folder / "s.json") << R"({"format": "mcdda-study", "version": 1, "model": )" << model
                                         << R"(, "parameters": [{"path": "/x", "values": [1]}]})";
        std::vector<Diagnostic> d;
        EXPECT_FALSE(read_study_file((folder / "s.json").string(), d).has_value()) << model;
        std::string text;
        for (const Diagnostic& x : d) text += format_diagnostic(x) + "\n";
        return text;
    };
    EXPECT_NE(problems_with_model("\"/dev/zero\"").find("/model: /dev/zero is a character device, not a model file"),
              std::string::npos);
    EXPECT_NE(problems_with_model("\"/tmp\"").find("/tmp is a directory"), std::string::npos);
    EXPECT_NE(problems_with_model("\"m\\u0000.json\"").find("/model: the file name holds a NUL character"),
              std::string::npos);
    EXPECT_NE(problems_with_model("\"missing.json\"").find("missing.json does not exist"), std::string::npos);
    std::vector<Diagnostic> d;
    EXPECT_FALSE(read_study_file("/dev/zero", d).has_value());
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("the study file /dev/zero is a character device"), std::string::npos);
    std::filesystem::remove_all(folder);
}

// A cell a spreadsheet would take for a formula (=, +, -, @, tab, CR first, and not a number)
// starts with ' and is quoted (OWASP's rule against CSV injection); numbers stay numbers.
TEST(Study, CsvCellsAreNeverFormulas) {
    StudyDefinition s;
    s.parameters = {{"=HYPERLINK(\"http://x\")", "/a", {}, std::nullopt}, {"-b", "/b", {}, std::nullopt}};
    s.outputs = {{"@SUM(A1)", "/steps", ""}, {"+c", "", "c"}, {"\tcmd", "", "d"}};
    StudyRow row;
    row.index = 1;
    row.status = "failed";
    row.message = "-2+3,cmd|' /C calc'!A0";
    row.values = {-1.5, 2};
    row.outputs = {-0.25, std::nullopt, 1e-300};
    const std::string csv = study_csv(s, {row});
    EXPECT_EQ(csv, "run,status,\"'=HYPERLINK(\"\"http://x\"\")\",\"'-b\",\"'@SUM(A1)\",\"'+c\",\"'\tcmd\",message\n"
                   "1,failed,-1.5,2,-0.25,,1e-300,\"'-2+3,cmd|' /C calc'!A0\"\n");
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

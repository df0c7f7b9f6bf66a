// What is checked of a study before its first run (study/StudyCheck.hpp): outputs that name no
// number of summary.json or column of history.csv, listing what there is, and a value of a
// parameter the model refuses, naming its run.

#include "io/ModelReader.hpp"
#include "study/StudyCheck.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace mcdda;

namespace {

const std::string prandtl = std::string(MCDDA_EXAMPLES_DIR) + "/prandtl-footing.json";

StudyDefinition study_of(const std::string& text) {
    std::vector<Diagnostic> d;
    const auto s = read_study_text(text, MCDDA_EXAMPLES_DIR, d);
    for (const Diagnostic& x : d) ADD_FAILURE() << format_diagnostic(x);
    return s.value_or(StudyDefinition{});
}

std::string messages(const std::vector<Diagnostic>& d) {
    std::string text;
    for (const Diagnostic& x : d) text += format_diagnostic(x) + "\n";
    return text;
}

}  // namespace

TEST(StudyCheck, OutputsMustNameWhatARunWrites) {
    const StudyDefinition s = study_of(R"({"format": "mcdda-study", "version": 1, "model": "prandtl-footing.json",
        "parameters": [{"path": "/materials/0/cohesion", "values": [1e5]}],
        "outputs": [{"name": "q", "summary": "/collapse/carried/loads/footing load"},
                    {"name": "s0", "summary": "/stages/0/unbalanced_ratio"},
                    {"name": "u", "history": "footing centre:uy"},
                    {"name": "typo", "summary": "/collapse/carried/load/footing load"},
                    {"name": "text", "summary": "/status"},
                    {"name": "stage", "summary": "/stages/1/unbalanced_ratio"},
                    {"name": "point", "history": "footing:uy"}]})");
    const ReadResult model = read_model_file(prandtl);
    ASSERT_TRUE(model.model.has_value());
    const std::vector<Diagnostic> d = check_study_outputs(s, *model.model);
    std::vector<std::string> paths;
    for (const Diagnostic& x : d) paths.push_back(x.path);
    EXPECT_EQ(paths, (std::vector<std::string>{"/outputs/3/summary", "/outputs/4/summary", "/outputs/5/summary",
                                               "/outputs/6/history"}))
        << messages(d);
    const std::string text = messages(d);
    EXPECT_NE(text.find("summary.json of this model has no number at /collapse/carried/load/footing load (it has "
                        "/steps, /time"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("/collapse/carried/loads/footing load"), std::string::npos);
    EXPECT_NE(text.find("history.csv of this model has no column \"footing:uy\" (it has step, time, stage, "
                        "unbalanced_ratio, load:footing load, footing centre:ux, footing centre:uy)"),
              std::string::npos)
        << text;
}

TEST(StudyCheck, AStrengthReductionHasItsFactorAndTrialColumns) {
    const StudyDefinition s = study_of(R"({"format": "mcdda-study", "version": 1, "model": "slope-wedge.json",
        "set": ["/analysis/type=\"strength_reduction\""],
        "parameters": [{"path": "/joint_materials/0/friction_angle", "values": [25]}],
        "outputs": [{"name": "F", "summary": "/factor_of_safety/value"},
                    {"name": "F3", "summary": "/factor_of_safety/table/3/factor"},
                    {"name": "f", "history": "factor"}, {"name": "step", "history": "step"}]})");
    const std::vector<StudyRun> runs = expand_study(s);
    const StudyCheck check = check_study(s, runs);
    EXPECT_FALSE(check.ok);
    ASSERT_EQ(check.study.size(), 1u) << messages(check.study) << messages(check.model);
    EXPECT_EQ(check.study[0].path, "/outputs/3/history");
}

// A value the model refuses is found before the first run, with the run that has it; every
// problem once.
TEST(StudyCheck, AValueTheModelRefusesIsFoundBeforeRunning) {
    const StudyDefinition s = study_of(R"({"format": "mcdda-study", "version": 1, "model": "prandtl-footing.json",
        "parameters": [{"name": "cu", "path": "/materials/0/cohesion", "range": [1, 0, 2]},
                       {"name": "E", "path": "/materials/0/young_modulus", "values": [1e7, 2e7, -1]}],
        "outputs": [{"name": "a", "summary": "/plastic_area"}]})");
    const std::vector<StudyRun> runs = expand_study(s);
    const StudyCheck check = check_study(s, runs);
    EXPECT_FALSE(check.ok);
    const std::string text = messages(check.model);
    EXPECT_NE(text.find("(in run 3: cu = 1, E = -1)"), std::string::npos) << text;
    EXPECT_NE(text.find("(in run 4: cu = 0, E = 1e+07)"), std::string::npos) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << text;
    // The same values, all good: nothing to say.
    StudyDefinition good = s;
    good.parameters[0].values = {1e5, 2e5};
    good.parameters[1].values = {1e7, 2e7};
    const StudyCheck fine = check_study(good, expand_study(good));
    EXPECT_TRUE(fine.ok) << messages(fine.model) << messages(fine.study);
}

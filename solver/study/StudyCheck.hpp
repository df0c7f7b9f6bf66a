#pragma once
/// \file StudyCheck.hpp
/// What is checked of a study before its first run (docs/study.md), so that a mistake costs
/// seconds rather than the runs before it: the base model with the values its parameters take,
/// and the outputs against what a run of that model writes.

#include "model/Diagnostic.hpp"
#include "model/Model.hpp"
#include "study/Study.hpp"

#include <string>
#include <vector>

namespace mcdda {

/// What a run of a model writes that a study can gather: numbers only.
struct StudyOutputNames {
    std::vector<std::string> summary;  ///< JSON pointers into summary.json; "<i>" stands for an index
    std::vector<std::string> history;  ///< columns of history.csv
};

/// The outputs a run of `model` gives (run/RunOutput.cpp writes them; docs/running.md lists
/// them). A roller whose displacement a parameter of `study` sets counts as moving.
StudyOutputNames study_output_names(const Model& model, const StudyDefinition& study);

/// The outputs of `study` that name nothing a run of `model` writes, each an error at
/// /outputs/i listing what there is.
std::vector<Diagnostic> check_study_outputs(const StudyDefinition& study, const Model& model);

struct StudyCheck {
    std::vector<Diagnostic> model;  ///< about the base model (after the first run, naming the run)
    std::vector<Diagnostic> study;  ///< about the study file
    bool ok = false;
};

/// Reads and validates the base model with the first run's values, then with each value a
/// parameter takes (every one of a parameter that takes at most 20, else its smallest and
/// largest), each in the first run that has it; then checks the outputs.
StudyCheck check_study(const StudyDefinition& study, const std::vector<StudyRun>& runs);

}  // namespace mcdda

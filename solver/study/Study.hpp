#pragma once
/// \file Study.hpp
/// Parameter studies (docs/study.md): a study file names a base model, the fields to vary (by
/// JSON pointer: lists, ranges, or uniform draws for Latin hypercube and Monte Carlo designs with
/// a seed) and the outputs to gather from each run's summary.json and history.csv. This part
/// reads the file, expands it into runs and turns a finished run's files into a row of
/// study.csv; `mcdda study` (app/cli/StudyCommand.cpp) runs them, in turn or spread over MPI
/// ranks.

#include "model/Diagnostic.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mcdda {

struct StudyParameter {
    std::string name;                 ///< column of study.csv
    std::string path;                 ///< JSON pointer into the model, e.g. "/materials/0/cohesion"
    std::vector<double> values;       ///< grid designs: the values (a list, or a range expanded)
    std::optional<std::array<double, 2>> uniform;  ///< sampled designs: drawn uniformly in [a, b]
};

struct StudyOutput {
    std::string name;     ///< column of study.csv
    std::string summary;  ///< a JSON pointer into the run's summary.json, or
    std::string history;  ///< a column of its history.csv (the last row's value)
};

struct StudyDefinition {
    enum class Design { Grid, LatinHypercube, MonteCarlo };
    std::string model;                   ///< the base model file (absolute, or relative to the study file)
    std::vector<std::string> overrides;  ///< applied to every run before the varied fields
    Design design = Design::Grid;
    int samples = 0;                     ///< sampled designs: number of runs
    std::uint64_t seed = 1;
    std::vector<StudyParameter> parameters;
    std::vector<StudyOutput> outputs;
    int threads_per_run = 0;             ///< 0: 1 under MPI with several ranks, else all cores
};

/// One run of a study: its number (1-based) and the values of the parameters.
struct StudyRun {
    int index = 0;
    std::vector<double> values;  ///< one per StudyDefinition::parameters
    /// The study's overrides and the parameters' as `--set` arguments ("/pointer=value").
    std::vector<std::string> overrides;
    std::string folder_name() const;  ///< "run_0001"
};

/// Reads a study file; the model path is resolved against the study file's folder. Problems are
/// diagnostics naming their JSON pointer (malformed JSON: `source`, line and column); nullopt
/// when there is any error. The file's variant also refuses a study file or model that is not a
/// regular file (a directory, /dev/zero), before reading it.
std::optional<StudyDefinition> read_study_file(const std::string& path, std::vector<Diagnostic>& diagnostics);
std::optional<StudyDefinition> read_study_text(const std::string& text, const std::string& folder,
                                               std::vector<Diagnostic>& diagnostics,
                                               const std::string& source = "study");

/// The runs of the study in order: the grid's every combination (the last parameter varying
/// fastest), or `samples` draws (deterministic for a seed, on any machine).
std::vector<StudyRun> expand_study(const StudyDefinition& study);

/// How a run ended and what it gave.
struct StudyRow {
    int index = 0;
    std::string status;   ///< completed, unbalanced, collapsed, failed, cancelled
    std::string message;
    std::vector<double> values;   ///< the run's parameter values
    std::vector<std::optional<double>> outputs;  ///< empty cell when the run did not give it
};

/// The row of a run whose files are in `folder` (summary.json, history.csv). A run that left no
/// summary is "failed" with `failure` as its message.
StudyRow read_run_row(const StudyDefinition& study, const StudyRun& run, const std::string& folder,
                      const std::string& failure = "no summary.json: the run did not end");

/// study.csv: a header (run, status, parameters, outputs, message) and the rows in run order.
std::string study_csv(const StudyDefinition& study, const std::vector<StudyRow>& rows);

/// A row as one line of JSON, and back (how MPI ranks send rows, and how a finished run records
/// its row in its folder so that a rerun of the study can skip it).
std::string row_to_json(const StudyRow& row);
std::optional<StudyRow> row_from_json(const std::string& text);

/// Whether a run with this status has its result (a rerun skips it): completed, unbalanced and
/// collapsed; failed or cancelled runs are run again.
bool row_is_finished(const StudyRow& row);

}  // namespace mcdda

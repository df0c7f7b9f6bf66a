#pragma once
/// \file RunMessages.hpp
/// What the desktop program says about pre-processing and runs, as translatable text (Qt Core
/// only): the log lines, the status-bar summaries and the end of a run.

#include "Preprocess.hpp"
#include "session/RunController.hpp"

#include <QString>
#include <QStringList>

namespace mcdda::gui {

/// The Messages dock's lines after pre-processing `p`, read from `source`: its diagnostics,
/// mesh statistics and times.
QStringList preprocess_report(const Preprocessed& p, const QString& source);
/// The mesh statistics, several lines: counts, angles, areas, the angle histogram.
QString mesh_report(const MeshStatistics& s);
/// The status bar's summary of `p`: blocks, nodes, elements, smallest angle; or its error count.
QString mesh_summary(const Preprocessed& p);
/// The errors among `p`'s diagnostics, one per line; a line saying so when there are none.
QStringList error_lines(const Preprocessed& p);
/// The first `count` of `lines` and, when there are more, a line saying how many more.
QString first_lines(const QStringList& lines, int count);
/// The log line of an accepted step.
QString progress_line(const RunProgress& p);
/// The status-bar line inside a long step.
QString iteration_line(const IterationInfo& info);
/// The status-bar line while a strength reduction trial runs.
QString trial_start_line(int number, double factor);
/// The log line of a strength reduction trial that ended: its factor, whether the model stood
/// and, when not, why.
QString trial_line(const StrengthTrial& trial);
/// The factor of safety a search found, in a few words ("1.55"), or why there is none.
QString factor_text(const FactorOfSafety& factor);
/// The log line of a search's result: the factor, its bracket and the number of trials.
QString factor_line(const FactorOfSafety& factor);
/// The log line of what an earthquake left, from a run's summary.json (its
/// "permanent_displacement": the largest, where, and each measurement point's, relative to the
/// base); empty when the file has none (no base motion) or cannot be read.
QString permanent_displacement_line(const QString& summary_path);
/// How a run ended, after `step` accepted steps; `message` says why unless it completed.
QString end_line(RunStatus status, int step, const QString& message);

}  // namespace mcdda::gui

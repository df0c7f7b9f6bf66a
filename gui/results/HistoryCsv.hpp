#pragma once
/// \file HistoryCsv.hpp
/// A run's history.csv (RunOutput::record_history): a header row (step, time, load:<name>...,
/// <point>:ux, <point>:uy...) and one row of numbers per step; or, of a strength reduction, one
/// row per trial (trial, factor, status, stands, ..., max_displacement, <point>:ux, ...).

#include <QString>
#include <QStringList>

#include <vector>

namespace mcdda::gui {

struct HistoryTable {
    QStringList columns;
    std::vector<std::vector<double>> rows;  ///< each as long as columns; words are NaN

    int column(const QString& name) const { return static_cast<int>(columns.indexOf(name)); }
    /// One row per strength reduction trial, not per step.
    bool isTrialTable() const { return columns.contains(QStringLiteral("factor")) && columns.contains(QStringLiteral("stands")); }
};

/// Reads the history at `path`; rows of the wrong length (e.g. cut off) are left out. False
/// with `error` set when the file cannot be read or has no header.
bool read_history(const QString& path, HistoryTable& table, QString* error = nullptr);

}  // namespace mcdda::gui

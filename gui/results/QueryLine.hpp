#pragma once
/// \file QueryLine.hpp
/// A field sampled along a straight line of the result picture (RS2's query lines, PLAXIS's
/// cross-sections), and its CSV file.

#include "model/Model.hpp"
#include "view/ResultProbe.hpp"

#include <QString>

#include <vector>

namespace mcdda::gui {

struct QuerySample {
    double distance = 0.0;  ///< from the line's start (m)
    Point2 point;           ///< where (m)
    double value = 0.0;     ///< in the picture's units; meaningless when !inside
    bool inside = false;    ///< on the mesh (not in an opening or outside the model)
};

/// `count` (≥ 2) evenly spaced samples of what `probe` shows from `from` to `to`, ends included.
std::vector<QuerySample> sample_line(const view::ResultProbe& probe, const Point2& from, const Point2& to, int count);

/// Writes the samples on the mesh as CSV (distance, x, y, value) with a header naming the field
/// and its units; atomically (a failed write leaves an existing file as it was).
bool write_query_csv(const std::vector<QuerySample>& samples, const QString& field, const QString& units,
                     const QString& path, QString& error);

}  // namespace mcdda::gui

#pragma once
/// \file PvdFile.hpp
/// The list of saved steps of a run: the DataSet entries of its ParaView collection (.pvd, as
/// RunOutput writes it). A small XML reader; no VTK.

#include <QString>

#include <vector>

namespace mcdda::gui {

struct PvdEntry {
    double time = 0.0;  ///< s
    QString file;       ///< absolute path of the step's .vtu
};

/// The entries of the .pvd at `path` in file order, files resolved against its folder. Empty
/// with `error` set (when given) when the file cannot be read or is not a collection.
std::vector<PvdEntry> read_pvd(const QString& path, QString* error = nullptr);

}  // namespace mcdda::gui

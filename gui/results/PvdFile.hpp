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

/// The contacts file RunOutput writes beside a step (<stem>_NNNNNN.vtu ->
/// <stem>_contacts_NNNNNN.vtp): contact forces, joint slip and opening, bolts. Empty when there
/// is none.
QString contacts_file_for(const QString& vtu_path);

}  // namespace mcdda::gui

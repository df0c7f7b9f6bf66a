#pragma once
/// \file ResultFileReader.hpp
/// A strict reader of the result files `mcdda run` writes (solver/io/VtuWriter.cpp): a step's
/// ASCII VTK XML unstructured grid (<model>_NNNNNN.vtu, also `mcdda mesh`'s <model>.vtu) and its
/// contacts poly data (<model>_contacts_NNNNNN.vtp). Every file is hostile input: the reader
/// parses the XML itself (no DTD, no entities, no comments) and accepts only the elements,
/// attributes, DataArray types, component counts and the ASCII format those writers produce,
/// with every count, index, offset, cell type and array name checked before anything is built.
/// Anything else is refused with one plain sentence naming the file and line, e.g.
///   r.vtu:5857: cell offsets must increase (offset 12 follows 15)
/// The output is built directly as VTK data sets (VTK's XML readers are never involved). Numbers
/// in point and cell data may be NaN or infinite (the caller decides what a field it draws may
/// hold); coordinates and field data (step, stage, time) must be finite. No Qt.

#include "view/ResultScene.hpp"  // ResultFileError

#include <vtkSmartPointer.h>

#include <cstddef>
#include <stdexcept>
#include <string>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace mcdda::view {


/// The mesh a result file must belong to (the model's): its counts are checked against the
/// file's declared ones before anything is read from them.
struct ExpectedMesh {
    std::size_t nodes = 0;
    std::size_t triangles = 0;
    bool quadratic = false;  ///< six-node triangles (VTK type 22) instead of three-node ones (5)
};

/// Reads a result .vtu: points, the model's triangles, point, cell and field data.
/// Throws ResultFileError.
vtkSmartPointer<vtkUnstructuredGrid> read_result_grid(const std::string& path, const ExpectedMesh& mesh);

/// Reads a contacts .vtp: points, one-point vertex cells, two-point lines, point, cell and field
/// data. Throws ResultFileError.
vtkSmartPointer<vtkPolyData> read_contacts_file(const std::string& path);

}  // namespace mcdda::view

#pragma once
/// \file VtuWriter.hpp
/// VTK XML unstructured grid (.vtu) files of the mesh and its fields, for ParaView.

#include "mesh/Mesh.hpp"

#include <array>
#include <string>
#include <vector>

namespace mcdda {

/// A named field on nodes or cells; `components` values per entry, stored entry by entry.
struct VtuField {
    std::string name;
    int components = 1;
    std::vector<double> values;
};

struct VtuFields {
    std::vector<VtuField> point_data;
    std::vector<VtuField> cell_data;
    std::vector<VtuField> field_data;  ///< of the whole data set (step, stage)
};

/// Writes the mesh (three- or six-node triangles, z = 0) with cell data `block` and `material`
/// (Int32) plus the given fields, atomically. Throws std::runtime_error on failure.
void write_vtu(const std::string& path, const Mesh& mesh, const VtuFields& fields = {});

/// Points in the plane drawn as vertices (one cell each) and line segments, with fields: VTK XML
/// poly data (.vtp). Cell data holds one entry per vertex cell, then one per line.
struct PolyData {
    std::vector<Point2> points;
    std::vector<int> vertices;
    std::vector<std::array<int, 2>> lines;
    VtuFields fields;
};

/// Writes `data` atomically. Throws std::runtime_error on failure.
void write_vtp(const std::string& path, const PolyData& data);

}  // namespace mcdda

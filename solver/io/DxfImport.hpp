#pragma once
/// \file DxfImport.hpp
/// A model from a DXF drawing (docs/dxf-import.md), read with dxflib:
///   closed LWPOLYLINE / POLYLINE   → a region whose material is named after the layer, or, on a
///                                    layer called holes/openings, a hole of the region around it
///   open polylines, LINE           → joints, their joint material named after the layer
///   POINT                          → measurement points "<layer> <n>"
/// Materials and joint materials get a new model's properties (Defaults.hpp), to be set after.
/// Drawing units come from $INSUNITS (millimetres, centimetres, metres, inches, feet …) unless
/// given; a drawing without units is read as metres and a warning says so. Every entity of
/// another kind is reported (counted by kind and layer), never dropped silently.

#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mcdda {

struct DxfImportOptions {
    /// Metres per drawing unit; 0: from the drawing's $INSUNITS (metres when it has none).
    double metres_per_unit = 0.0;
};

struct DxfImportResult {
    std::optional<Model> model;            ///< none when the drawing cannot be used
    std::vector<Diagnostic> diagnostics;   ///< what was skipped, assumed or wrong
    std::string summary;                   ///< "2 regions (layers rock, clay), 1 hole, 12 joints, …"
};

DxfImportResult import_dxf_file(const std::string& path, const DxfImportOptions& options = {});

/// Metres per unit for a unit name of the command line: m, mm, cm, km, in, ft; 0 when unknown.
double metres_per_unit_named(const std::string& name);

}  // namespace mcdda

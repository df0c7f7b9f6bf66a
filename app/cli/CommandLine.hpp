#pragma once
/// \file CommandLine.hpp
/// Parsing of `mcdda COMMAND MODEL [options]`; no behaviour, just the user's request.

#include <optional>
#include <string>
#include <vector>

namespace mcdda::cli {

struct Request {
    std::string command;                 ///< check, mesh, render; empty with --help/--version
    std::string model;                   ///< model file path
    std::string out;                     ///< --out (directory for mesh, PNG file for render)
    std::vector<std::string> overrides;  ///< --set POINTER=VALUE, in order
    bool help = false;
    bool version = false;
    bool profile = false;                ///< --profile: print a timing breakdown
    bool quiet = false;                  ///< --quiet: errors only
    int width = 1600, height = 1000;     ///< --size WxH for render
    bool show_mesh = true;               ///< --no-mesh hides element edges in render
    std::string results;                 ///< --results STEP.vtu: render draws this result
    std::string contacts;                ///< --contacts STEP.vtp: with it, the contact forces and bolts
    std::string field = "plastic_state"; ///< --field NAME: what the result picture colours
    double deform = 0.0;                 ///< --deform FACTOR: displacement scale of the result picture
    bool deform_auto = false;            ///< --deform auto: the largest displacement drawn as 5 % of the model
    bool compression_positive = false;   ///< --compression-positive: stresses as geotechnics reads them
    std::string colour_map;              ///< --colour-map NAME (rainbow, viridis, grey, diverging)
    int bands = 0;                       ///< --bands N: colour bands; 0 = smooth
    double range_min = 0.0, range_max = 0.0;  ///< --range MIN:MAX (both 0: automatic)
    bool show_axes = true;               ///< --no-axes hides the rulers and the scale bar
    std::string title;                   ///< --title TEXT over a result picture
    int threads = 0;                     ///< --threads N for run (0: $MCDDA_THREADS, else one per core)
    std::string units;                   ///< --units NAME for import-dxf (empty: the drawing's)
};

/// Parses argv; returns the request or sets `error` to a message for the user.
std::optional<Request> parse_command_line(const std::vector<std::string>& args, std::string& error);

/// The text printed by --help.
std::string usage_text();

}  // namespace mcdda::cli

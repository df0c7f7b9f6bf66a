#pragma once
/// \file ModelScene.hpp
/// Turns a pre-processed model into a VTK scene: the one picture of a model that the desktop
/// view, `mcdda render` and the tests share. VTK stays out of this header.

#include "Preprocess.hpp"

#include <string>
#include <vector>

class vtkRenderer;

namespace mcdda::view {

/// What the picture shows; everything on by default.
struct SceneOptions {
    bool show_mesh = true;      ///< element edges (the fill is always drawn)
    bool show_joints = true;    ///< joint traces, red, over everything else
    bool show_supports = true;  ///< fixed points and rollers
    bool show_loads = true;     ///< point loads and edge pressures
    bool show_legend = true;    ///< box in the top right corner naming colours and symbols
    bool show_points = true;    ///< measurement points with their names
    bool show_axes = true;      ///< coordinate axes on the left and bottom edges and a scale bar
    /// Regions not drawn (nor their mesh, outlines and the joints through them): those absent in
    /// the construction stage shown (regions_present()).
    std::vector<int> hidden_regions;
    /// Supports, loads and bolts not drawn, by name: those absent in the stage shown (items_absent()).
    std::vector<std::string> hidden_items;
    /// The construction stage shown (0-based; -1 = the model as drawn): the ground water drawn is
    /// the one in force in it (water_of_stage()).
    int stage = -1;
    bool show_water = true;  ///< the piezometric line, blue, with the ▽ water-table symbol
};

/// Adds the actors of the model to `renderer`: blocks filled in their material's colour with
/// dark outlines, mesh edges, joints, the water table, supports, loads, measurement points and the legend; sets
/// a white-ish background and fits a parallel camera (see fit_camera). With an empty mesh the
/// blocks, or else the model's regions, are filled. Nothing already in `renderer` is removed.
/// Line widths and text grow with the render window's DPI (72 = one pixel per point).
void build_model_scene(vtkRenderer* renderer, const Preprocessed& p, const SceneOptions& options);

/// Points the parallel camera at everything in `renderer` with a margin, keeping the legend's
/// column on the right free when there is room. Uses the renderer's current size in pixels, so
/// call it again after the window was resized.
void fit_camera(vtkRenderer* renderer, const Preprocessed& p, const SceneOptions& options);

/// fit_camera with an explicit column of `reserved_pixels` on the right kept free (for a legend
/// other than the model's; ignored when it would take more than 45 % of the width), and bands on
/// the left, bottom and top for axes and a title.
void fit_camera(vtkRenderer* renderer, const Preprocessed& p, double reserved_pixels, double left_pixels = 0.0,
                double bottom_pixels = 0.0, double top_pixels = 0.0);

}  // namespace mcdda::view

#pragma once
/// \file SceneLegend.hpp
/// The legend box of model pictures: which colour is which material, what the red lines and
/// the symbols mean. Laid out in pixels, anchored to the top right corner of the viewport.

#include "view/ModelScene.hpp"
#include "view/Palette.hpp"

#include <string>
#include <vector>

class vtkRenderer;

namespace mcdda::view {

/// One row of the legend: an icon and its text.
struct LegendEntry {
    enum class Icon { Swatch, Line, Pin, Roller, Arrow, Pressure, Diamond, WaterTable, Dashpot, CompliantBase };
    Icon icon = Icon::Swatch;
    Rgb color{};
    std::string label;
};

/// Rows for what the scene shows: used materials, block boundaries, joints, the water table,
/// supports, loads, measurement points. Empty when the legend is switched off or the model is empty.
std::vector<LegendEntry> legend_entries(const Preprocessed& p, const SceneOptions& options);

/// Width of the legend box in pixels at `dpi` (72 = one pixel per point); 0 without entries.
int legend_width(const std::string& title, const std::vector<LegendEntry>& entries, double dpi);

/// Space the legend keeps from the viewport's edges (pixels).
int legend_margin(double dpi);

/// Adds the legend's 2-D actors (frame, icons, texts) to `renderer`.
void add_legend(vtkRenderer* renderer, const std::string& title,
                const std::vector<LegendEntry>& entries, double dpi);

/// The legend's heading: the model's name, or "Legend" when it has none.
std::string legend_title(const Preprocessed& p);

}  // namespace mcdda::view

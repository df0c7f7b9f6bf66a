#pragma once
/// \file Palette.hpp
/// The colours of model pictures, in one place so the screen, the PNGs and the legend agree.
/// Chosen for print and projector: light material fills (mesh lines stay visible on them),
/// saturated symbols, and no red fills (red means joints).

#include <array>

namespace mcdda::view {

/// RGB in [0, 1].
using Rgb = std::array<double, 3>;

/// Fill colour of material `index` (cycles after the palette ends); grey for −1 (unassigned).
Rgb material_color(int index);

namespace palette {
inline constexpr Rgb background{0.965, 0.970, 0.975};   ///< white-ish, not pure white
inline constexpr Rgb block_outline{0.10, 0.10, 0.12};   ///< block and region boundaries
inline constexpr Rgb mesh_edge{0.36, 0.38, 0.42};       ///< element edges (fine meshes stay light)
inline constexpr Rgb joint{0.85, 0.08, 0.08};           ///< joints inside the rock (block edges on one, cracks)
inline constexpr Rgb joint_outside{0.95, 0.62, 0.62};   ///< parts of traces outside any region
inline constexpr Rgb support{0.05, 0.25, 0.70};         ///< fixed points and rollers
inline constexpr Rgb point_load{0.60, 0.00, 0.60};      ///< point loads
inline constexpr Rgb pressure{0.80, 0.33, 0.00};        ///< edge pressures
inline constexpr Rgb measurement{0.00, 0.45, 0.20};     ///< measurement points
inline constexpr Rgb bolt{0.55, 0.42, 0.00};            ///< rock bolts (steel, ochre)
/// The piezometric line and its ▽ symbol: a bright blue, far from the supports' navy and the
/// light blue and teal fills, so the water reads as water.
inline constexpr Rgb water{0.00, 0.50, 1.00};
/// Absorbing boundaries and the compliant base (dashpots): a magenta far from the joints' red,
/// the loads' purple and the supports' navy, so a boundary that lets waves out reads apart.
inline constexpr Rgb absorbing{0.75, 0.05, 0.50};
inline constexpr Rgb text{0.08, 0.08, 0.10};            ///< legend and label text
inline constexpr Rgb legend_frame{0.55, 0.56, 0.58};
inline constexpr Rgb unassigned{0.75, 0.75, 0.75};      ///< material index −1 or out of range
inline constexpr Rgb snap_marker{1.00, 0.55, 0.00};     ///< where a drawing click would land
/// A query line over a result picture: near-black in a white halo, readable on every colour map.
inline constexpr Rgb query_line{0.05, 0.05, 0.05};
inline constexpr Rgb query_halo{1.00, 1.00, 1.00};
inline constexpr Rgb grid{0.30, 0.32, 0.36};            ///< the snapping grid (drawn translucent)
}  // namespace palette

}  // namespace mcdda::view

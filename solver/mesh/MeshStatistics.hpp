#pragma once
/// \file MeshStatistics.hpp
/// Quality figures users check before they run: counts, angles, a histogram of minimum angles.

#include "geometry/Block.hpp"
#include "mesh/Mesh.hpp"

#include <array>
#include <string>

namespace mcdda {

struct MeshStatistics {
    int blocks = 0;
    int nodes = 0;
    int elements = 0;
    double min_angle_deg = 0.0;  ///< smallest interior angle of any triangle
    double max_angle_deg = 0.0;
    double min_area = 0.0, max_area = 0.0, total_area = 0.0;  ///< m²
    /// Count of triangles whose smallest angle falls in [10k, 10k+10) degrees, k = 0..5.
    std::array<int, 6> min_angle_histogram{};
    /// Sharpest corner of the blocks themselves: no mesh can have a smaller bound near it.
    double min_input_angle_deg = 180.0;
};

MeshStatistics compute_statistics(const Mesh& mesh, const std::vector<Block>& blocks);

/// Smallest interior corner angle over all block rings (degrees).
double smallest_corner_angle_deg(const std::vector<Block>& blocks);

/// A few lines of text for terminals and the GUI's log.
std::string describe(const MeshStatistics& s);

}  // namespace mcdda

#pragma once
/// \file MeshStatistics.hpp
/// Quality figures users check before they run: counts, angles, a histogram of minimum angles.

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
};

MeshStatistics compute_statistics(const Mesh& mesh);

/// A few lines of text for terminals and the GUI's log.
std::string describe(const MeshStatistics& s);

}  // namespace mcdda

#include "mesh/MeshStatistics.hpp"

#include "geometry/BlockFeatures.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mcdda {

namespace {
constexpr double to_deg = 180.0 / 3.14159265358979323846;
}

double smallest_corner_angle_deg(const std::vector<Block>& blocks) {
    double smallest = 180.0;
    for (const Block& b : blocks) smallest = std::min(smallest, sharpest_corner(b).angle_deg);
    return smallest;
}

MeshStatistics compute_statistics(const Mesh& mesh, const std::vector<Block>& blocks) {
    MeshStatistics s;
    s.min_input_angle_deg = smallest_corner_angle_deg(blocks);
    s.blocks = mesh.block_count();
    s.nodes = static_cast<int>(mesh.nodes.size());
    s.elements = static_cast<int>(mesh.triangles.size());
    s.min_angle_deg = mesh.triangles.empty() ? 0.0 : 180.0;
    s.min_area = mesh.triangles.empty() ? 0.0 : 1e300;
    for (const auto& t : mesh.triangles) {
        const Point2 p[3] = {mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]};
        const double area = 0.5 * ((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y));
        double smallest = 180.0;
        for (int k = 0; k < 3; ++k) {
            const Point2& a = p[k];
            const Point2& b = p[(k + 1) % 3];
            const Point2& c = p[(k + 2) % 3];
            const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
            const double angle = std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * to_deg;
            smallest = std::min(smallest, angle);
            s.max_angle_deg = std::max(s.max_angle_deg, angle);
        }
        s.min_angle_deg = std::min(s.min_angle_deg, smallest);
        s.min_angle_histogram[std::min(5, static_cast<int>(smallest / 10.0))]++;
        s.min_area = std::min(s.min_area, area);
        s.max_area = std::max(s.max_area, area);
        s.total_area += area;
    }
    return s;
}

std::string describe(const MeshStatistics& s) {
    std::ostringstream out;
    out.precision(4);
    out << s.blocks << " blocks, " << s.nodes << " nodes, " << s.elements << " triangles\n"
        << "angles: min " << s.min_angle_deg << "°, max " << s.max_angle_deg << "°\n"
        << "areas: min " << s.min_area << " m², max " << s.max_area << " m², total " << s.total_area << " m²\n"
        << "sharpest block corner: " << s.min_input_angle_deg << "°\n"
        << "triangles by smallest angle:";
    for (int k = 0; k < 6; ++k)
        out << (k ? ", " : " ") << 10 * k << (k == 5 ? "+" : "-" + std::to_string(10 * k + 10)) << "°: "
            << s.min_angle_histogram[k];
    out << "\n";
    return out.str();
}

}  // namespace mcdda

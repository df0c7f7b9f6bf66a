#include "TunnelModel.hpp"

#include <cmath>

namespace mcdda::guitest {

Model tunnel_model()
{
    const double degree = M_PI / 180.0;
    Model m;
    m.name = "Test tunnel";

    Material rock;
    rock.name = "Sandstone";
    rock.young_modulus = 5e9;
    rock.poisson_ratio = 0.25;
    rock.density = 2500;
    rock.parameters = {{"cohesion", 2e6}, {"friction_angle", 35 * degree}, {"dilation_angle", 0.0}, {"tensile_strength", 0.5e6}};
    m.materials.push_back(rock);

    JointMaterial joint_material;
    joint_material.name = "Bedding";
    joint_material.friction_angle = 30 * degree;
    m.joint_materials.push_back(joint_material);
    m.default_joint_material = 0;

    Region region;
    region.name = "rock";
    region.material = 0;
    region.boundary = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    Ring hole;
    for (int i = 0; i < 32; ++i) {
        const double a = 2.0 * M_PI * i / 32;
        hole.push_back({hole_centre.x + hole_radius * std::cos(a), hole_centre.y + hole_radius * std::sin(a)});
    }
    region.holes.push_back(hole);
    m.regions.push_back(region);

    Joint joint;
    joint.name = "J1";
    joint.points = {{-1.0, joint_y0 - joint_slope}, {11.0, joint_y0 + 11.0 * joint_slope}};
    joint.joint_material = 0;
    m.joints.push_back(joint);

    m.fixed_points.push_back({"base", {5.0, 0.0}});
    Roller left;
    left.name = "left";
    left.from = {0, 0};
    left.to = {0, 10};
    left.fix_x = true;
    m.rollers.push_back(left);
    PointLoad load;
    load.name = "footing";
    load.point = {8.0, 10.0};
    load.force = {0.0, -1e5};
    m.point_loads.push_back(load);
    EdgePressure pressure;
    pressure.name = "right";
    pressure.from = {10, 0};
    pressure.to = {10, 10};
    pressure.pressure = 1e6;
    m.edge_pressures.push_back(pressure);
    m.measurement_points.push_back({"crown", {5.0, 7.0}});

    m.mesh.size = 0.8;
    return m;
}

std::vector<Point2> rock_samples() { return {{1.5, 8.5}, {8.5, 1.5}, {2.0, 5.0}, {8.0, 5.0}}; }

std::vector<Point2> opening_samples() { return {{4.0, 6.0}, {6.0, 4.0}}; }

}  // namespace mcdda::guitest

#include "model/Defaults.hpp"

namespace mcdda {

Material default_rock(const std::string& name)
{
    Material rock;
    rock.name = name;
    rock.young_modulus = 10e9;
    rock.poisson_ratio = 0.25;
    rock.density = 25.5e3 / standard_gravity;
    rock.law = "mohr-coulomb";
    rock.parameters = {{"cohesion", 1e6}, {"friction_angle", 35.0 * degree}, {"dilation_angle", 0.0}, {"tensile_strength", 0.0}};
    return rock;
}

JointMaterial default_joint(const std::string& name)
{
    JointMaterial joint;
    joint.name = name;
    joint.friction_angle = 30.0 * degree;
    return joint;
}

Model new_model(const std::string& rock_name, const std::string& joint_name)
{
    Model m;
    m.materials.push_back(default_rock(rock_name));
    m.joint_materials.push_back(default_joint(joint_name));
    m.default_joint_material = 0;
    m.gravity = {0.0, -standard_gravity};
    // Static load steps one pseudo-second apart, as the static examples count them ("t = 20 s"
    // is step 20), not 100 steps of 0.01 s that read like a dynamic run.
    m.analysis.steps = 20;
    m.analysis.time_step = 1.0;
    return m;
}

}  // namespace mcdda

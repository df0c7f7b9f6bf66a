#include "model/Defaults.hpp"

namespace mcdda {

Material default_rock(const std::string& name)
{
    Material rock;
    rock.name = name;
    rock.young_modulus = 10e9;
    rock.poisson_ratio = 0.25;
    rock.density = 25.5e3 / standard_gravity;
    rock.cohesion = 1e6;
    rock.friction_angle = 35.0 * degree;
    rock.dilation_angle = 0.0;
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
    return m;
}

}  // namespace mcdda

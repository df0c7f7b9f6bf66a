#include "model/StrengthReduction.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

Material reduced_strength(const Material& m, double factor) {
    if (!m.reduce) return m;
    Material r = m;
    r.cohesion = m.cohesion / factor;
    r.friction_angle = std::atan(std::tan(m.friction_angle) / factor);
    r.tensile_strength = m.tensile_strength / factor;
    r.dilation_angle = std::min(m.dilation_angle, r.friction_angle);
    return r;
}

JointMaterial reduced_strength(const JointMaterial& j, double factor) {
    if (!j.reduce) return j;
    JointMaterial r = j;
    r.cohesion = j.cohesion / factor;
    r.friction_angle = std::atan(std::tan(j.friction_angle) / factor);
    r.tensile_strength = j.tensile_strength / factor;
    return r;
}

void reduce_strength(Model& model, double factor) {
    for (Material& m : model.materials) m = reduced_strength(m, factor);
    for (JointMaterial& j : model.joint_materials) j = reduced_strength(j, factor);
}

}  // namespace mcdda

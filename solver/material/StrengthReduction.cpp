#include "material/StrengthReduction.hpp"

#include "material/MaterialLaws.hpp"

#include <cmath>

namespace mcdda {

double davis_factor(double friction_angle, double dilation_angle) {
    return std::cos(dilation_angle) * std::cos(friction_angle) /
           (1.0 - std::sin(dilation_angle) * std::sin(friction_angle));
}

Material reduced_strength(const Material& m, double factor, AnalysisSettings::NonAssociatedFlow flow) {
    const MaterialLaw* law = find_material_law(m.law);
    if (!m.reduce || !law || !law->reduced) return m;
    return law->reduced(m, factor, flow);
}

JointMaterial reduced_strength(const JointMaterial& j, double factor) {
    if (!j.reduce) return j;
    JointMaterial r = j;
    r.cohesion /= factor;
    r.friction_angle = std::atan(std::tan(j.friction_angle) / factor);
    r.tensile_strength /= factor;
    return r;
}

void reduce_strength(Model& model, double factor) {
    for (Material& m : model.materials) m = reduced_strength(m, factor, model.analysis.non_associated_flow);
    for (JointMaterial& j : model.joint_materials) j = reduced_strength(j, factor);
}

}  // namespace mcdda

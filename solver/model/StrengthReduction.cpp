#include "model/StrengthReduction.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

namespace {

/// c/F, atan(tan φ / F) and σt/F, the reduction block and joint materials share (unless the
/// material keeps its strength).
template <class Strength>
Strength divided(Strength s, double factor) {
    if (!s.reduce) return s;
    s.cohesion /= factor;
    s.friction_angle = std::atan(std::tan(s.friction_angle) / factor);
    s.tensile_strength /= factor;
    return s;
}

}  // namespace

double davis_factor(double friction_angle, double dilation_angle) {
    return std::cos(dilation_angle) * std::cos(friction_angle) /
           (1.0 - std::sin(dilation_angle) * std::sin(friction_angle));
}

Material reduced_strength(const Material& m, double factor, AnalysisSettings::NonAssociatedFlow flow) {
    if (!m.reduce) return m;
    Material r = divided(m, factor);
    r.dilation_angle = std::min(m.dilation_angle, r.friction_angle);  // ψ ≤ reduced φ
    if (flow == AnalysisSettings::NonAssociatedFlow::Davis && r.dilation_angle < r.friction_angle) {
        const double beta = davis_factor(r.friction_angle, r.dilation_angle);
        r.cohesion *= beta;
        r.friction_angle = std::atan(beta * std::tan(r.friction_angle));
        r.dilation_angle = r.friction_angle;
    }
    return r;
}

JointMaterial reduced_strength(const JointMaterial& j, double factor) { return divided(j, factor); }

void reduce_strength(Model& model, double factor) {
    for (Material& m : model.materials) m = reduced_strength(m, factor, model.analysis.non_associated_flow);
    for (JointMaterial& j : model.joint_materials) j = reduced_strength(j, factor);
}

}  // namespace mcdda

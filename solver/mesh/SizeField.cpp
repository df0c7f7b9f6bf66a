#include "mesh/SizeField.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

SizeField::SizeField(const MeshControls& controls, double global_size)
    : global_(global_size), grading_(controls.grading), local_(controls.local) {}

double SizeField::operator()(Point2 p) const {
    double h = global_;
    for (const LocalSize& l : local_) {
        const double d = distance_to_segment(p, l.from, l.to);
        h = std::min(h, l.size + grading_ * std::max(0.0, d - l.radius));
    }
    return h;
}

double resolved_global_size(const Model& model) {
    if (model.mesh.size > 0.0) return model.mesh.size;
    const auto box = model.bounds();
    const double diagonal = std::hypot(box[2] - box[0], box[3] - box[1]);
    return diagonal > 0.0 ? diagonal / 20.0 : 1.0;
}

}  // namespace mcdda

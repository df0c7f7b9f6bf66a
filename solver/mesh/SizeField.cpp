#include "mesh/SizeField.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

namespace {

/// Below this many features a point looks at all of them.
constexpr std::size_t binned_from = 32;

}  // namespace

SizeField::SizeField(const MeshControls& controls, double global_size)
    : global_(global_size), grading_(controls.grading), local_(controls.local) {
    if (local_.size() < binned_from || !(grading_ > 0.0)) {
        for (std::size_t i = 0; i < local_.size(); ++i) everywhere_.push_back(static_cast<int>(i));
        return;
    }
    // A feature makes the size finer than the global one within its reach: its radius plus the
    // distance over which the grading brings its size up to the global size.
    auto reach = [&](const LocalSize& l) { return l.radius + std::max(0.0, global_ - l.size) / grading_; };
    double mean = 0.0;
    for (const LocalSize& l : local_) mean += reach(l);
    cell_ = std::max(mean / static_cast<double>(local_.size()), 1e-12);
    for (std::size_t i = 0; i < local_.size(); ++i) {
        const LocalSize& l = local_[i];
        const double r = reach(l);
        const double x0 = std::min(l.from.x, l.to.x) - r, x1 = std::max(l.from.x, l.to.x) + r;
        const double y0 = std::min(l.from.y, l.to.y) - r, y1 = std::max(l.from.y, l.to.y) + r;
        // A feature reaching over very many cells (a long line) is looked at everywhere instead.
        if ((x1 - x0) * (y1 - y0) > 64.0 * cell_ * cell_) {
            everywhere_.push_back(static_cast<int>(i));
            continue;
        }
        for (double x = std::floor(x0 / cell_); x <= std::floor(x1 / cell_); x += 1.0)
            for (double y = std::floor(y0 / cell_); y <= std::floor(y1 / cell_); y += 1.0)
                cells_[key(x * cell_ + 0.5 * cell_, y * cell_ + 0.5 * cell_)].push_back(static_cast<int>(i));
    }
}

unsigned long long SizeField::key(double x, double y) const {
    // Unsigned: cell indices may be negative.
    const auto i = static_cast<long long>(std::floor(x / cell_)), j = static_cast<long long>(std::floor(y / cell_));
    return (static_cast<unsigned long long>(i) << 32) ^ (static_cast<unsigned long long>(j) & 0xffffffffULL);
}

double SizeField::operator()(Point2 p) const {
    double h = global_;
    auto consider = [&](int i) {
        const LocalSize& l = local_[i];
        const double d = distance_to_segment(p, l.from, l.to);
        h = std::min(h, l.size + grading_ * std::max(0.0, d - l.radius));
    };
    for (int i : everywhere_) consider(i);
    if (!cells_.empty()) {
        const auto it = cells_.find(key(p.x, p.y));
        if (it != cells_.end())
            for (int i : it->second) consider(i);
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

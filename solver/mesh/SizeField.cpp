#include "mesh/SizeField.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

namespace {

/// Below this many features a point looks at all of them.
constexpr std::size_t binned_from = 32;
/// Cells per side of the grid at most (a few features far apart).
constexpr long long max_cells_per_side = 4096;
/// Kept features a feature is compared with before it is kept too (see keep_undominated).
constexpr std::size_t dominance_candidates = 64;

/// Does feature `a` ask for a size no larger than `b` everywhere? Within δ, the largest distance
/// from b's segment to a's, d_a(p) ≤ d_b(p) + δ at every p, so a's size
/// s_a + g·max(0, d_a − r_a) is at most s_b + g·max(0, d_b − r_b) wherever
/// s_a + g·max(0, δ + r_b − r_a) ≤ s_b. A margin of 1e-9 keeps rounding on the safe side: then the
/// field is the same, bit for bit, without b.
bool dominates(const LocalSize& a, const LocalSize& b, double grading) {
    if (a.from.x == b.from.x && a.from.y == b.from.y && a.to.x == b.to.x && a.to.y == b.to.y && a.size == b.size &&
        a.radius == b.radius)
        return true;
    const double apart = std::max(distance_to_segment(b.from, a.from, a.to), distance_to_segment(b.to, a.from, a.to));
    return a.size + grading * std::max(0.0, apart + b.radius - a.radius) <= b.size * (1.0 - 1e-9);
}

/// The features that can make the field finer somewhere: none asking for the global size or
/// more, none another one overrules everywhere. Copies of one refinement (80,000 of them took a
/// minute to mesh, every point looking at all) become one. Each feature, smallest size first,
/// is compared with the first few kept, so this stays linear in their number.
std::vector<LocalSize> keep_undominated(const std::vector<LocalSize>& features, double global, double grading) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < features.size(); ++i)
        if (features[i].size < global) order.push_back(i);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return features[a].size < features[b].size; });
    std::vector<LocalSize> kept;
    for (std::size_t i : order) {
        const std::size_t compared = std::min(kept.size(), dominance_candidates);
        bool overruled = false;
        for (std::size_t k = 0; k < compared && !overruled; ++k) overruled = dominates(kept[k], features[i], grading);
        if (!overruled) kept.push_back(features[i]);
    }
    return kept;
}

}  // namespace

SizeField::SizeField(const MeshControls& controls, double global_size)
    : global_(global_size), grading_(controls.grading),
      local_(keep_undominated(controls.local, global_size, controls.grading)) {
    if (local_.size() < binned_from || !(grading_ > 0.0)) {
        for (std::size_t i = 0; i < local_.size(); ++i) everywhere_.push_back(static_cast<int>(i));
        return;
    }
    // The grid covers the features' boxes with about one cell per feature.
    double box[4] = {1e300, 1e300, -1e300, -1e300};
    for (const LocalSize& l : local_) {
        box[0] = std::min({box[0], l.from.x - l.radius, l.to.x - l.radius});
        box[1] = std::min({box[1], l.from.y - l.radius, l.to.y - l.radius});
        box[2] = std::max({box[2], l.from.x + l.radius, l.to.x + l.radius});
        box[3] = std::max({box[3], l.from.y + l.radius, l.to.y + l.radius});
    }
    const double width = box[2] - box[0], height = box[3] - box[1];
    const double extent = std::max(width, height);
    if (!std::isfinite(extent)) {
        for (std::size_t i = 0; i < local_.size(); ++i) everywhere_.push_back(static_cast<int>(i));
        return;
    }
    cell_ = std::max({std::sqrt(width * height / static_cast<double>(local_.size())),
                      extent / static_cast<double>(max_cells_per_side), 1e-12 * std::max(extent, 1.0)});
    x0_ = box[0];
    y0_ = box[1];
    nx_ = static_cast<long long>(width / cell_) + 1;
    ny_ = static_cast<long long>(height / cell_) + 1;
    cells_.resize(static_cast<std::size_t>(nx_ * ny_));
    smallest_ = global_;
    for (std::size_t i = 0; i < local_.size(); ++i) {
        const LocalSize& l = local_[i];
        const long long i0 = column(std::min(l.from.x, l.to.x) - l.radius), i1 = column(std::max(l.from.x, l.to.x) + l.radius);
        const long long j0 = row(std::min(l.from.y, l.to.y) - l.radius), j1 = row(std::max(l.from.y, l.to.y) + l.radius);
        // A feature over very many cells (a long line) is looked at everywhere instead.
        if ((i1 - i0 + 1) * (j1 - j0 + 1) > 64) {
            everywhere_.push_back(static_cast<int>(i));
            continue;
        }
        smallest_ = std::min(smallest_, l.size);
        for (long long x = i0; x <= i1; ++x)
            for (long long y = j0; y <= j1; ++y) cells_[static_cast<std::size_t>(y * nx_ + x)].push_back(static_cast<int>(i));
    }
}

long long SizeField::column(double x) const {
    return std::clamp(static_cast<long long>(std::floor((x - x0_) / cell_)), 0LL, nx_ - 1);
}

long long SizeField::row(double y) const {
    return std::clamp(static_cast<long long>(std::floor((y - y0_) / cell_)), 0LL, ny_ - 1);
}

double SizeField::operator()(Point2 p) const {
    double h = global_;
    auto consider = [&](int i) {
        const LocalSize& l = local_[i];
        const double d = distance_to_segment(p, l.from, l.to);
        h = std::min(h, l.size + grading_ * std::max(0.0, d - l.radius));
    };
    for (int i : everywhere_) consider(i);
    if (cells_.empty()) return h;
    // Rings of cells around the point's own (outside the grid: around the cell nearest to it).
    // A feature first met in ring r lies wholly outside rings 0 … r − 1, so at least (r − 1)
    // cells from the point's projection onto the grid, and the point is further still by its
    // distance to the grid: it cannot give less than smallest_ + grading · that distance.
    const double dx = std::max({0.0, x0_ - p.x, p.x - (x0_ + static_cast<double>(nx_) * cell_)});
    const double dy = std::max({0.0, y0_ - p.y, p.y - (y0_ + static_cast<double>(ny_) * cell_)});
    const double outside2 = dx * dx + dy * dy;
    const long long ci = column(p.x), cj = row(p.y);
    const long long last = std::max({ci, nx_ - 1 - ci, cj, ny_ - 1 - cj});
    auto scan = [&](long long x, long long y) {
        if (x < 0 || x >= nx_ || y < 0 || y >= ny_) return;
        for (int i : cells_[static_cast<std::size_t>(y * nx_ + x)]) consider(i);
    };
    for (long long r = 0; r <= last; ++r) {
        const double apart = static_cast<double>(std::max(0LL, r - 1)) * cell_;
        if (r > 0 && smallest_ + grading_ * std::sqrt(outside2 + apart * apart) >= h) break;
        if (r == 0) {
            scan(ci, cj);
            continue;
        }
        for (long long x = ci - r; x <= ci + r; ++x) {
            scan(x, cj - r);
            scan(x, cj + r);
        }
        for (long long y = cj - r + 1; y <= cj + r - 1; ++y) {
            scan(ci - r, y);
            scan(ci + r, y);
        }
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

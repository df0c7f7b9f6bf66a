#pragma once
/// \file SizeField.hpp
/// Target element edge length over the model plane: the global size, made finer near the local
/// refinement features of the mesh controls and growing linearly (the grading) away from them.

#include "model/Model.hpp"

#include <vector>

namespace mcdda {

class SizeField {
public:
    /// `global_size` is the resolved global size (m) when the controls leave it automatic.
    SizeField(const MeshControls& controls, double global_size);

    /// Target edge length at `p` (m).
    double operator()(Point2 p) const;

    double global_size() const { return global_; }
    /// The local refinement features the field looks at: those that make it finer somewhere and
    /// that no other one overrules everywhere (copies count once).
    std::size_t feature_count() const { return local_.size(); }

private:
    double global_;
    double grading_;
    std::vector<LocalSize> local_;
    /// Many features (the tips of thousands of cracks) are binned in a grid of square cells by
    /// where they are (their segment widened by their radius), and a point looks at the cells
    /// in rings around its own until no feature further out can make the size finer: with a
    /// gentle grading every feature reaches over the whole model, so binning by reach would make
    /// every point look at all of them (13,000 cracks: minutes of meshing). Few features, and
    /// features spanning many cells, are looked at everywhere (`everywhere_`).
    double cell_ = 0.0;
    double x0_ = 0.0, y0_ = 0.0;
    long long nx_ = 0, ny_ = 0;
    double smallest_ = 0.0;  ///< the smallest size among the binned features
    std::vector<std::vector<int>> cells_;
    std::vector<int> everywhere_;
    long long column(double x) const;  ///< the grid column of x, clamped to the grid
    long long row(double y) const;
};

/// The global size the mesher uses: the controls' size, or 1/20 of the model's box diagonal.
double resolved_global_size(const Model& model);

}  // namespace mcdda

#pragma once
/// \file SizeField.hpp
/// Target element edge length over the model plane: the global size, made finer near the local
/// refinement features of the mesh controls and growing linearly (the grading) away from them.

#include "model/Model.hpp"

#include <unordered_map>
#include <vector>

namespace mcdda {

class SizeField {
public:
    /// `global_size` is the resolved global size (m) when the controls leave it automatic.
    SizeField(const MeshControls& controls, double global_size);

    /// Target edge length at `p` (m).
    double operator()(Point2 p) const;

    double global_size() const { return global_; }

private:
    double global_;
    double grading_;
    std::vector<LocalSize> local_;
    /// Many features (the tips of thousands of cracks) are binned in square cells by the reach
    /// of their influence (where they make the size finer than the global one), so that a point
    /// looks only at the features of its cell. Few features are all looked at (`everywhere_`).
    double cell_ = 0.0;
    std::unordered_map<unsigned long long, std::vector<int>> cells_;
    std::vector<int> everywhere_;
    unsigned long long key(double x, double y) const;
};

/// The global size the mesher uses: the controls' size, or 1/20 of the model's box diagonal.
double resolved_global_size(const Model& model);

}  // namespace mcdda

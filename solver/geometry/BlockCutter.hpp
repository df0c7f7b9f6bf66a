#pragma once
/// \file BlockCutter.hpp
/// Cuts regions into blocks along joints, as DDA's block cutting does, with exact arithmetic
/// (CGAL 2-D arrangement of region boundaries and joint traces).

#include "geometry/Block.hpp"
#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <vector>

namespace mcdda {

/// Returns the blocks of `model` (joint sets must already be expanded). Reports as errors:
/// overlapping regions, explicit joints lying outside every region. Joint pieces that separate
/// nothing (dangling ends, traces inside one block) become the cracks of their block.
/// Expects region rings that passed check_region_rings.
std::vector<Block> cut_blocks(const Model& model, std::vector<Diagnostic>& diagnostics);

}  // namespace mcdda

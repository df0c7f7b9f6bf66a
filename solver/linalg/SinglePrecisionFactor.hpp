#pragma once
/// \file SinglePrecisionFactor.hpp
/// A copy in single precision of a Cholesky factor P A Pᵀ = L Lᵀ, for the solves that only
/// precondition: the conjugate-gradient iterations against a later matrix with a factor held
/// from an earlier one, and the directions of that factor's low-rank correction.
///
/// A triangular solve reads the whole factor once forward and once back and does two flops per
/// entry read, so it runs at the speed of memory: CHOLMOD's simplicial factor costs a double
/// and a row index, 12 bytes, per entry. Here the columns are grouped into supernodes (columns
/// with the same rows below their diagonal block: one row index per row of a group, not per
/// entry) and the values kept as floats, 4 bytes per entry and a fraction of a row index;
/// sums are formed in double. A preconditioner only has to be close to the matrix: its rounding
/// (a relative 6·10⁻⁸ per entry) is a perturbation far smaller than the drift of the matrix
/// from the factor held (the geometry and the contacts since), which the iterations correct
/// anyway, and every residual they check is formed in double. Solves whose answer is used as
/// it stands (a fresh factor's) stay with CHOLMOD's double-precision factor.

#include <vector>

struct cholmod_factor_struct;

namespace mcdda {

class SinglePrecisionFactor {
public:
    /// Copies a numeric LLᵀ factor (simplicial or supernodal, int indices).
    void assign(const cholmod_factor_struct& factor);
    void clear();
    bool empty() const { return groups_.empty(); }
    /// Groups of columns (supernodes) the copy holds.
    int groups() const { return static_cast<int>(groups_.size()); }

    /// X = A⁻¹ B with the copy, for `columns` right-hand sides at once (B and X column-major,
    /// of the factor's size; they may be the same). Each group of the factor is read once for
    /// all of them.
    void solve(const double* b, double* x, int columns = 1) const;

private:
    struct Group {
        int first;        ///< first column (in the factor's order)
        int width;        ///< columns
        int rows;         ///< rows below the diagonal block
        long long value;  ///< offset of the diagonal block (width², column-major), then the rows (row-major)
        long long row;    ///< offset of the rows' indices
    };
    std::vector<Group> groups_;
    std::vector<float> values_;
    std::vector<int> rows_;
    std::vector<int> permutation_;  ///< row k of P A Pᵀ is row permutation_[k] of A
    mutable std::vector<double> work_;

    void add_group(int first, int width, const int* below, int rows);
};

}  // namespace mcdda

#pragma once
/// \file LowRankCorrection.hpp
/// A held Cholesky factor of an earlier matrix K₀ made to fit a later matrix K = K₀ + ΔK whose
/// large changes are few, by the Sherman–Morrison–Woodbury formula (Golub & Van Loan, Matrix
/// Computations, 4th ed., 2013, §2.1.4):
///
///   (K₀ + U C Uᵀ)⁻¹ = K₀⁻¹ − Z (C⁻¹ + Uᵀ Z)⁻¹ Zᵀ,   Z = K₀⁻¹ U.
///
/// Between two steps of static DDA the matrix changes in two ways: the geometry drifts (every
/// entry, by about the displacement increment over an element's size, 10⁻⁵ a step) and a few
/// contacts open, close or start to slide (their springs, as stiff as the rock, appear or go:
/// rank 2 each, on the equations of three nodes). Conjugate gradients preconditioned by K₀'s
/// factor need up to one iteration per missed rank; corrected for the large changes, only the
/// drift is left to them. The large changes are found from the values themselves — entries that
/// moved by more than a share of their diagonal scale — so the correction knows nothing of
/// contacts: a bolt installed or a support's spring changed is caught alike.

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <functional>
#include <vector>

namespace mcdda {

class LowRankCorrection {
public:
    /// Solves K₀ X = B for a block of right-hand sides with the held factor.
    using HeldSolve = std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>;

    /// Builds the correction from the lower-triangle values of the current matrix and of the
    /// held one (same pattern, the diagonal first in each column). Returns false, and corrects
    /// nothing, when the large changes touch more than `max_equations` equations or need more
    /// than `max_rank` directions (then a factorisation is the cheaper answer).
    bool build(const Eigen::SparseMatrix<double>& current, const std::vector<double>& held, const HeldSolve& solve,
               int max_equations, int max_rank);

    /// Directions corrected (0: none); each cost one solve with the held factor to build.
    int rank() const { return static_cast<int>(z_.cols()); }

    /// Given the residual r and y = K₀⁻¹ r, makes y the corrected preconditioner's answer.
    void apply(const Eigen::VectorXd& r, Eigen::VectorXd& y) const;

    void clear() { z_.resize(0, 0); }

private:
    Eigen::MatrixXd z_;  ///< K₀⁻¹ U, one column per direction
    Eigen::PartialPivLU<Eigen::MatrixXd> capacitance_;  ///< C⁻¹ + Uᵀ Z
};

}  // namespace mcdda

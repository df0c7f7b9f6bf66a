#include "linalg/LowRankCorrection.hpp"

#include <algorithm>
#include <cmath>

namespace mcdda {

namespace {
/// An entry is a large change when it moved by more than this share of √(Kᵢᵢ Kⱼⱼ): a contact
/// spring is of the order of the rock's own diagonal, the geometry's drift a step 10⁻⁵ of it.
constexpr double large_change = 1e-2;
/// Directions of the changes' block kept: eigenvalues above this share of the largest (the
/// drift within the block is far below it; a spring is not).
constexpr double kept_eigenvalue = 1e-3;
}  // namespace

bool LowRankCorrection::build(const Eigen::SparseMatrix<double>& current, const std::vector<double>& held,
                              const HeldSolve& solve, int max_equations, int max_rank) {
    clear();
    const int n = static_cast<int>(current.rows());
    const auto* outer = current.outerIndexPtr();
    const auto* inner = current.innerIndexPtr();
    const double* value = current.valuePtr();
    auto diagonal = [&](int e) { return std::fabs(value[outer[e]]); };

    // The equations the large changes touch, in order. Squares compared (no square root per
    // stored entry); a NaN fails the comparison and counts as a large change.
    std::vector<int> at(n, -1);
    std::vector<int> equations;
    for (int j = 0; j < n; ++j)
        for (auto p = outer[j]; p < outer[j + 1]; ++p) {
            const int i = inner[p];
            const double change = value[p] - held[p];
            if (!(change * change <= large_change * large_change * (diagonal(i) * diagonal(j)))) {
                for (int e : {i, j})
                    if (at[e] < 0) {
                        at[e] = 0;
                        equations.push_back(e);
                    }
                if (static_cast<int>(equations.size()) > max_equations) return false;
            }
        }
    if (equations.empty()) return true;
    std::sort(equations.begin(), equations.end());
    const int m = static_cast<int>(equations.size());
    for (int k = 0; k < m; ++k) at[equations[k]] = k;

    // The changes among those equations (their whole block, drift included: it is exact there).
    Eigen::MatrixXd block = Eigen::MatrixXd::Zero(m, m);
    for (int kj = 0; kj < m; ++kj) {
        const int j = equations[kj];
        for (auto p = outer[j]; p < outer[j + 1]; ++p) {
            const int ki = at[inner[p]];
            if (ki < 0) continue;
            block(ki, kj) = block(kj, ki) = value[p] - held[p];
        }
    }
    // ΔK on the block = Q Λ Qᵀ; the directions that matter make U = E·Q, C = Λ.
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(block);
    if (eigen.info() != Eigen::Success) return false;
    const Eigen::VectorXd& lambda = eigen.eigenvalues();
    const double largest = lambda.cwiseAbs().maxCoeff();
    std::vector<int> kept;
    for (int k = 0; k < m; ++k)
        if (std::fabs(lambda[k]) > kept_eigenvalue * largest) kept.push_back(k);
    const int r = static_cast<int>(kept.size());
    if (r > max_rank) return false;
    if (r == 0) return true;

    Eigen::MatrixXd q(m, r);  // the kept directions on the block's equations
    for (int c = 0; c < r; ++c) q.col(c) = eigen.eigenvectors().col(kept[c]);
    Eigen::MatrixXd u = Eigen::MatrixXd::Zero(n, r);
    for (int k = 0; k < m; ++k) u.row(equations[k]) = q.row(k);
    z_ = solve(u);
    // Uᵀ Z from the m rows where U is not zero (the dense product cost n·r² per build).
    Eigen::MatrixXd z_rows(m, r);
    for (int k = 0; k < m; ++k) z_rows.row(k) = z_.row(equations[k]);
    Eigen::MatrixXd capacitance = q.transpose() * z_rows;
    for (int c = 0; c < r; ++c) capacitance(c, c) += 1.0 / lambda[kept[c]];
    capacitance_.compute(capacitance);
    return true;
}

void LowRankCorrection::apply(const Eigen::VectorXd& r, Eigen::VectorXd& y) const {
    if (z_.cols() == 0) return;
    y -= z_ * capacitance_.solve(z_.transpose() * r);
}

}  // namespace mcdda

// SinglePrecisionFactor: a float copy of CHOLMOD's factor, grouped into supernodes, solves as the
// double-precision factor does to single precision, from a simplicial and a supernodal factor.
#include "linalg/SinglePrecisionFactor.hpp"

#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <vector>

namespace mcdda {
namespace {

struct Decomposition : Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> {
    const cholmod_factor& factor() const { return *m_cholmodFactor; }
};

/// A square grid of m × m nodes, two unknowns each, coupled by its cells as a 2-D mesh's
/// stiffness is, with one corner's node held by springs: symmetric positive definite.
Eigen::SparseMatrix<double> grid_matrix(int m) {
    const int n = 2 * m * m;
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i + 1 < m; ++i)
        for (int j = 0; j + 1 < m; ++j) {
            const int corner = i * m + j;
            const int nodes[4] = {corner, corner + 1, corner + m, corner + m + 1};
            for (int a = 0; a < 8; ++a)
                for (int b = 0; b < 8; ++b) {
                    const int ea = 2 * nodes[a / 2] + a % 2, eb = 2 * nodes[b / 2] + b % 2;
                    // The 4-node Laplacian stencil per component, the components weakly coupled,
                    // the cells' stiffness varying across the grid (10× from one side to the other).
                    const double scale = 1.0 + 9.0 * i / m;
                    const double v = a == b ? 3.25 : (a % 2 == b % 2 ? -1.0 : 0.05);
                    if (ea >= eb) entries.emplace_back(ea, eb, scale * v);
                }
        }
    for (int e : {0, 1}) entries.emplace_back(e, e, 1e3);
    Eigen::SparseMatrix<double> lower(n, n);
    lower.setFromTriplets(entries.begin(), entries.end());
    return lower;
}

void expect_same_solution(int supernodal) {
    const Eigen::SparseMatrix<double> lower = grid_matrix(60);
    Decomposition llt;
    llt.cholmod().final_ll = 1;
    llt.cholmod().supernodal = supernodal;
    llt.compute(lower);
    ASSERT_EQ(llt.info(), Eigen::Success);
    ASSERT_EQ(llt.factor().is_super != 0, supernodal == CHOLMOD_SUPERNODAL);

    SinglePrecisionFactor single;
    EXPECT_TRUE(single.empty());
    single.assign(llt.factor());
    ASSERT_FALSE(single.empty());
    // Columns are grouped: two unknowns a node at least, the separators' nodes many more.
    EXPECT_LT(single.groups(), lower.rows() / 2);

    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(lower.rows(), -1.0, 2.0);
    const Eigen::VectorXd exact = llt.solve(b);
    Eigen::VectorXd x(b.size());
    single.solve(b.data(), x.data());
    const double error = (x - exact).norm() / exact.norm();
    EXPECT_LT(error, 1e-4);
    EXPECT_GT(error, 0.0);  // the copy is in single precision, not the factor itself
    // The residual against the matrix is small: a good preconditioner.
    const Eigen::VectorXd residual = b - lower.selfadjointView<Eigen::Lower>() * x;
    EXPECT_LT(residual.norm(), 1e-5 * b.norm());
    // In place, the same answer.
    Eigen::VectorXd y = b;
    single.solve(y.data(), y.data());
    EXPECT_EQ((y - x).norm(), 0.0);
    // Several right-hand sides at once: each as if solved alone.
    Eigen::MatrixXd columns(b.size(), 3);
    columns.col(0) = b;
    columns.col(1) = Eigen::VectorXd::Ones(b.size());
    columns.col(2) = -2.0 * b;
    Eigen::MatrixXd solved(b.size(), 3);
    single.solve(columns.data(), solved.data(), 3);
    for (int c = 0; c < 3; ++c) {
        Eigen::VectorXd alone(b.size());
        single.solve(columns.col(c).data(), alone.data());
        EXPECT_EQ((solved.col(c) - alone).norm(), 0.0) << "column " << c;
    }
    single.clear();
    EXPECT_TRUE(single.empty());
}

TEST(SinglePrecisionFactor, SolvesAsTheSimplicialFactorDoesToSinglePrecision) {
    expect_same_solution(CHOLMOD_SIMPLICIAL);
}

TEST(SinglePrecisionFactor, SolvesAsTheSupernodalFactorDoesToSinglePrecision) {
    expect_same_solution(CHOLMOD_SUPERNODAL);
}

}  // namespace
}  // namespace mcdda

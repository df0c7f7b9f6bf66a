// SymmetricSystem: assembly into the pattern, direct solves, and solves of a changed matrix with
// a held factor (conjugate gradients preconditioned by it).
#include "linalg/SymmetricSystem.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mcdda {
namespace {

/// A chain of n equations coupled by springs of stiffness k[i] between i and i+1, equation 0
/// also held by a spring to ground: symmetric positive definite.
struct Chain {
    int n;
    std::vector<CouplingGroup> groups;  // one per spring between neighbours
    explicit Chain(int n_) : n(n_) {
        for (int i = 0; i + 1 < n; ++i) {
            CouplingGroup g;
            g.size = 2;
            g.equation[0] = i;
            g.equation[1] = i + 1;
            groups.push_back(g);
        }
    }
    void assemble(SymmetricSystem& s, const std::vector<double>& k, double ground) const {
        s.clear_values();
        for (int i = 0; i + 1 < n; ++i) {
            const double block[4] = {k[i], -k[i], -k[i], k[i]};
            s.add(i, block);
        }
        s.add_diagonal(0, ground);
    }
    /// The pattern set, the chain assembled and factorised.
    void factorise_first(SymmetricSystem& s, const std::vector<double>& k, double ground) const {
        s.set_pattern(n, groups);
        assemble(s, k, ground);
        s.factorize();
    }
    Eigen::MatrixXd dense(const std::vector<double>& k, double ground) const {
        Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
        for (int i = 0; i + 1 < n; ++i) {
            a(i, i) += k[i];
            a(i + 1, i + 1) += k[i];
            a(i, i + 1) -= k[i];
            a(i + 1, i) -= k[i];
        }
        a(0, 0) += ground;
        return a;
    }
};

TEST(SymmetricSystem, UnsymmetricBlocksAreSolvedByLu) {
    // Groups of three equations in shuffled order (so that a block's (a, b) entry lands above
    // the diagonal as often as below), unsymmetric blocks, against a dense LU of the same matrix.
    const int n = 40;
    std::vector<CouplingGroup> groups;
    for (int i = 0; i + 2 < n; i += 2) {
        CouplingGroup g;
        g.size = 3;
        g.equation[0] = i + 2;
        g.equation[1] = i;
        g.equation[2] = i + 1;
        groups.push_back(g);
    }
    SymmetricSystem s;
    s.set_pattern(n, groups);
    s.set_unsymmetric(true);
    s.clear_values();
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t gi = 0; gi < groups.size(); ++gi) {
        Eigen::Matrix3d block;
        block << 4.0, -1.0 + 0.3 * gi, 0.5, -1.2, 5.0, -0.7 * gi, 0.25, 2.0, 6.0;
        s.add(static_cast<int>(gi), block.data());
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) dense(groups[gi].equation[a], groups[gi].equation[b]) += block(a, b);
    }
    for (int e = 0; e < n; ++e) {
        s.add_diagonal(e, 1.0);
        dense(e, e) += 1.0;
    }
    ASSERT_GT((dense - dense.transpose()).norm(), 1.0);  // really unsymmetric
    s.factorize();
    Eigen::VectorXd rhs(n);
    for (int i = 0; i < n; ++i) rhs[i] = std::sin(1.0 + i);
    const Eigen::VectorXd x = s.solve(rhs);
    const Eigen::VectorXd expected = dense.fullPivLu().solve(rhs);
    EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
    // The same system symmetric again: Cholesky of the lower part.
    s.set_unsymmetric(false);
    const Chain chain(n);
    std::vector<double> k(n - 1, 2.0);
    chain.factorise_first(s, k, 1.0);
    const Eigen::VectorXd y = s.solve(rhs);
    EXPECT_LT((chain.dense(k, 1.0) * y - rhs).norm(), 1e-10 * rhs.norm());
}

TEST(SymmetricSystem, SolvesTheAssembledMatrixDirectly) {
    const Chain chain(50);
    SymmetricSystem s;
    std::vector<double> k(chain.n - 1);
    for (int i = 0; i < chain.n - 1; ++i) k[i] = 1.0 + 0.1 * i;
    chain.factorise_first(s, k, 2.0);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(chain.n, -1.0, 3.0);
    const Eigen::VectorXd x = s.solve(b);
    EXPECT_LT((chain.dense(k, 2.0) * x - b).norm(), 1e-10 * b.norm());
    EXPECT_EQ(s.factorizations(), 1);
    EXPECT_EQ(s.symbolic_analyses(), 1);
}

// A square grid of m × m nodes, two unknowns each, coupled by its cells (a 2-D mesh's pattern):
// on a mesh this large nested dissection gives a smaller factor than minimum degree (3.15M
// entries and 5.0e8 flops against 3.21M and 6.1e8 here), so the analysis, trying both, keeps
// METIS's ordering. (On grids of 60 × 60 nodes
// AMD still wins.)
TEST(SymmetricSystem, ALargeTwoDimensionalMeshIsOrderedByNestedDissection) {
    const int m = 150, n = 2 * m * m;
    std::vector<CouplingGroup> cells;
    for (int i = 0; i + 1 < m; ++i)
        for (int j = 0; j + 1 < m; ++j) {
            CouplingGroup g;
            g.size = 8;
            const int corner = i * m + j;
            const int nodes[4] = {corner, corner + 1, corner + m, corner + m + 1};
            for (int a = 0; a < 4; ++a)
                for (int c = 0; c < 2; ++c) g.equation[2 * a + c] = 2 * nodes[a] + c;
            cells.push_back(g);
        }
    SymmetricSystem s;
    EXPECT_STREQ(s.ordering(), "");
    s.set_pattern(n, cells);
    s.clear_values();
    // Each cell: the 4-node Laplacian stencil for each component (−1 to the other nodes), the
    // components coupled weakly, a diagonal that keeps the block positive definite.
    double block[64];
    for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) block[8 * a + b] = a == b ? 3.5 : (a % 2 == b % 2 ? -1.0 : 0.1);
    for (int g = 0; g < static_cast<int>(cells.size()); ++g) s.add(g, block);
    for (int e = 0; e < n; ++e) s.add_diagonal(e, 1.0);
    s.factorize();
    EXPECT_STREQ(s.ordering(), "METIS");
    EXPECT_GT(s.factorization_flops(), 0.0);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
    const Eigen::VectorXd x = s.solve(b);
    const Eigen::SparseMatrix<double> lower = s.matrix();
    const Eigen::VectorXd residual = b - lower.selfadjointView<Eigen::Lower>() * x;
    EXPECT_LT(residual.norm(), 1e-9 * b.norm());
}

TEST(SymmetricSystem, AHeldFactorSolvesASlightlyChangedMatrixToTheSameAccuracy) {
    const Chain chain(200);
    SymmetricSystem s;
    std::vector<double> k(chain.n - 1, 1.0);
    chain.factorise_first(s, k, 1.0);
    // Stiffen a few springs by 30 % (a moved geometry, a few contacts): the held factor stays
    // and the solve iterates against the new matrix.
    for (int i : {3, 70, 150}) k[i] *= 1.3;
    chain.assemble(s, k, 1.0);
    s.factorize(/*may_reuse=*/true);
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(chain.n);
    const Eigen::VectorXd x = s.solve(b);
    EXPECT_EQ(s.factorizations(), 1);
    EXPECT_EQ(s.reused_factors(), 1);
    EXPECT_GT(s.refinement_iterations(), 0);
    const Eigen::VectorXd exact = chain.dense(k, 1.0).ldlt().solve(b);
    EXPECT_LT((x - exact).norm(), 1e-8 * exact.norm());
    // Without may_reuse the matrix is factorised.
    s.factorize();
    EXPECT_EQ(s.factorizations(), 2);
    EXPECT_LT((s.solve(b) - exact).norm(), 1e-10 * exact.norm());
}

TEST(SymmetricSystem, TheMatrixOfTheHeldFactorIsSolvedDirectlyHoweverOftenItComesBack) {
    // The elastic matrix assembled again after another matrix (a tangent that could not be
    // factorised, a changed one solved with the held factor): its own factor solves it, with no
    // iterations and, however many solves follow, no factorisation (iterating, as with any
    // held factor, charged each solve to the factorisation's budget until it was spent).
    const Chain chain(200);
    SymmetricSystem s;
    std::vector<double> k(chain.n - 1, 1.0);
    chain.factorise_first(s, k, 1.0);
    std::vector<double> other = k;
    for (int i : {3, 70, 150}) other[i] *= 1.3;
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(chain.n, 1.0, 2.0);
    const Eigen::VectorXd exact = chain.dense(k, 1.0).ldlt().solve(b);
    chain.assemble(s, other, 1.0);
    s.factorize(true);  // held: the solve iterates
    s.solve(b);
    const int iterations = s.refinement_iterations();
    EXPECT_GT(iterations, 0);
    chain.assemble(s, k, 1.0);
    s.factorize(true);
    for (int repeat = 0; repeat < 20; ++repeat) EXPECT_LT((s.solve(b) - exact).norm(), 1e-12 * exact.norm());
    EXPECT_EQ(s.refinement_iterations(), iterations);
    EXPECT_EQ(s.factorizations(), 1);
    // A matrix that differs in one entry's last bit is not taken for it.
    k[100] = std::nextafter(k[100], 2.0);
    chain.assemble(s, k, 1.0);
    const int before = s.reused_factors() + s.factorizations();
    s.factorize(true);  // held (iterating) or factorised, by the budget: not solved as the old matrix
    EXPECT_EQ(s.reused_factors() + s.factorizations(), before + 1);
}

TEST(SymmetricSystem, AnInexactSolveWithAHeldFactorStopsAtTheToleranceAsked) {
    // An inexact Newton correction: conjugate gradients stop once the residual is within the
    // tolerance asked, in fewer iterations than an exact solve takes.
    const Chain chain(300);
    std::vector<double> k(chain.n - 1, 1.0);
    std::vector<double> changed = k;
    // Softened here and there, each by its own factor (points starting to yield).
    for (int i = 0; i < chain.n - 1; i += 12) changed[i] *= 0.01 + 0.2 * (1.0 + std::sin(1.3 * i));
    Eigen::VectorXd b(chain.n);
    for (int i = 0; i < chain.n; ++i) b[i] = std::sin(0.37 * i * i + 1.0);  // loads at every node
    const Eigen::SparseMatrix<double> full = chain.dense(changed, 1.0).sparseView();
    int iterations[2] = {0, 0};
    for (int exact = 0; exact < 2; ++exact) {
        SymmetricSystem s;
        chain.factorise_first(s, k, 1.0);
        chain.assemble(s, changed, 1.0);
        s.factorize(true);
        const double tolerance = exact ? SymmetricSystem::exact : 1e-2;
        const Eigen::VectorXd x = s.solve(b, tolerance);
        EXPECT_EQ(s.factorizations(), 1);  // solved with the held factor
        EXPECT_LE((full * x - b).norm(), tolerance * b.norm());
        if (!exact) EXPECT_GT((full * x - b).norm(), SymmetricSystem::exact * b.norm());  // it stopped early
        iterations[exact] = s.refinement_iterations();
    }
    EXPECT_GT(iterations[0], 0);
    EXPECT_LT(iterations[0], iterations[1]);
}

TEST(SymmetricSystem, AMatrixSolvedAgainAfterManyIterationsIsFactorised) {
    // A matrix far from the held one (springs alternately 10 and 0.2 times as stiff): its first solve
    // iterates; solving it again factorises it instead of iterating again.
    const Chain chain(400);
    SymmetricSystem s;
    std::vector<double> k(chain.n - 1, 1.0);
    chain.factorise_first(s, k, 1.0);
    for (int i = 0; i < chain.n - 1; ++i) k[i] = i % 2 ? 10.0 : 0.2;
    chain.assemble(s, k, 1.0);
    s.factorize(true);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(chain.n, 1.0, 2.0);
    const Eigen::VectorXd exact = chain.dense(k, 1.0).ldlt().solve(b);
    for (int repeat = 0; repeat < 3; ++repeat) EXPECT_LT((s.solve(b) - exact).norm(), 1e-8 * exact.norm());
    EXPECT_GT(s.refinement_iterations(), 2);  // the first solve iterated
    EXPECT_EQ(s.factorizations(), 2);
}

TEST(SymmetricSystem, AfterAHeldFactorThatDidNotFitTheNextMatricesAreFactorisedAtOnce) {
    // A factor of a matrix far from the current one (springs up to a hundred times stiffer or
    // softer, as after an open–close round that changed hundreds of contacts) spends its 40
    // iterations in vain. The next 3 matrices are then factorised at once, after a second misfit
    // in a row the next 15; then a factor is held again.
    const Chain chain(400);
    SymmetricSystem s;
    std::vector<double> k(chain.n - 1, 1.0);
    chain.factorise_first(s, k, 1.0);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(chain.n, 1.0, 2.0);
    int matrix = 0;
    enum class Way { Factorised, Held, Misfit };
    const auto solve = [&](bool far) {
        ++matrix;
        for (int i = 0; i < chain.n - 1; ++i)
            k[i] = far ? std::pow(10.0, 2.0 * std::sin(1.7 * i + matrix)) : k[i] * (1.0 + 1e-3 * std::sin(0.3 * i));
        chain.assemble(s, k, 1.0);
        const int factorizations = s.factorizations(), held = s.reused_factors();
        s.factorize(true);
        const Eigen::VectorXd x = s.solve(b);
        const Eigen::VectorXd exact = chain.dense(k, 1.0).ldlt().solve(b);
        EXPECT_LT((x - exact).norm(), 1e-6 * exact.norm()) << "matrix " << matrix;
        if (s.reused_factors() == held) return Way::Factorised;
        return s.factorizations() == factorizations ? Way::Held : Way::Misfit;
    };
    EXPECT_EQ(solve(true), Way::Misfit);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(solve(false), Way::Factorised) << "matrix " << matrix;
    EXPECT_EQ(solve(true), Way::Misfit);
    for (int i = 0; i < 15; ++i) EXPECT_EQ(solve(false), Way::Factorised) << "matrix " << matrix;
    EXPECT_EQ(solve(false), Way::Held);
}

/// A square grid of w × w equations, each coupled by springs to its right and upper neighbours,
/// the bottom row held to ground: a two-dimensional pattern whose factorisation costs many solves.
struct Grid {
    int w, n;
    std::vector<CouplingGroup> groups;  // one per spring
    explicit Grid(int w_) : w(w_), n(w_ * w_) {
        for (int y = 0; y < w; ++y)
            for (int x = 0; x < w; ++x) {
                if (x + 1 < w) groups.push_back(pair(y * w + x, y * w + x + 1));
                if (y + 1 < w) groups.push_back(pair(y * w + x, (y + 1) * w + x));
            }
    }
    static CouplingGroup pair(int i, int j) {
        CouplingGroup g;
        g.size = 2;
        g.equation[0] = i;
        g.equation[1] = j;
        return g;
    }
    void assemble(SymmetricSystem& s, const std::vector<double>& k) const {
        s.clear_values();
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const double block[4] = {k[g], -k[g], -k[g], k[g]};
            s.add(static_cast<int>(g), block);
        }
        for (int x = 0; x < w; ++x) s.add_diagonal(x, 1.0);
    }
};

TEST(SymmetricSystem, AHeldFactorIsCorrectedForAFewLargeChanges) {
    // Between two steps of static DDA a few contacts change state (their springs, as stiff as the
    // rock, appear or go) while the geometry drifts a little everywhere. The held factor is
    // corrected for the few large changes (Sherman–Morrison–Woodbury), so that conjugate
    // gradients are left with the drift alone: one or two iterations, where the factor alone
    // needs about one per changed direction.
    const Grid grid(100);
    std::vector<double> k(grid.groups.size(), 1.0);
    SymmetricSystem s;
    s.set_pattern(grid.n, grid.groups);
    grid.assemble(s, k);
    s.factorize();
    // Five springs spread over the grid made 40 times stiffer, two others 1,000 times softer
    // (contacts that closed and opened), every spring drifting by up to 10⁻⁷.
    for (std::size_t g = 0; g < k.size(); ++g) k[g] *= 1.0 + 1e-7 * std::sin(0.7 * static_cast<double>(g));
    for (int g : {100, 5900, 10200, 15700, 19000}) k[g] *= 40.0;
    for (int g : {6300, 17800}) k[g] *= 1e-3;
    grid.assemble(s, k);
    s.factorize(/*may_reuse=*/true);
    Eigen::VectorXd b(grid.n);
    for (int i = 0; i < grid.n; ++i) b[i] = std::sin(0.37 * i + 1.0);
    const Eigen::VectorXd x = s.solve(b);
    EXPECT_EQ(s.factorizations(), 1);  // solved with the held factor
    EXPECT_LE(s.refinement_iterations(), 2);
    const Eigen::SparseMatrix<double> lower = s.matrix();
    EXPECT_LT((b - lower.selfadjointView<Eigen::Lower>() * x).norm(), 1e-10 * b.norm());
    // The same matrix factorised gives the same solution.
    s.factorize();
    EXPECT_LT((s.solve(b) - x).norm(), 1e-8 * x.norm());
}

TEST(SymmetricSystem, GroupsWithinThePatternReplaceTheOldOnesAndOthersLeaveThemAsTheyWere) {
    // A chain whose last spring is first left out of the pattern, then reserved (pattern_only):
    // the springs as groups after the first, as contacts are after the elements.
    const Chain chain(6);
    SymmetricSystem s;
    const std::vector<CouplingGroup> first(chain.groups.begin(), chain.groups.begin() + 1);
    const std::vector<CouplingGroup> middle(chain.groups.begin() + 1, chain.groups.end() - 1);
    const std::vector<CouplingGroup> all_but_first(chain.groups.begin() + 1, chain.groups.end());
    std::vector<CouplingGroup> initial = first;
    initial.insert(initial.end(), middle.begin(), middle.end());
    s.set_pattern(chain.n, initial);
    // The last spring couples equations 4 and 5, which the pattern does not: refused, and the
    // groups stay as they were (the first and the middle ones).
    EXPECT_FALSE(s.set_groups_if_in_pattern(all_but_first, 1));
    EXPECT_EQ(s.group_count(), 1 + static_cast<int>(middle.size()));
    // Within the pattern: the middle groups in reverse order replace the old ones.
    std::vector<CouplingGroup> reversed(middle.rbegin(), middle.rend());
    ASSERT_TRUE(s.set_groups_if_in_pattern(reversed, 1));
    EXPECT_EQ(s.group_count(), 1 + static_cast<int>(reversed.size()));
    // Assembled through the new groups, the matrix is the chain's without its last spring.
    std::vector<double> k = {1.0, 2.0, 3.0, 4.0, 0.0};
    s.clear_values();
    const double b0[4] = {k[0], -k[0], -k[0], k[0]};
    s.add(0, b0);
    for (std::size_t i = 0; i < reversed.size(); ++i) {
        const double ki = k[reversed[i].equation[0]];  // spring i joins equations i and i + 1
        const double b[4] = {ki, -ki, -ki, ki};
        s.add(1 + static_cast<int>(i), b);
    }
    s.add_diagonal(0, 1.0);
    s.add_diagonal(5, 1.0);  // equation 5 held on its own
    s.factorize();
    Eigen::MatrixXd dense = chain.dense(k, 1.0);
    dense(5, 5) += 1.0;
    const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(chain.n, 1.0, 2.0);
    EXPECT_LT((dense * s.solve(rhs) - rhs).norm(), 1e-12 * rhs.norm());
    // With the last spring reserved in the pattern it is accepted.
    s.set_pattern(chain.n, first, all_but_first);
    EXPECT_TRUE(s.set_groups_if_in_pattern(all_but_first, 1));
    EXPECT_EQ(s.group_count(), chain.n - 1);
}

TEST(SymmetricSystem, ASingularMatrixIsReportedAlsoWhenAFactorIsHeld) {
    const Chain chain(30);
    SymmetricSystem s;
    std::vector<double> k(chain.n - 1, 1.0);
    chain.factorise_first(s, k, 1.0);
    // The ground spring removed: the chain is free to move (a mechanism).
    chain.assemble(s, k, 0.0);
    s.factorize(true);
    EXPECT_THROW(s.solve(Eigen::VectorXd::Ones(chain.n)), SingularSystem);
}

}  // namespace
}  // namespace mcdda

// Anderson acceleration (linalg/AndersonMixing.hpp) of a slowly contracting fixed-point
// iteration x ← x + (b − A x): what the elastic (initial-stress) iteration of non-associated
// plasticity looks like once much of a model yields.

#include "linalg/AndersonMixing.hpp"

#include <gtest/gtest.h>

namespace {

/// Iterations until |b − A x| < 1e-10 |b| (cap: 2000), plain or mixed.
int iterations_to_converge(bool mixed) {
    const int n = 8;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) a(i, i) = 0.02 + 0.9 * i / (n - 1);  // contraction 0.98 in the slowest mode
    for (int i = 0; i + 1 < n; ++i) a(i, i + 1) = a(i + 1, i) = 0.01;
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    mcdda::AndersonMixing anderson(5);
    for (int k = 0; k < 2000; ++k) {
        const Eigen::VectorXd f = b - a * x;
        if (f.norm() < 1e-10 * b.norm()) return k;
        x += mixed ? anderson.next(x, f) : f;
    }
    return 2000;
}

}  // namespace

TEST(AndersonMixing, ConvergesWhereThePlainIterationCrawls) {
    const int plain = iterations_to_converge(false), mixed = iterations_to_converge(true);
    std::cout << "plain " << plain << " iterations, Anderson (depth 5) " << mixed << "\n";
    EXPECT_GT(plain, 500);
    EXPECT_LT(mixed, 60);
}

TEST(AndersonMixing, TheFirstCorrectionIsThePlainOneAndResetForgets) {
    mcdda::AndersonMixing anderson(3);
    const Eigen::VectorXd x = Eigen::VectorXd::Zero(2), f = Eigen::VectorXd::Ones(2);
    EXPECT_TRUE(anderson.next(x, f).isApprox(f));
    anderson.next(x + f, 0.5 * f);
    anderson.reset();
    EXPECT_TRUE(anderson.next(x, f).isApprox(f));  // no history after a reset
}

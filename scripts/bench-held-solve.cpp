// Times the single-precision copy's solves (solver/linalg/SinglePrecisionFactor.cpp) on a
// two-dimensional grid of two-unknown nodes coupled to their eight neighbours (31,250 equations,
// about the default example's), factorised by CHOLMOD with the solver's settings. Prints the
// milliseconds per solve and a checksum of the solutions (equal checksums: the same answers to
// the last bit). Built and run by scripts/bench-held-solve.sh.
#include "linalg/SinglePrecisionFactor.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {
struct Decomposition : Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> {
    const cholmod_factor& factor() const { return *m_cholmodFactor; }
};
}  // namespace

int main(int argc, char** argv) {
    const double supernodal_switch = argc > 1 ? std::atof(argv[1]) : 300.0;  // the solver's (simplicial here)
    const int nx = 125, ny = 125, n = 2 * nx * ny;
    auto unknown = [&](int i, int j, int d) { return 2 * (i * ny + j) + d; };
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            for (int di = -1; di <= 1; ++di)
                for (int dj = -1; dj <= 1; ++dj) {
                    const int a = i + di, b = j + dj;
                    if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
                    for (int p = 0; p < 2; ++p)
                        for (int q = 0; q < 2; ++q) {
                            const int r = unknown(i, j, p), c = unknown(a, b, q);
                            const double v = r == c ? 20.0 + 0.001 * i : (p == q ? -1.0 - 0.1 * ((i + j) % 3) : 0.3);
                            if (r >= c) entries.emplace_back(r, c, v);
                        }
                }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(entries.begin(), entries.end());
    Decomposition llt;
    cholmod_common& c = llt.cholmod();
    c.final_ll = 1;
    c.supernodal_switch = supernodal_switch;
    c.nmethods = 2;
    c.method[0].ordering = CHOLMOD_AMD;
    c.method[1].ordering = CHOLMOD_METIS;
    llt.compute(a);
    mcdda::SinglePrecisionFactor single;
    single.assign(llt.factor());
    std::vector<double> b(n), x(n);
    for (int i = 0; i < n; ++i) b[i] = std::sin(0.1 * i);
    const int solves = 1000;
    double checksum = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < solves; ++k) {
        single.solve(b.data(), x.data(), 1);
        checksum += x[k];
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%d equations, %.3g factor entries, %s: %.3f ms per solve, checksum %.17g\n", n, c.lnz,
                llt.factor().is_super ? "supernodal" : "simplicial", 1e3 * seconds / solves, checksum);
}

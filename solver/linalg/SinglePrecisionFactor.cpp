#include "linalg/SinglePrecisionFactor.hpp"

#include <cholmod.h>

#include <stdexcept>

namespace mcdda {

void SinglePrecisionFactor::clear() {
    groups_.clear();
    values_.clear();
    rows_.clear();
    permutation_.clear();
}

void SinglePrecisionFactor::add_group(int first, int width, const int* below, int rows) {
    Group g;
    g.first = first;
    g.width = width;
    g.rows = rows;
    g.value = static_cast<long long>(values_.size());
    g.row = static_cast<long long>(rows_.size());
    values_.resize(values_.size() + static_cast<std::size_t>(width) * (width + rows), 0.0f);
    rows_.insert(rows_.end(), below, below + rows);
    groups_.push_back(g);
}

void SinglePrecisionFactor::assign(const cholmod_factor& L) {
    clear();
    if (!L.is_ll || L.itype != CHOLMOD_INT || L.xtype != CHOLMOD_REAL || L.dtype != CHOLMOD_DOUBLE)
        throw std::logic_error("SinglePrecisionFactor: a real LLᵀ factor with int indices expected");
    const int n = static_cast<int>(L.n);
    const int* perm = static_cast<const int*>(L.Perm);
    permutation_.assign(perm, perm + n);
    const double* x = static_cast<const double*>(L.x);

    if (L.is_super) {
        const int* super = static_cast<const int*>(L.super);
        const int* pi = static_cast<const int*>(L.pi);
        const int* px = static_cast<const int*>(L.px);
        const int* s = static_cast<const int*>(L.s);
        for (std::size_t k = 0; k < L.nsuper; ++k) {
            const int first = super[k], width = super[k + 1] - super[k];
            const int height = pi[k + 1] - pi[k];  // rows of the supernode, its diagonal block first
            add_group(first, width, s + pi[k] + width, height - width);
            const Group& g = groups_.back();
            float* block = values_.data() + g.value;
            float* below = block + static_cast<std::size_t>(width) * width;
            const double* column = x + px[k];  // height × width, column-major
            for (int j = 0; j < width; ++j)
                for (int i = j; i < height; ++i) {
                    const double v = column[i + static_cast<std::size_t>(j) * height];
                    if (i < width)
                        block[i + j * width] = static_cast<float>(v);
                    else
                        below[static_cast<std::size_t>(i - width) * width + j] = static_cast<float>(v);
                }
        }
        return;
    }

    // Simplicial: column j + 1 joins column j's group when its rows are column j's below the
    // diagonal (j + 1 is then the first of them, and the counts differ by one), the fundamental
    // supernodes of the factor (row indices are kept sorted, the diagonal first).
    const int* p = static_cast<const int*>(L.p);
    const int* i = static_cast<const int*>(L.i);
    const int* nz = static_cast<const int*>(L.nz);
    for (int first = 0; first < n;) {
        int width = 1;
        while (first + width < n) {
            const int j = first + width - 1;
            if (nz[j] < 2 || i[p[j] + 1] != j + 1 || nz[j + 1] != nz[j] - 1) break;
            ++width;
        }
        const int last = first + width - 1;
        const int rows = nz[last] - 1;
        add_group(first, width, i + p[last] + 1, rows);
        const Group& g = groups_.back();
        float* block = values_.data() + g.value;
        float* below = block + static_cast<std::size_t>(width) * width;
        for (int j = 0; j < width; ++j) {
            const int c = first + j;
            // Column c holds rows c … last of the diagonal block, then the group's rows.
            for (int k = 0; k < nz[c]; ++k) {
                const double v = x[p[c] + k];
                const int r = j + k;  // position within the group's rows (block first)
                if (r < width)
                    block[r + j * width] = static_cast<float>(v);
                else
                    below[static_cast<std::size_t>(r - width) * width + j] = static_cast<float>(v);
            }
        }
        first += width;
    }
}

namespace {

/// One group's part of the forward solve L y = b: its diagonal block, then its rows below. The
/// group's unknowns are held in registers (W columns, a constant: the loops unrolled), so the
/// rows' sums do not wait on stores that might alias them.
template <int W>
void forward(int w, const float* block, const float* below, const int* row, int rows, double* yg, double* y) {
    constexpr int capacity = W > 0 ? W : 1;
    const double* v = yg;
    double registers[capacity];
    if constexpr (W == 0) {  // any width: the general loops
        for (int j = 0; j < w; ++j) {
            const double yj = (yg[j] /= block[j + j * w]);
            for (int r = j + 1; r < w; ++r) yg[r] -= block[r + j * w] * yj;
        }
    } else {
        w = W;
        for (int j = 0; j < W; ++j) registers[j] = yg[j];
        for (int j = 0; j < W; ++j) {
            registers[j] /= block[j + j * W];
            for (int r = j + 1; r < W; ++r) registers[r] -= block[r + j * W] * registers[j];
        }
        for (int j = 0; j < W; ++j) yg[j] = registers[j];
        v = registers;
    }
    // The rows' sums four at a time: each row's sum is one chain of dependent additions, which
    // alone would wait on the adder's latency at every term; four rows' chains overlap. Each
    // row's terms are still added in the same order (the same rounding as one row at a time).
    int r = 0;
    for (; r + 4 <= rows; r += 4, below += 4 * w) {
        const float *b0 = below, *b1 = below + w, *b2 = below + 2 * w, *b3 = below + 3 * w;
        double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
        for (int j = 0; j < w; ++j) {
            const double vj = v[j];
            s0 += b0[j] * vj;
            s1 += b1[j] * vj;
            s2 += b2[j] * vj;
            s3 += b3[j] * vj;
        }
        y[row[r]] -= s0;
        y[row[r + 1]] -= s1;
        y[row[r + 2]] -= s2;
        y[row[r + 3]] -= s3;
    }
    for (; r < rows; ++r, below += w) {
        double sum = 0.0;
        for (int j = 0; j < w; ++j) sum += below[j] * v[j];
        y[row[r]] -= sum;
    }
}

/// One group's part of the back solve Lᵀ x = y: its rows below (already solved), then its
/// diagonal block.
template <int W>
void back(int w, const float* block, const float* below, const int* row, int rows, double* yg, double* y) {
    constexpr int capacity = W > 0 ? W : 1;
    if constexpr (W == 0) {
        // Four rows per pass over the group's unknowns (each unknown takes their terms in the
        // rows' order, as one row at a time would).
        int r = 0;
        for (; r + 4 <= rows; r += 4, below += 4 * w) {
            const float *b0 = below, *b1 = below + w, *b2 = below + 2 * w, *b3 = below + 3 * w;
            const double y0 = y[row[r]], y1 = y[row[r + 1]], y2 = y[row[r + 2]], y3 = y[row[r + 3]];
            for (int j = 0; j < w; ++j) {
                double v = yg[j];
                v -= b0[j] * y0;
                v -= b1[j] * y1;
                v -= b2[j] * y2;
                v -= b3[j] * y3;
                yg[j] = v;
            }
        }
        for (; r < rows; ++r, below += w) {
            const double yr = y[row[r]];
            for (int j = 0; j < w; ++j) yg[j] -= below[j] * yr;
        }
        for (int j = w - 1; j >= 0; --j) {
            double v = yg[j];
            for (int r = j + 1; r < w; ++r) v -= block[r + j * w] * yg[r];
            yg[j] = v / block[j + j * w];
        }
    } else {
        double v[capacity];
        for (int j = 0; j < W; ++j) v[j] = yg[j];
        for (int r = 0; r < rows; ++r, below += W) {
            const double yr = y[row[r]];
            for (int j = 0; j < W; ++j) v[j] -= below[j] * yr;
        }
        for (int j = W - 1; j >= 0; --j) {
            for (int r = j + 1; r < W; ++r) v[j] -= block[r + j * W] * v[r];
            v[j] /= block[j + j * W];
        }
        for (int j = 0; j < W; ++j) yg[j] = v[j];
    }
}

using Kernel = void (*)(int, const float*, const float*, const int*, int, double*, double*);
/// The kernels by width: constant-length loops for the common widths (a node's two unknowns, a
/// few nodes), the general loops for the rest.
constexpr Kernel forward_kernels[] = {forward<0>, forward<1>, forward<2>, forward<3>, forward<4>,
                                      forward<5>, forward<6>, forward<7>, forward<8>};
constexpr Kernel back_kernels[] = {back<0>, back<1>, back<2>, back<3>, back<4>, back<5>, back<6>, back<7>, back<8>};
constexpr int widest_kernel = 8;

Kernel kernel(const Kernel (&kernels)[widest_kernel + 1], int width) {
    return kernels[width <= widest_kernel ? width : 0];
}

}  // namespace

void SinglePrecisionFactor::solve(const double* b, double* x, int columns) const {
    const int n = static_cast<int>(permutation_.size());
    work_.resize(static_cast<std::size_t>(n) * columns);
    for (int c = 0; c < columns; ++c)
        for (int k = 0; k < n; ++k)
            work_[static_cast<std::size_t>(c) * n + k] = b[static_cast<std::size_t>(c) * n + permutation_[k]];
    // Each group for every column while its values are in the cache.
    auto sweep = [&](const Kernel(&kernels)[widest_kernel + 1], auto begin, auto end) {
        for (auto it = begin; it != end; ++it) {
            const Group& g = *it;
            const float* block = values_.data() + g.value;
            const float* below = block + static_cast<std::size_t>(g.width) * g.width;
            const int* row = rows_.data() + g.row;
            for (int c = 0; c < columns; ++c) {
                double* y = work_.data() + static_cast<std::size_t>(c) * n;
                kernel(kernels, g.width)(g.width, block, below, row, g.rows, y + g.first, y);
            }
        }
    };
    sweep(forward_kernels, groups_.begin(), groups_.end());  // L y = P b
    sweep(back_kernels, groups_.rbegin(), groups_.rend());   // Lᵀ z = y, the groups in reverse
    for (int c = 0; c < columns; ++c)
        for (int k = 0; k < n; ++k)
            x[static_cast<std::size_t>(c) * n + permutation_[k]] = work_[static_cast<std::size_t>(c) * n + k];
}

}  // namespace mcdda

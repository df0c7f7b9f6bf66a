#include "linalg/SymmetricSystem.hpp"

#include "linalg/SinglePrecisionFactor.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>

namespace mcdda {

using StorageIndex = Eigen::SparseMatrix<double>::StorageIndex;

// CHOLMOD's automatic choice between the simplicial and the supernodal method (dense BLAS
// blocks), which pays only on large factors.
class CholmodFactor {
public:
    struct Decomposition : Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> {
        const cholmod_factor& factor() const { return *m_cholmodFactor; }
    };
    Decomposition llt;
    /// The factor in single precision, for the solves that only precondition: those with a
    /// factor held from an earlier matrix (copied at the first of them after a factorisation).
    SinglePrecisionFactor single;
    bool single_current = false;

    /// z = A⁻¹ r with the factor's single-precision copy, for `columns` right-hand sides
    /// (column-major).
    void precondition(const double* r, double* z, int columns) {
        if (!single_current) {
            single.assign(llt.factor());
            single_current = true;
        }
        single.solve(r, z, columns);
    }
};

// UMFPACK's LU with its default (unsymmetric or symmetric) strategy chosen from the pattern.
class LuFactor {
public:
    Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu;
};

SymmetricSystem::SymmetricSystem() : factor_(std::make_unique<CholmodFactor>()), lu_(std::make_unique<LuFactor>()) {
    factor_->llt.cholmod().print = 0;  // failures are reported through SingularSystem, not stderr
    // LLᵀ in both methods: a simplicial LDLᵀ would accept an indefinite matrix (a mechanism)
    // and only stop at an exactly zero pivot.
    factor_->llt.cholmod().final_ll = 1;
    // Supernodal only for factors with many flops per entry: the simplicial method factorised
    // 4k–20k equations 2–2.5 times faster than CHOLMOD's default switch (40) chose, on the
    // reference BLAS and on OpenBLAS alike; from about 20k six-node equations on both switches
    // pick the supernodal method (docs/plasticity.md).
    factor_->llt.cholmod().supernodal_switch = 300;
    // No iterative refinement of LU solves: the equilibrium iterations refine the solution
    // themselves (each solves for the out-of-balance force of the last), and UMFPACK's check of
    // every solve's backward error (a product with the matrix and an estimate) took a fifth to a
    // third of the solve time of Salençon's tunnel with ψ = 0 while it refined nothing there (the
    // same results to the last bit; docs/benchmarks.md, "LU solves without iterative refinement").
    lu_->lu.umfpackControl()(UMFPACK_IRSTEP) = 0;
    // Fill-reducing ordering: the symbolic analysis tries AMD and METIS's nested dissection and
    // keeps the one whose factor has fewer entries. On the default example's 31k equations
    // nested dissection gives 1.84M entries and 2.2e8 flops per factorisation against AMD's
    // 1.98M and 3.1e8; the Hoek–Brown tunnel's run takes a fifth less CPU with it
    // (docs/benchmarks.md). The price is one METIS call per pattern (about 0.2 s at 31k
    // equations).
    cholmod_common& c = factor_->llt.cholmod();
    c.nmethods = 2;
    c.method[0].ordering = CHOLMOD_AMD;
    c.method[1].ordering = CHOLMOD_METIS;
}

SymmetricSystem::~SymmetricSystem() = default;

void SymmetricSystem::set_pattern(int equations, const std::vector<CouplingGroup>& groups,
                                  const std::vector<CouplingGroup>& pattern_only) {
    equations_ = equations;
    // Column lists of the lower triangle, the diagonal always present (inertia, springs).
    std::vector<std::vector<int>> rows(equations);
    for (int e = 0; e < equations; ++e) rows[e].push_back(e);
    for (const auto* list : {&groups, &pattern_only})
        for (const CouplingGroup& g : *list)
            for (int a = 0; a < g.size; ++a)
                for (int b = 0; b <= a; ++b) {
                    const int i = g.equation[a], j = g.equation[b];
                    if (i < 0 || j < 0) continue;
                    rows[std::min(i, j)].push_back(std::max(i, j));
                }
    std::vector<StorageIndex> outer(equations + 1, 0);
    std::size_t nonzeros = 0;
    for (int c = 0; c < equations; ++c) {
        auto& r = rows[c];
        std::sort(r.begin(), r.end());
        r.erase(std::unique(r.begin(), r.end()), r.end());
        nonzeros += r.size();
        outer[c + 1] = static_cast<StorageIndex>(nonzeros);
    }
    matrix_.resize(equations, equations);
    matrix_.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
    std::copy(outer.begin(), outer.end(), matrix_.outerIndexPtr());
    StorageIndex* inner = matrix_.innerIndexPtr();
    for (int c = 0; c < equations; ++c) std::copy(rows[c].begin(), rows[c].end(), inner + outer[c]);
    rows.clear();

    set_groups(groups);
    diagonal_slot_.resize(equations);
    for (int e = 0; e < equations; ++e) diagonal_slot_[e] = outer[e];  // the diagonal is each column's first row
    analysed_ = false;
    has_factor_ = llt_valid_ = false;
    factored_values_.clear();
    correction_.clear();
    correction_built_ = false;
    full_.resize(0, 0);
    full_source_.clear();
    lu_analysed_ = false;
    lu_current_ = false;
    clear_values();
}

int SymmetricSystem::slot_of(int i, int j) const {
    const int col = std::min(i, j), row = std::max(i, j);
    const StorageIndex* inner = matrix_.innerIndexPtr();
    const StorageIndex* begin = inner + matrix_.outerIndexPtr()[col];
    const StorageIndex* end = inner + matrix_.outerIndexPtr()[col + 1];
    const StorageIndex* it = std::lower_bound(begin, end, row);
    return it != end && *it == row ? static_cast<int>(it - inner) : -1;
}

void SymmetricSystem::set_groups(const std::vector<CouplingGroup>& groups, int keep) {
    group_size_.resize(keep);
    group_slot_offset_.resize(keep + 1);
    slots_.resize(group_slot_offset_.back());
    for (const CouplingGroup& g : groups) {
        group_size_.push_back(g.size);
        for (int a = 0; a < g.size; ++a)
            for (int b = 0; b <= a; ++b) {
                const int i = g.equation[a], j = g.equation[b];
                slots_.push_back(i < 0 || j < 0 ? -1 : 2 * slot_of(i, j) + (i < j ? 1 : 0));
            }
        group_slot_offset_.push_back(static_cast<int>(slots_.size()));
    }
}

bool SymmetricSystem::set_groups_if_in_pattern(const std::vector<CouplingGroup>& groups, int keep) {
    // The new groups' slots are found first, aside: a coupling missing from the pattern leaves
    // the groups as they were.
    new_slots_.clear();
    for (const CouplingGroup& g : groups)
        for (int a = 0; a < g.size; ++a)
            for (int b = 0; b <= a; ++b) {
                const int i = g.equation[a], j = g.equation[b];
                if (i < 0 || j < 0) {
                    new_slots_.push_back(-1);
                    continue;
                }
                const int slot = slot_of(i, j);
                if (slot < 0) return false;
                new_slots_.push_back(2 * slot + (i < j ? 1 : 0));
            }
    group_size_.resize(keep);
    group_slot_offset_.resize(keep + 1);
    slots_.resize(group_slot_offset_.back());
    slots_.insert(slots_.end(), new_slots_.begin(), new_slots_.end());
    for (const CouplingGroup& g : groups) {
        group_size_.push_back(g.size);
        group_slot_offset_.push_back(group_slot_offset_.back() + g.size * (g.size + 1) / 2);
    }
    return true;
}

void SymmetricSystem::clear_values() {
    std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
    if (unsymmetric_) upper_.assign(static_cast<std::size_t>(matrix_.nonZeros()), 0.0);
}

void SymmetricSystem::save_values(std::vector<double>& out) const {
    out.assign(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros());
}

void SymmetricSystem::restore_values(const std::vector<double>& saved) {
    std::copy(saved.begin(), saved.end(), matrix_.valuePtr());
}

void SymmetricSystem::add(int g, const double* k) {
    const int n = group_size_[g];
    const int* slot = slots_.data() + group_slot_offset_[g];
    double* values = matrix_.valuePtr();
    if (!unsymmetric_) {
        for (int a = 0; a < n; ++a)
            for (int b = 0; b <= a; ++b, ++slot)
                if (*slot >= 0) values[*slot >> 1] += k[a + b * n];
        return;
    }
    // The lower triangle's entry is the block's (a, b) unless equation a lies above equation b.
    double* upper = upper_.data();
    for (int a = 0; a < n; ++a)
        for (int b = 0; b <= a; ++b, ++slot) {
            if (*slot < 0) continue;
            const int at = *slot >> 1;
            const bool swapped = *slot & 1;
            values[at] += swapped ? k[b + a * n] : k[a + b * n];
            if (a != b) upper[at] += swapped ? k[a + b * n] : k[b + a * n];
        }
}

void SymmetricSystem::add_diagonal(int e, double value) { matrix_.valuePtr()[diagonal_slot_[e]] += value; }

namespace {
/// More iterations than this in one solve: the held factor no longer fits the matrix.
constexpr int max_refinement_iterations = 40;
/// A triangular solve or a product with the matrix runs at a lower flop rate than the
/// factorisation, whose dense blocks (supernodal) make better use of the cache: measured on
/// OpenBLAS (docs/benchmarks.md), a 51k-element six-node system factorised in the time of 27
/// solves for 96 solves' flops, a 5k one (simplicial) in the time of 20 for 31.
constexpr double solve_flop_cost_supernodal = 3.5;
constexpr double solve_flop_cost_simplicial = 1.5;
}  // namespace

void SymmetricSystem::factorize(bool may_reuse) {
    if (unsymmetric_) {
        factorize_lu();
        return;
    }
    // The very matrix the held factor is of (the elastic matrix again after a tangent that could
    // not be factorised): solved directly, neither iterated nor factorised again.
    if (llt_valid_ && analysed_ && values_digest() == factored_digest_) {
        stale_ = false;
        lu_current_ = false;
        has_factor_ = true;
        return;
    }
    // Keep the held factor while iterating with it has cost less than a factorisation. After a
    // held factor that did not fit (its iterations did not converge) the next 3 matrices that
    // could keep one are factorised at once, after two misfits in a row the next 15, after
    // three the next 63: where every matrix is far from the last (open–close rounds that change
    // hundreds of contacts each on a finely jointed slope) the 40 iterations were spent in vain
    // on each; where held factors fit this changes nothing.
    const bool may_hold = may_reuse && llt_valid_ && analysed_ && refinement_flops_ < factor_->llt.cholmod().fl;
    if (may_hold && held_skips_left_ > 0) {
        --held_skips_left_;
    } else if (may_hold) {
        stale_ = true;
        lu_current_ = false;
        has_factor_ = true;
        last_refinement_iterations_ = 0;
        correction_built_ = false;
        ++reused_factors_;
        return;
    }
    factorize_now();
}

std::uint64_t SymmetricSystem::values_digest() const {
    // FNV-1a over the bytes of the values, a word at a time: equal matrices, equal digests; a
    // different matrix shares one with a chance of 2⁻⁶⁴.
    std::uint64_t h = 1469598103934665603ULL;
    const double* v = matrix_.valuePtr();
    for (Eigen::Index i = 0; i < matrix_.nonZeros(); ++i) {
        std::uint64_t bits;
        std::memcpy(&bits, v + i, sizeof bits);
        h = (h ^ bits) * 1099511628211ULL;
    }
    return h;
}

const char* SymmetricSystem::ordering() const {
    if (!analysed_) return "";
    const cholmod_common& c = factor_->llt.cholmod();
    return c.method[c.selected].ordering == CHOLMOD_METIS ? "METIS" : "AMD";
}

double SymmetricSystem::factorization_flops() const { return analysed_ ? factor_->llt.cholmod().fl : 0.0; }

void SymmetricSystem::factorize_now() {
    const auto start = std::chrono::steady_clock::now();
    if (!analysed_) {
        factor_->llt.analyzePattern(matrix_);
        analysed_ = true;
        ++analyses_;
    }
    has_factor_ = false;
    lu_current_ = false;
    stale_ = false;
    refinement_flops_ = 0.0;
    factored_digest_ = values_digest();
    factored_values_.assign(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros());
    correction_.clear();
    correction_built_ = false;
    factor_->single_current = false;
    factor_->llt.factorize(matrix_);
    ++factorizations_;
    factorization_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    has_factor_ = llt_valid_ = factor_->llt.info() == Eigen::Success;
    if (!has_factor_)
        throw SingularSystem("the stiffness matrix is not positive definite (a block is free to move: "
                                 "check supports, or use a dynamic analysis)");
}

void SymmetricSystem::factorize_lu() {
    const auto start = std::chrono::steady_clock::now();
    if (full_.rows() != equations_) {
        // The whole pattern, column by column: above the diagonal the transposed lower entries.
        std::vector<std::vector<std::pair<int, int>>> columns(equations_);  // (row, source)
        const StorageIndex* outer = matrix_.outerIndexPtr();
        const StorageIndex* inner = matrix_.innerIndexPtr();
        for (int c = 0; c < equations_; ++c)
            for (StorageIndex p = outer[c]; p < outer[c + 1]; ++p) {
                const int r = inner[p];
                columns[c].emplace_back(r, 2 * static_cast<int>(p));
                if (r != c) columns[r].emplace_back(c, 2 * static_cast<int>(p) + 1);
            }
        std::vector<StorageIndex> full_outer(equations_ + 1, 0);
        for (int c = 0; c < equations_; ++c) {
            std::sort(columns[c].begin(), columns[c].end());
            full_outer[c + 1] = full_outer[c] + static_cast<StorageIndex>(columns[c].size());
        }
        full_.resize(equations_, equations_);
        full_.resizeNonZeros(full_outer.back());
        std::copy(full_outer.begin(), full_outer.end(), full_.outerIndexPtr());
        full_source_.resize(full_outer.back());
        for (int c = 0; c < equations_; ++c)
            for (std::size_t k = 0; k < columns[c].size(); ++k) {
                full_.innerIndexPtr()[full_outer[c] + k] = columns[c][k].first;
                full_source_[full_outer[c] + k] = columns[c][k].second;
            }
        lu_analysed_ = false;
    }
    const double* lower = matrix_.valuePtr();
    double* values = full_.valuePtr();
    for (std::size_t p = 0; p < full_source_.size(); ++p) {
        const int source = full_source_[p];
        values[p] = source & 1 ? upper_[source >> 1] : lower[source >> 1];
    }
    if (!lu_analysed_) {
        lu_->lu.analyzePattern(full_);
        lu_analysed_ = true;
        ++analyses_;
    }
    has_factor_ = false;
    stale_ = false;
    lu_->lu.factorize(full_);
    ++factorizations_;
    factorization_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lu_current_ = true;
    has_factor_ = lu_->lu.info() == Eigen::Success;
    if (!has_factor_)
        throw SingularSystem("the tangent stiffness matrix is singular (a mechanism: the material can carry "
                             "no more, or a block is free to move)");
}

Eigen::VectorXd SymmetricSystem::solve(const Eigen::VectorXd& rhs, double tolerance) {
    if (lu_current_) return lu_->lu.solve(rhs);
    const cholmod_common& c = factor_->llt.cholmod();
    // CHOLMOD chooses the supernodal method from the flops per factor entry (supernodal_switch).
    const double cost = c.fl >= c.supernodal_switch * c.lnz ? solve_flop_cost_supernodal : solve_flop_cost_simplicial;
    const double product_flops = cost * 4.0 * static_cast<double>(matrix_.nonZeros());
    const double iteration_flops = cost * 4.0 * c.lnz + product_flops;
    // Factorise the current matrix once iterating has cost a factorisation, or when this matrix
    // is solved again and its first solve took more than a quarter of a factorisation's worth of
    // iterations (the plastic iterations solve one matrix many times).
    if (stale_ && (refinement_flops_ >= c.fl || 4.0 * last_refinement_iterations_ * iteration_flops > c.fl))
        factorize_now();
    if (!stale_) return factor_->llt.solve(rhs);
    if (!correction_built_) {
        // Its directions are solved for together, each after the first at about half the price
        // of a solve of its own (measured with CHOLMOD's factor on the default example: 4 ms for
        // one, 1–1.3 ms for each further one; the single-precision copy, too, reads the factor
        // once for all of them); worth it while that costs at most three quarters of a
        // factorisation.
        const int max_rank = std::max(1, static_cast<int>(1.0 + 2.0 * (0.75 * c.fl / iteration_flops - 1.0)));
        correction_built_ = true;
        correction_.build(
            matrix_, factored_values_,
            [this](const Eigen::MatrixXd& b) {
                Eigen::MatrixXd z(b.rows(), b.cols());
                factor_->precondition(b.data(), z.data(), static_cast<int>(b.cols()));
                return z;
            },
            6 * max_rank, max_rank);
        if (correction_.rank() > 0) refinement_flops_ += (0.5 + 0.5 * correction_.rank()) * iteration_flops;
    }
    // Conjugate gradients on the current matrix, preconditioned by the held factor (its copy in
    // single precision, corrected).
    const auto A = matrix_.selfadjointView<Eigen::Lower>();
    const double target = tolerance * rhs.norm();
    Eigen::VectorXd x = Eigen::VectorXd::Zero(rhs.size()), r = rhs, z, p, Ap;
    double rz = 0.0;
    for (int k = 0; k < max_refinement_iterations; ++k) {
        if (r.norm() <= target) {
            last_refinement_iterations_ = k;
            held_misfits_ = 0;
            return x;
        }
        z.resize(r.size());
        factor_->precondition(r.data(), z.data(), 1);
        correction_.apply(r, z);
        const double rz_next = r.dot(z);
        // A preconditioner that is not positive definite (a correction of a matrix that is not
        // either): factorise to find out.
        if (!(rz_next > 0.0)) break;
        if (k == 0) p = z;
        else p = z + (rz_next / rz) * p;
        rz = rz_next;
        Ap = A * p;
        const double curvature = p.dot(Ap);
        ++refinement_iterations_;
        // What holding costs beyond the solve a fresh factor would make: the product with the
        // matrix, and every solve after the first.
        refinement_flops_ += k == 0 ? product_flops : iteration_flops;
        if (!(curvature > 0.0)) break;  // not positive definite along p: factorise to find out
        const double alpha = rz / curvature;
        x += alpha * p;
        r -= alpha * Ap;
    }
    if (r.norm() <= target) {
        last_refinement_iterations_ = max_refinement_iterations;
        held_misfits_ = 0;
        return x;
    }
    held_misfits_ = std::min(held_misfits_ + 1, 3);
    held_skips_left_ = (1 << (2 * held_misfits_)) - 1;  // 3, 15, 63
    factorize_now();  // the held factor no longer fits (throws when the matrix is singular)
    return factor_->llt.solve(rhs);
}

}  // namespace mcdda

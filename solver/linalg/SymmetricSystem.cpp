#include "linalg/SymmetricSystem.hpp"

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <stdexcept>

namespace mcdda {

using StorageIndex = Eigen::SparseMatrix<double>::StorageIndex;

// CHOLMOD's automatic choice between the simplicial and the supernodal method (dense BLAS
// blocks), which pays only on large factors.
class CholmodFactor {
public:
    Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
};

SymmetricSystem::SymmetricSystem() : factor_(std::make_unique<CholmodFactor>()) {
    factor_->llt.cholmod().print = 0;  // failures are reported through SingularSystem, not stderr
    // LLᵀ in both methods: a simplicial LDLᵀ would accept an indefinite matrix (a mechanism)
    // and only stop at an exactly zero pivot.
    factor_->llt.cholmod().final_ll = 1;
    // Supernodal only for factors with many flops per entry: the simplicial method factorised
    // 4k–20k equations 2–2.5 times faster than CHOLMOD's default switch (40) chose, on the
    // reference BLAS and on OpenBLAS alike; from about 20k six-node equations on both switches
    // pick the supernodal method (docs/plasticity.md).
    factor_->llt.cholmod().supernodal_switch = 300;
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
    has_factor_ = false;
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

bool SymmetricSystem::pattern_contains(const std::vector<CouplingGroup>& groups) const {
    for (const CouplingGroup& g : groups)
        for (int a = 0; a < g.size; ++a)
            for (int b = 0; b <= a; ++b) {
                const int i = g.equation[a], j = g.equation[b];
                if (i >= 0 && j >= 0 && slot_of(i, j) < 0) return false;
            }
    return true;
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
                slots_.push_back(i < 0 || j < 0 ? -1 : slot_of(i, j));
            }
        group_slot_offset_.push_back(static_cast<int>(slots_.size()));
    }
}

void SymmetricSystem::clear_values() {
    std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
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
    for (int a = 0; a < n; ++a)
        for (int b = 0; b <= a; ++b, ++slot)
            if (*slot >= 0) values[*slot] += k[a + b * n];
}

void SymmetricSystem::add_diagonal(int e, double value) { matrix_.valuePtr()[diagonal_slot_[e]] += value; }

void SymmetricSystem::factorize() {
    if (!analysed_) {
        factor_->llt.analyzePattern(matrix_);
        analysed_ = true;
        ++analyses_;
    }
    has_factor_ = false;
    factor_->llt.factorize(matrix_);
    ++factorizations_;
    has_factor_ = factor_->llt.info() == Eigen::Success;
    if (!has_factor_)
        throw SingularSystem("the stiffness matrix is not positive definite (a block is free to move: "
                                 "check supports, or use a dynamic analysis)");
}

Eigen::VectorXd SymmetricSystem::solve(const Eigen::VectorXd& rhs) const { return factor_->llt.solve(rhs); }

}  // namespace mcdda

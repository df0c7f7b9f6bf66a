#pragma once
/// \file BlasInfo.hpp
/// Which BLAS the process uses. CHOLMOD's speed depends on it (Debian links libblas.so.3, which
/// its alternatives system points to the reference BLAS or to OpenBLAS), so `mcdda --version`
/// and summary.json name it.

#include <string>

namespace mcdda {

/// E.g. "OpenBLAS 0.3.21 (…/openblas-serial/libblas.so.3)" or "reference BLAS (…/blas/libblas.so.3)".
std::string blas_in_use();

}  // namespace mcdda

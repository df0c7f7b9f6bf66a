#include "linalg/BlasInfo.hpp"

#include <dlfcn.h>

#include <climits>
#include <cstdlib>
#include <string>

namespace mcdda {

std::string blas_in_use() {
    std::string library = "unknown library";
    // Any BLAS routine (CHOLMOD loaded the library): the file it comes from names the library.
    Dl_info info{};
    void* routine = dlsym(RTLD_DEFAULT, "dgemm_");
    if (routine && dladdr(routine, &info) != 0 && info.dli_fname) {
        library = info.dli_fname;
        char resolved[PATH_MAX];
        if (realpath(info.dli_fname, resolved)) library = resolved;  // through Debian's alternatives
    }
    // OpenBLAS identifies itself; the reference BLAS has no such function.
    using ConfigFunction = const char* (*)();
    if (auto config = reinterpret_cast<ConfigFunction>(dlsym(RTLD_DEFAULT, "openblas_get_config"))) {
        std::string text = config();
        // "OpenBLAS 0.3.21 DYNAMIC_ARCH NO_AFFINITY Haswell MAX_THREADS=64": name, version, core.
        return text + " (" + library + ")";
    }
    if (library.find("/blas/") != std::string::npos) return "reference BLAS (" + library + ")";
    return library;
}

}  // namespace mcdda

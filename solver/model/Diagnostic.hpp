#pragma once
/// \file Diagnostic.hpp
/// Messages about user input. Errors stop the pipeline; warnings are shown and the work goes on.

#include <algorithm>
#include <string>
#include <vector>

namespace mcdda {

/// A message about the input, naming the item it concerns by its JSON pointer.
struct Diagnostic {
    enum class Severity { Warning, Error };
    Severity severity = Severity::Error;
    std::string path;     ///< JSON pointer into the model file, e.g. "/joints/3"; may be empty
    std::string message;  ///< plain English, no trailing period
};

inline bool has_errors(const std::vector<Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::Error; });
}

/// "error: /materials/0/poisson_ratio: must be below 0.5 (got 0.5)"
inline std::string format_diagnostic(const Diagnostic& d) {
    std::string text = d.severity == Diagnostic::Severity::Error ? "error: " : "warning: ";
    if (!d.path.empty()) text += d.path + ": ";
    return text + d.message;
}

}  // namespace mcdda

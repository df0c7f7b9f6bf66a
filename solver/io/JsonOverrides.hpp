#pragma once
/// \file JsonOverrides.hpp
/// `--set /json/pointer=value`: change any field of a model before it is read, for batch studies.

#include "model/Diagnostic.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace mcdda {

/// Applies "POINTER=VALUE" assignments to `document`. VALUE is parsed as JSON when it is valid
/// JSON (numbers, true, arrays …) and taken as a string otherwise. The pointer must name an
/// existing field, an array element, or a new key of an existing object. Problems are reported
/// in `diagnostics` (path = the pointer) and that assignment is skipped.
void apply_overrides(nlohmann::json& document, const std::vector<std::string>& assignments,
                     std::vector<Diagnostic>& diagnostics);

}  // namespace mcdda

#pragma once
/// \file JsonText.hpp
/// Parses the text of a JSON file (a model, a study), turning the JSON library's errors into
/// diagnostics a user can act on: the file, line and column, and what is wrong in plain words
/// ("NaN is not a number JSON allows"), never the library's exception text.

#include "model/Diagnostic.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace mcdda {

/// The document `text` holds; nullopt, with an error "SOURCE:LINE:COLUMN: malformed JSON: ..."
/// (or "...: number 1e400 is too large ...") in `diagnostics`, when it is not valid JSON.
std::optional<nlohmann::json> parse_json_text(const std::string& text, const std::string& source,
                                              std::vector<Diagnostic>& diagnostics);

}  // namespace mcdda

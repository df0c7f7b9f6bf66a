#pragma once
/// \file ModelReader.hpp
/// Reads the JSON model file (format "mcdda-model", version 1; docs/model-format.md) into a
/// Model. Structure and types are checked here, every problem named by its JSON pointer; value
/// ranges and geometry are checked by ModelValidator and the block cutter.

#include "model/Diagnostic.hpp"
#include "model/Model.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mcdda {

struct ReadResult {
    std::optional<Model> model;           ///< empty when the file could not be understood
    std::vector<Diagnostic> diagnostics;  ///< errors and warnings, in file order
};

/// Parses `text` (the file's content), applying `overrides` ("POINTER=VALUE") first.
/// `source` names the file in messages about malformed JSON.
ReadResult read_model_text(const std::string& text, const std::vector<std::string>& overrides = {},
                           const std::string& source = "model");

/// Reads and parses a file; a missing or unreadable file is an error diagnostic, not an exception.
ReadResult read_model_file(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace mcdda

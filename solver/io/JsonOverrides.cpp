#include "io/JsonOverrides.hpp"

#include "io/TextEncoding.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace mcdda {

namespace {

Diagnostic override_error(const std::string& pointer, const std::string& message) {
    return {Diagnostic::Severity::Error, pointer, "--set: " + message};
}

/// The JSON library's pointer errors in words (its own text names exception ids).
std::string pointer_problem(const nlohmann::json::exception& e, const std::string& pointer) {
    switch (e.id) {
        case 107: return "a pointer starts with '/', e.g. /materials/0/cohesion (got \"" + pointer + "\")";
        case 108: return "'~' in a pointer must be followed by 0 ('~') or 1 ('/')";
        case 106: return "an array index in the pointer must not begin with 0 (got \"" + pointer + "\")";
        case 109: return "an array index in the pointer is not a number";
        case 410: return "an array index in the pointer is too large";
        case 401:
        case 403:
        case 404: return "no such field in the model";
        default: break;
    }
    std::string what = e.what();
    const auto bracket = what.find("] ");
    return bracket == std::string::npos ? what : what.substr(bracket + 2);
}

}  // namespace

void apply_overrides(nlohmann::json& document, const std::vector<std::string>& assignments,
                     std::vector<Diagnostic>& diagnostics) {
    using nlohmann::json;
    for (const std::string& assignment : assignments) {
        const auto eq = assignment.find('=');
        if (eq == std::string::npos || eq == 0) {
            diagnostics.push_back(override_error(
                assignment, "expected POINTER=VALUE, e.g. /materials/0/cohesion=3.45e6"));
            continue;
        }
        const std::string pointer_text = assignment.substr(0, eq);
        const std::string value_text = assignment.substr(eq + 1);
        if (!is_utf8(pointer_text)) {
            diagnostics.push_back(override_error(pointer_text, "the pointer is not UTF-8 text"));
            continue;
        }
        json value = json::parse(value_text, nullptr, /*allow_exceptions=*/false);
        if (value.is_discarded()) {  // a bare word is a string, which JSON holds in UTF-8 only
            if (!is_utf8(value_text)) {
                diagnostics.push_back(override_error(pointer_text, "the value is not UTF-8 text"));
                continue;
            }
            value = value_text;
        }

        try {
            const json::json_pointer pointer(pointer_text);
            if (pointer.empty()) {
                diagnostics.push_back(override_error(pointer_text, "cannot replace the whole model"));
                continue;
            }
            const json::json_pointer parent = pointer.parent_pointer();
            if (!document.contains(parent)) {
                diagnostics.push_back(override_error(
                    pointer_text, "no field " + parent.to_string() + " in the model"));
                continue;
            }
            json& container = document.at(parent);
            if (container.is_array()) {
                const std::string& last = pointer.back();
                const bool append = last == "-";
                std::size_t index = 0;
                if (!append) {
                    if (last.empty() || last.find_first_not_of("0123456789") != std::string::npos) {
                        diagnostics.push_back(override_error(pointer_text, "array index expected"));
                        continue;
                    }
                    index = std::stoul(last);
                    if (index >= container.size()) {
                        diagnostics.push_back(override_error(
                            pointer_text, "index " + last + " is past the end (size " +
                                              std::to_string(container.size()) + ")"));
                        continue;
                    }
                }
                if (append) container.push_back(value); else container[index] = value;
            } else if (container.is_object()) {
                container[pointer.back()] = value;
            } else {
                diagnostics.push_back(override_error(
                    pointer_text, parent.to_string() + " is neither an object nor an array"));
            }
        } catch (const json::exception& e) {
            diagnostics.push_back(override_error(pointer_text, pointer_problem(e, pointer_text)));
        } catch (const std::exception& e) {
            diagnostics.push_back(override_error(pointer_text, e.what()));
        }
    }
}

}  // namespace mcdda

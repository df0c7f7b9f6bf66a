#include "io/JsonText.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace mcdda {

namespace {

using nlohmann::json;

/// Line and column (1-based) of a byte offset.
std::pair<std::size_t, std::size_t> line_and_column(const std::string& text, std::size_t byte) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
    }
    return {line, column};
}

/// Byte offset and text of the first number literal outside strings that overflows a double.
std::pair<std::size_t, std::string> first_overflowing_number(const std::string& text) {
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char ch = text[i];
        if (in_string) {
            if (ch == '\\') ++i;
            else if (ch == '"') in_string = false;
            continue;
        }
        if (ch == '"') {
            in_string = true;
            continue;
        }
        if (ch != '-' && !std::isdigit(static_cast<unsigned char>(ch))) continue;
        std::size_t end = i;
        while (end < text.size() && std::strchr("+-.eE0123456789", text[end]) != nullptr) ++end;
        const std::string literal = text.substr(i, end - i);
        if (!std::isfinite(std::strtod(literal.c_str(), nullptr))) return {i, literal};
        i = end - 1;
    }
    return {0, "?"};
}

bool delimiter(char c) { return std::strchr(" \t\r\n,:[]{}\"", c) != nullptr; }

/// The word of the text around `byte` (where the parser stopped) and where it starts, at most 30
/// characters, with bytes that are not printable ASCII shown as '?': what the message quotes. A
/// bad word is found bad at the delimiter after it ("1e]"), hence the step back.
std::pair<std::string, std::size_t> word_at(const std::string& text, std::size_t byte) {
    if (byte >= text.size()) return {"", byte};
    if (delimiter(text[byte]) && byte > 0 && !delimiter(text[byte - 1])) --byte;
    if (delimiter(text[byte])) return {std::string(1, text[byte]), byte};
    std::size_t start = byte, end = byte;
    while (start > 0 && byte - start < 30 && !delimiter(text[start - 1])) --start;
    while (end < text.size() && end - start < 30 && !delimiter(text[end])) ++end;
    std::string word = text.substr(start, end - start);
    for (char& c : word)
        if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    return {word, start};
}

bool names_nan_or_infinity(std::string word) {
    for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!word.empty() && (word[0] == '-' || word[0] == '+')) word.erase(0, 1);
    return word.rfind("nan", 0) == 0 || word.rfind("inf", 0) == 0;
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
}

/// The parser's complaint ("syntax error while parsing value - invalid literal; last read:
/// '[N'") in words, with the word the file has at the place; `byte` moves to the start of a bad
/// word.
std::string plain_parse_error(const std::string& what, const std::string& text, std::size_t& byte) {
    std::string context, problem = what;
    const auto parsing = what.find("while parsing ");
    const auto dash = what.find(" - ", parsing == std::string::npos ? 0 : parsing);
    if (parsing != std::string::npos && dash != std::string::npos) {
        context = what.substr(parsing + 14, dash - parsing - 14);
        problem = what.substr(dash + 3);
    } else if (const auto colon = what.find(": ", what.find("column ")); colon != std::string::npos) {
        problem = what.substr(colon + 2);
    }
    // "; last read: '<token so far>'" repeats the file's text in the library's notation.
    std::string expected;
    if (const auto last = problem.find("; last read: '"); last != std::string::npos) {
        const auto more = problem.rfind("'; expected ");
        if (more != std::string::npos && more > last) expected = problem.substr(more + 3);
        problem = problem.substr(0, last) + (expected.empty() ? "" : "; " + expected);
    }
    const auto [word, start] = word_at(text, byte);
    const bool bad_word = problem.rfind("invalid literal", 0) == 0 || problem.rfind("invalid number", 0) == 0;
    if (bad_word) byte = start;
    if (bad_word && names_nan_or_infinity(word))
        return word + " is not a number in JSON, which has no NaN or infinity: write a finite number";
    if (problem.rfind("invalid literal", 0) == 0) {
        if (context == "object key") return "a key must be text in double quotes, got " + word;
        return word + " is not a JSON value (text goes in double quotes; the only bare words are true, "
                      "false and null)";
    }
    if (problem.rfind("invalid number", 0) == 0) {
        const auto semicolon = problem.find("; ");
        return word + " is not a number" +
               (semicolon == std::string::npos ? std::string() : " (" + problem.substr(semicolon + 2) + ")");
    }
    if (problem.rfind("invalid string: ill-formed UTF-8", 0) == 0)
        return "a text holds bytes that are not UTF-8: save the file as UTF-8";
    if (problem.rfind("invalid string: ", 0) == 0) return "a text in double quotes is not valid: " + problem.substr(16);
    if (problem.rfind("unexpected end of input", 0) == 0) {
        if (text.find_first_not_of(" \t\r\n") == std::string::npos) return "the file is empty";
        return "the file ends before the JSON does (a ] or } missing?)";
    }
    if (problem.rfind("unexpected ", 0) == 0) {
        std::string found = problem.substr(11), wanted;
        if (const auto semicolon = found.find("; expected "); semicolon != std::string::npos) {
            wanted = found.substr(semicolon + 11);
            found = found.substr(0, semicolon);
        }
        for (std::string* s : {&found, &wanted}) {
            replace_all(*s, "string literal", "text in double quotes");
            replace_all(*s, "number literal", "a number");
            replace_all(*s, "end of input", "the end of the file");
        }
        return "found " + found + (wanted.empty() ? std::string() : " where " + wanted + " was expected");
    }
    return problem;
}

}  // namespace

std::optional<json> parse_json_text(const std::string& text, const std::string& source,
                                    std::vector<Diagnostic>& diagnostics) {
    auto error = [&](std::size_t byte, const std::string& message) {
        const auto [line, column] = line_and_column(text, byte);
        diagnostics.push_back({Diagnostic::Severity::Error, "",
                               source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message});
    };
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        // The library reports the byte just past the problem; step back to point at it.
        std::size_t byte = e.byte > 0 ? e.byte - 1 : 0;
        const std::string problem = plain_parse_error(e.what(), text, byte);
        error(byte, "malformed JSON: " + problem);
    } catch (const json::out_of_range&) {
        // A number beyond the range of a double (1e400): the library gives no position, so the
        // first such literal is found here.
        const auto [byte, literal] = first_overflowing_number(text);
        error(byte, "number " + literal + " is too large (beyond ±1.8e308)");
    }
    return std::nullopt;
}

}  // namespace mcdda

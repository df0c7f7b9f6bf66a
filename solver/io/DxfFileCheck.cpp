#include "io/DxfFileCheck.hpp"

#include "io/NumberText.hpp"
#include "io/TextEncoding.hpp"

#include <dxflib/dl_codes.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

namespace mcdda {

namespace {

/// dxflib reads a line with fgets into DL_DXF_MAXLINE bytes: the text, '\n' and the terminator.
constexpr std::size_t longest_line = DL_DXF_MAXLINE - 2;
/// Past this many problems the rest are not listed.
constexpr std::size_t most_errors = 20;

/// The text of a value as a message quotes it: UTF-8, control characters as '?', 40 characters.
std::string shown(const std::string& text)
{
    std::string s = as_utf8(text.size() > 40 ? text.substr(0, 40) : text);
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = '?';
    return text.size() > 40 ? s + "..." : s;
}

/// What a group code of an imported entity holds, in words.
std::string code_meaning(int code, const std::string& kind)
{
    switch (code) {
    case 10: case 11: return "the x";
    case 20: case 21: return "the y";
    case 30: case 31: return "the z";
    case 38: return "the elevation";
    case 42: return "the bulge";
    case 70: return "the flags";
    case 90: return kind == "LWPOLYLINE" ? "the number of vertices" : "the value";
    default: return "the value";
    }
}

/// An entity being read: its kind (the value of its group 0), where it starts, its layer, and
/// the counts it declares against what it holds.
struct Entity {
    std::string kind;
    std::size_t line = 0;
    std::string layer;
    std::map<int, long long> declared;  ///< count group code → value
    std::map<int, long long> held;      ///< item group code → occurrences (after its count)
    long long vertices_before_count = 0;  ///< LWPOLYLINE: 10s before the 90 (dxflib drops them)

    std::string name() const
    {
        return "the " + kind + (layer.empty() ? std::string() : " on layer \"" + shown(layer) + "\"") + " from line " +
               std::to_string(line);
    }
    bool imported() const
    {
        return kind == "LWPOLYLINE" || kind == "POLYLINE" || kind == "VERTEX" || kind == "LINE" || kind == "POINT";
    }
};

/// The counts dxflib allocates by: (entity, count code, item code, what the items are).
struct CountRule {
    const char* kind;
    int count, item;
    const char* items;
};
constexpr CountRule count_rules[] = {{"LWPOLYLINE", 90, 10, "vertices"},  {"SPLINE", 72, 40, "knots"},
                                     {"SPLINE", 73, 10, "control points"}, {"SPLINE", 74, 11, "fit points"},
                                     {"LEADER", 76, 10, "vertices"}};

class Checker {
public:
    std::vector<Diagnostic> errors;

    bool full() const { return errors.size() >= most_errors; }
    void error(const std::string& message)
    {
        if (full()) return;
        errors.push_back({Diagnostic::Severity::Error, "", message});
        if (full()) errors.push_back({Diagnostic::Severity::Error, "", "more problems not listed"});
    }

    /// One group: its code's line number, code and value.
    void group(std::size_t line, int code, const std::string& value)
    {
        // dxflib starts an entity (or a header variable) at group code 9 as at 0: "9 LWPOLYLINE"
        // followed by a count of 10⁹ made it allocate for 10⁹ vertices.
        if (code == 0 || code == 9) {
            finish();
            entity_ = Entity{value, line, {}, {}, {}, 0};
            return;
        }
        if (code == 8) entity_.layer = value;
        for (const CountRule& rule : count_rules) {
            if (entity_.kind != rule.kind) continue;
            if (code == rule.count) {
                const auto n = whole_number(value);
                entity_.declared[code] = n ? *n : 0;
                entity_.held[rule.item] = 0;
                count_lines_[code] = line;
            } else if (code == rule.item) {
                if (entity_.declared.count(rule.count)) ++entity_.held[rule.item];
                else if (code == 10 && entity_.kind == "LWPOLYLINE") ++entity_.vertices_before_count;
            }
        }
        if (entity_.imported()) check_number(line + 1, code, value);
    }

    /// Checks the counts of the entity read last (at the next entity and the end of the file).
    void finish()
    {
        for (const CountRule& rule : count_rules) {
            if (entity_.kind != rule.kind) continue;
            const auto declared = entity_.declared.find(rule.count);
            const long long held = entity_.declared.count(rule.count) ? entity_.held[rule.item] : 0;
            const bool lw = entity_.kind == std::string("LWPOLYLINE");
            if (declared == entity_.declared.end()) {
                if (lw && entity_.vertices_before_count > 0)
                    error("line " + std::to_string(entity_.line) + ": " + entity_.name() +
                          " does not say its number of vertices (group code 90) before them");
                continue;
            }
            // An LWPOLYLINE's count must match (dxflib keeps that many, overwriting the last);
            // other entities are not imported: a count beyond their content is what matters.
            const bool wrong = lw ? declared->second != held || entity_.vertices_before_count > 0
                                  : declared->second > held;
            if (wrong)
                error("line " + std::to_string(count_lines_[rule.count] + 1) + ": " + entity_.name() + " declares " +
                      std::to_string(declared->second) + " " + rule.items + " (group code " +
                      std::to_string(rule.count) + ") but holds " +
                      std::to_string(held + entity_.vertices_before_count));
        }
        entity_ = Entity{};
    }

private:
    void check_number(std::size_t line, int code, const std::string& value)
    {
        const bool real = code >= 10 && code <= 59;
        const bool whole = (code >= 60 && code <= 79) || (code >= 90 && code <= 99);
        if (!real && !whole) return;
        std::string problem;
        if (value.empty()) {
            problem = "is empty, not a number";
        } else if (real) {
            const std::optional<double> v = decimal_number(value, /*comma=*/true);  // dxflib takes ',' for '.'
            if (!v) problem = "is \"" + shown(value) + "\", not a number";
            else if (!std::isfinite(*v)) problem = "is \"" + shown(value) + "\", beyond the range of a number";
        } else {
            const std::optional<long long> v = whole_number(value);
            if (!v || *v < -2147483648LL || *v > 2147483647LL)
                problem = "is \"" + shown(value) + "\", not a whole number" + (v ? " dxflib can read" : "");
        }
        if (!problem.empty())
            error("line " + std::to_string(line) + ": " + code_meaning(code, entity_.kind) + " (group code " +
                  std::to_string(code) + ") of " + entity_.name() + " " + problem);
    }

    Entity entity_;
    std::map<int, std::size_t> count_lines_;  ///< count group code → the line of its code
};

/// Reads lines ('\n'-terminated) of at most `longest_line` bytes, as dxflib's fgets does.
class Lines {
public:
    explicit Lines(std::streambuf& in) : in_(in) {}

    enum class Result { Line, End, TooLong, Nul };

    /// The next line without '\n', stripped as dxflib strips it (trailing CR, spaces and tabs,
    /// leading spaces and tabs).
    Result next(std::string& line)
    {
        line.clear();
        ++number_;
        int c = in_.sbumpc();
        if (c == std::char_traits<char>::eof()) return Result::End;
        for (; c != std::char_traits<char>::eof() && c != '\n'; c = in_.sbumpc()) {
            if (c == 0) return Result::Nul;
            if (line.size() >= longest_line) return Result::TooLong;
            line += static_cast<char>(c);
        }
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
        const std::size_t start = line.find_first_not_of(" \t");
        line.erase(0, start == std::string::npos ? line.size() : start);
        return Result::Line;
    }
    std::size_t number() const { return number_; }

private:
    std::streambuf& in_;
    std::size_t number_ = 0;
};

}  // namespace

std::vector<Diagnostic> check_dxf_file(const std::string& path)
{
    auto only = [](const std::string& message) {
        return std::vector<Diagnostic>{{Diagnostic::Severity::Error, "", message}};
    };
    std::ifstream in(path, std::ios::binary);
    if (!in) return only("cannot open " + path);
    char head[32] = {};
    in.read(head, sizeof head);
    const auto got = static_cast<std::size_t>(in.gcount());
    const std::string start(head, got);
    if (got == 0) return only("the file is empty");
    if (start.rfind("AutoCAD Binary DXF", 0) == 0)
        return only("a binary DXF, which is not supported: save the drawing as ASCII DXF");
    const bool utf16_bom =
        got >= 2 && ((start[0] == '\xFF' && start[1] == '\xFE') || (start[0] == '\xFE' && start[1] == '\xFF'));
    const bool utf16_le = got >= 4 && start[0] != '\0' && start[1] == '\0' && start[2] != '\0' && start[3] == '\0';
    const bool utf16_be = got >= 4 && start[0] == '\0' && start[1] != '\0' && start[2] == '\0' && start[3] != '\0';
    if (utf16_bom || utf16_le || utf16_be)
        return only("UTF-16 text, which is not supported: save the drawing as ASCII DXF (in UTF-8 or ANSI)");
    const auto nul = start.find('\0');  // binary data: said before its first line is taken for a group code
    if (nul != std::string::npos)
        return only("line " + std::to_string(1 + std::count(start.begin(), start.begin() + nul, '\n')) +
                    " holds a NUL byte: the file is not an ASCII DXF drawing (binary data?)");
    in.clear();
    in.seekg(0);

    Checker checker;
    Lines lines(*in.rdbuf());
    std::string code_text, value;
    while (!checker.full()) {
        Lines::Result r = lines.next(code_text);
        const std::size_t code_line = lines.number();
        if (r == Lines::Result::Line && code_line == 1 && code_text.rfind("\xEF\xBB\xBF", 0) == 0)
            code_text.erase(0, 3);  // a UTF-8 byte order mark
        if (r == Lines::Result::Line) r = lines.next(value);
        if (r == Lines::Result::End) break;
        if (r == Lines::Result::Nul) {
            checker.error("line " + std::to_string(lines.number()) +
                          " holds a NUL byte: the file is not an ASCII DXF drawing (binary data?)");
            break;
        }
        if (r == Lines::Result::TooLong) {
            checker.error("line " + std::to_string(lines.number()) + " is longer than " + std::to_string(longest_line) +
                          " characters, more than a DXF line holds: the file is not an ASCII DXF drawing, or it is "
                          "damaged");
            break;
        }
        const std::optional<long long> code = whole_number(code_text);
        if (!code || *code < -5 || *code > 1071) {
            checker.error("line " + std::to_string(code_line) + ": \"" + shown(code_text) +
                          "\" is not a DXF group code (a whole number from 0 to 1071): the file is not an ASCII DXF "
                          "drawing, or it is damaged");
            break;
        }
        checker.group(code_line, static_cast<int>(*code), value);
    }
    checker.finish();
    return checker.errors;
}

}  // namespace mcdda

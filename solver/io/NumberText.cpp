#include "io/NumberText.hpp"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <string>

namespace mcdda {

namespace {

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

}  // namespace

std::optional<double> decimal_number(std::string_view text, bool comma)
{
    // [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]
    std::size_t i = 0;
    const auto digits = [&] {
        const std::size_t start = i;
        while (i < text.size() && digit(text[i])) ++i;
        return i > start;
    };
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    bool mantissa = digits();
    if (i < text.size() && (text[i] == '.' || (comma && text[i] == ','))) {
        ++i;
        mantissa = digits() || mantissa;
    }
    if (!mantissa) return std::nullopt;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        if (!digits()) return std::nullopt;
    }
    if (i != text.size()) return std::nullopt;
    std::string plain(text);
    for (char& c : plain)
        if (c == ',') c = '.';
    return std::strtod(plain.c_str(), nullptr);  // ±HUGE_VAL beyond the range of a double
}

std::optional<long long> whole_number(std::string_view text)
{
    std::size_t i = text.size() > 0 && (text[0] == '+' || text[0] == '-') ? 1 : 0;
    if (i == text.size()) return std::nullopt;
    for (std::size_t k = i; k < text.size(); ++k)
        if (!digit(text[k])) return std::nullopt;
    const std::string plain(text);
    errno = 0;
    const long long value = std::strtoll(plain.c_str(), nullptr, 10);
    if (errno == ERANGE) return std::nullopt;
    return value;
}

}  // namespace mcdda

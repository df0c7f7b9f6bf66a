#include "view/PictureText.hpp"

#include <cctype>
#include <cstdio>
#include <utility>

namespace mcdda::view {

namespace {

std::function<std::string(const char*)>& translator()
{
    static std::function<std::string(const char*)> installed;
    return installed;
}

char& decimal_point()
{
    static char point = '.';
    return point;
}

}  // namespace

std::string picture_text(const char* english) { return translator() ? translator()(english) : std::string(english); }

void set_picture_translator(std::function<std::string(const char*)> t) { translator() = std::move(t); }

void set_picture_decimal_point(char point) { decimal_point() = point; }

std::string picture_number(const char* printf_format, double value)
{
    char text[64];
    std::snprintf(text, sizeof text, printf_format, value);
    return with_picture_decimals(text);
}

std::string with_picture_decimals(std::string text)
{
    const char point = decimal_point();
    if (point == '.') return text;
    auto digit = [&](std::size_t i) { return i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); };
    for (std::size_t i = 1; i < text.size(); ++i)
        if (text[i] == '.' && digit(i - 1) && (digit(i + 1) || (i + 1 < text.size() && text[i + 1] == 'e')))
            text[i] = point;
    return text;
}

}  // namespace mcdda::view

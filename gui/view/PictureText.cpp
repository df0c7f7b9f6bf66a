#include "view/PictureText.hpp"

#include <utility>

namespace mcdda::view {

namespace {

std::function<std::string(const char*)>& translator()
{
    static std::function<std::string(const char*)> installed;
    return installed;
}

}  // namespace

std::string picture_text(const char* english) { return translator() ? translator()(english) : std::string(english); }

void set_picture_translator(std::function<std::string(const char*)> t) { translator() = std::move(t); }

}  // namespace mcdda::view

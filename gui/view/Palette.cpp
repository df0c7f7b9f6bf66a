#include "view/Palette.hpp"

namespace mcdda::view {

Rgb material_color(int index)
{
    // Light tones (ColorBrewer Paired/Set3 family) that are told apart easily and keep dark
    // mesh lines readable on top of them.
    static constexpr Rgb colors[] = {
        {0.651, 0.808, 0.890},  // light blue
        {0.698, 0.875, 0.541},  // light green
        {0.992, 0.749, 0.435},  // light orange
        {0.792, 0.698, 0.839},  // lavender
        {0.898, 0.847, 0.741},  // sand
        {0.553, 0.827, 0.780},  // teal
        {1.000, 1.000, 0.600},  // light yellow
        {0.745, 0.729, 0.855},  // grey violet
    };
    constexpr int count = static_cast<int>(sizeof(colors) / sizeof(colors[0]));
    if (index < 0) return palette::unassigned;
    return colors[index % count];
}

}  // namespace mcdda::view

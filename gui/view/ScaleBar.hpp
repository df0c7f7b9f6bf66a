#pragma once
/// \file ScaleBar.hpp
/// Rulers along the left and bottom edges of a picture (x and y in metres, at round values over
/// the model's extent) and a scale bar of a round length in the bottom-left corner. They are a
/// VTK prop worked out again from the camera at every render, so they stay right while the
/// desktop view zooms and pans.

#include "view/SceneGeometry.hpp"

#include <vtkSmartPointer.h>

class vtkProp;
class vtkRenderer;

namespace mcdda::view {

/// Pixels the rulers take from the left and bottom edges at `dpi`: fit_camera keeps them free.
int axes_left_pixels(double dpi);
int axes_bottom_pixels(double dpi);

/// Adds the rulers for the model box `box` and the scale bar to `renderer`, in black.
void add_axes_and_scale_bar(vtkRenderer* renderer, const Box& box, double dpi);

/// The same as a prop of its own whose box may change (set_axes_box): the desktop view's rulers
/// while the first region is drawn, before the model has an extent. An empty box draws nothing.
vtkSmartPointer<vtkProp> make_axes_and_scale_bar(const Box& box, double dpi);
void set_axes_box(vtkProp* axes, const Box& box);

/// 1, 2 or 5 times a power of ten near `raw` (round spacings and lengths).
double nice_step(double raw);

}  // namespace mcdda::view

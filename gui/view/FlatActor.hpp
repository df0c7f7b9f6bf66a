#pragma once
/// \file FlatActor.hpp
/// An unlit actor for 2-D lines and areas: colours come out exactly as in the palette. Shared by
/// the model and the result scenes.

#include "view/Palette.hpp"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;

namespace mcdda::view {

/// Actor drawing `data` in one colour, without lighting, with lines `line_width` pixels wide.
vtkSmartPointer<vtkActor> flat_actor(vtkPolyData* data, const Rgb& color, double line_width);

}  // namespace mcdda::view

#pragma once
/// \file LocalisedScalarBar.hpp
/// VTK's colour scale with its labels written in the pictures' decimal separator
/// (view/PictureText.hpp): VTK formats them with printf, in the C locale, so a German picture
/// would read "0.5" on its scale beside "0,5" in its title.

#include <vtkScalarBarActor.h>

#include <string>
#include <vector>

namespace mcdda::view {

class LocalisedScalarBar : public vtkScalarBarActor {
public:
    static LocalisedScalarBar* New();
    vtkTypeMacro(LocalisedScalarBar, vtkScalarBarActor);

    /// The label texts as last laid out (by a render).
    std::vector<std::string> label_texts() const;

protected:
    LocalisedScalarBar() = default;
    void LayoutTicks() override;
};

}  // namespace mcdda::view

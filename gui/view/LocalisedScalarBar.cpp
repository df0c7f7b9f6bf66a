#include "view/LocalisedScalarBar.hpp"
#include "view/PictureText.hpp"

#include <vtkObjectFactory.h>
#include <vtkScalarBarActorInternal.h>
#include <vtkTextActor.h>

namespace mcdda::view {

vtkStandardNewMacro(LocalisedScalarBar);

void LocalisedScalarBar::LayoutTicks()
{
    vtkScalarBarActor::LayoutTicks();  // creates the label actors, formatted by printf
    for (const auto& label : this->P->TextActors)
        if (label && label->GetInput()) label->SetInput(with_picture_decimals(label->GetInput()).c_str());
}

std::vector<std::string> LocalisedScalarBar::label_texts() const
{
    std::vector<std::string> texts;
    for (const auto& label : this->P->TextActors)
        if (label && label->GetInput()) texts.emplace_back(label->GetInput());
    return texts;
}

}  // namespace mcdda::view

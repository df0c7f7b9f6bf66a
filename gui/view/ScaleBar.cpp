#include "view/ScaleBar.hpp"
#include "view/PictureText.hpp"

#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProp.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkViewport.h>
#include <vtkWindow.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace mcdda::view {

namespace {

int scaled(double points, double dpi) { return static_cast<int>(std::lround(points * dpi / 72.0)); }

std::string number_text(double v, double step)
{
    if (std::abs(v) < 1e-9 * step) v = 0.0;  // no "-0"
    return picture_number("%g", v);
}

/// The rulers and the scale bar as a prop: rebuilt from the camera before each render (as VTK's
/// legend scale actor does), drawn as 2-D lines and texts over the picture.
class AxesOverlay : public vtkProp {
public:
    static AxesOverlay* New();
    vtkTypeMacro(AxesOverlay, vtkProp);

    Box box;
    double dpi = 72.0;

    int RenderOpaqueGeometry(vtkViewport* viewport) override
    {
        build(viewport);
        int n = 0;
        for (auto& a : parts_) n += a->RenderOpaqueGeometry(viewport);
        return n;
    }
    int RenderOverlay(vtkViewport* viewport) override
    {
        int n = 0;
        for (auto& a : parts_) n += a->RenderOverlay(viewport);
        return n;
    }
    vtkTypeBool HasTranslucentPolygonalGeometry() override { return 0; }
    void ReleaseGraphicsResources(vtkWindow* window) override
    {
        for (auto& a : parts_) a->ReleaseGraphicsResources(window);
    }

private:
    void build(vtkViewport* viewport)
    {
        for (auto& a : parts_) a->ReleaseGraphicsResources(viewport->GetVTKWindow());
        parts_.clear();
        auto* renderer = vtkRenderer::SafeDownCast(viewport);
        if (renderer == nullptr || !box.valid()) return;
        // The window's resolution when it has one: the desktop view's rulers are made before its
        // window knows the screen's pixel ratio (they were drawn at 72 dpi on a 144 dpi screen).
        if (vtkWindow* window = viewport->GetVTKWindow(); window != nullptr && window->GetDPI() > 0)
            dpi = window->GetDPI();
        const int* size = renderer->GetSize();
        const double w = std::max(1, size[0]), h = std::max(1, size[1]);
        vtkCamera* camera = renderer->GetActiveCamera();
        double focal[3];
        camera->GetFocalPoint(focal);
        const double mpp = 2.0 * camera->GetParallelScale() / h;  // metres per pixel
        if (!(mpp > 0.0)) return;
        auto px = [&](double x) { return w / 2 + (x - focal[0]) / mpp; };
        auto py = [&](double y) { return h / 2 + (y - focal[1]) / mpp; };
        const double left = scaled(50, dpi), bottom = scaled(38, dpi), tick = scaled(5, dpi);

        vtkNew<vtkPoints> points;
        vtkNew<vtkCellArray> lines;
        auto line = [&](double x0, double y0, double x1, double y1) {
            const vtkIdType ids[2] = {points->InsertNextPoint(x0, y0, 0), points->InsertNextPoint(x1, y1, 0)};
            lines->InsertNextCell(2, ids);
        };
        auto text = [&](const std::string& s, double x, double y, bool right_aligned, bool above) {
            vtkNew<vtkTextActor> t;
            t->SetInput(s.c_str());
            vtkTextProperty* p = t->GetTextProperty();
            p->SetColor(0.0, 0.0, 0.0);
            p->SetFontFamilyToArial();
            p->SetFontSize(scaled(10, dpi));
            p->SetJustification(right_aligned ? VTK_TEXT_RIGHT : VTK_TEXT_CENTERED);
            p->SetVerticalJustification(above ? VTK_TEXT_BOTTOM : right_aligned ? VTK_TEXT_CENTERED : VTK_TEXT_TOP);
            t->SetDisplayPosition(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)));
            parts_.push_back(vtkSmartPointer<vtkActor2D>(t.GetPointer()));
        };

        // Rulers over the model's extent where it is in sight, ticks at round coordinates.
        const double x0 = std::max(box.xmin, focal[0] - (w / 2 - left) * mpp), x1 = std::min(box.xmax, focal[0] + w / 2 * mpp);
        const double y0 = std::max(box.ymin, focal[1] - (h / 2 - bottom) * mpp), y1 = std::min(box.ymax, focal[1] + h / 2 * mpp);
        if (x1 > x0) {
            line(px(x0), bottom, px(x1), bottom);
            const double step = nice_step((x1 - x0) / 6.0);
            for (double x = std::ceil(x0 / step - 1e-9) * step; x <= x1 + 1e-9 * step; x += step) {
                line(px(x), bottom, px(x), bottom - tick);
                text(number_text(x, step), px(x), bottom - tick - 1, false, false);
            }
        }
        if (y1 > y0) {
            line(left, py(y0), left, py(y1));
            const double step = nice_step((y1 - y0) / 6.0);
            for (double y = std::ceil(y0 / step - 1e-9) * step; y <= y1 + 1e-9 * step; y += step) {
                line(left, py(y), left - tick, py(y));
                text(number_text(y, step), left - tick - 2, py(y), true, false);
            }
        }
        // The scale bar: a round length, about a fifth of the picture wide, in the corner.
        const double length = nice_step(0.2 * (w - left) * mpp);
        const double bx = left + scaled(12, dpi), by = bottom + scaled(10, dpi), bl = length / mpp;
        const double bh = scaled(4, dpi);
        for (double k = 0; k < bh; k += 1.0) line(bx, by + k, bx + bl, by + k);  // a solid bar
        line(bx, by - tick / 2, bx, by + bh + tick / 2);
        line(bx + bl, by - tick / 2, bx + bl, by + bh + tick / 2);
        text(number_text(length, length) + " m", bx + bl / 2, by + bh + 2, false, true);

        vtkNew<vtkPolyData> data;
        data->SetPoints(points);
        data->SetLines(lines);
        vtkNew<vtkPolyDataMapper2D> mapper;
        mapper->SetInputData(data);
        vtkNew<vtkActor2D> drawn;
        drawn->SetMapper(mapper);
        drawn->GetProperty()->SetColor(0.0, 0.0, 0.0);
        drawn->GetProperty()->SetLineWidth(std::max(1.0, dpi / 72.0));
        parts_.insert(parts_.begin(), vtkSmartPointer<vtkActor2D>(drawn.GetPointer()));
    }

    std::vector<vtkSmartPointer<vtkActor2D>> parts_;
};

vtkStandardNewMacro(AxesOverlay);

}  // namespace

double nice_step(double raw)
{
    if (!(raw > 0.0) || !std::isfinite(raw)) return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / decade;
    return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * decade;
}

int axes_left_pixels(double dpi) { return scaled(56, dpi); }

int axes_bottom_pixels(double dpi) { return scaled(72, dpi); }

void add_axes_and_scale_bar(vtkRenderer* renderer, const Box& box, double dpi)
{
    if (renderer == nullptr || !box.valid()) return;
    renderer->AddViewProp(make_axes_and_scale_bar(box, dpi));
}

vtkSmartPointer<vtkProp> make_axes_and_scale_bar(const Box& box, double dpi)
{
    vtkNew<AxesOverlay> overlay;
    overlay->box = box;
    overlay->dpi = dpi;
    return overlay.GetPointer();
}

void set_axes_box(vtkProp* axes, const Box& box)
{
    if (auto* overlay = AxesOverlay::SafeDownCast(axes)) overlay->box = box;
}

}  // namespace mcdda::view

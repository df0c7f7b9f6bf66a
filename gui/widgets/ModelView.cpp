#include "widgets/ModelView.hpp"

#include "tools/ViewTool.hpp"
#include "view/Palette.hpp"
#include "view/PictureText.hpp"
#include "view/ScaleBar.hpp"
#include "view/SceneGeometry.hpp"

#include <QEvent>
#include <QGuiApplication>
#include <QCoreApplication>
#include <QLocale>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QResizeEvent>
#include <QWheelEvent>
#include <QtGui/qguiapplication_platform.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProp.h>
#include <vtkProperty.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>

namespace mcdda::gui {

struct ModelView::Impl {
    vtkNew<vtkRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkRenderer> overlay;  ///< layer 1, same camera: the rubber band stays on top
    vtkNew<vtkPolyData> preview_data;
    vtkNew<vtkActor> preview_halo_actor;  ///< white under an emphasised (query) rubber band
    vtkNew<vtkActor> preview_actor;
    std::vector<Point2> preview;
    /// Rulers over the picture while the first region is drawn (the model has no extent yet, so
    /// the picture of the model has none).
    vtkSmartPointer<vtkProp> drawing_axes;
    vtkNew<vtkPolyData> query_data;  ///< the query line and its end markers
    vtkNew<vtkActor> query_halo_actor;
    vtkNew<vtkActor> query_actor;
    bool query_set = false;
    Point2 query_from, query_to;
    vtkNew<vtkPolyData> marker_data;  ///< where a click would land (snapped)
    vtkNew<vtkActor> marker_actor;
    bool marker_shown = false;
    Point2 marker;
    vtkNew<vtkPolyData> grid_data;  ///< the snapping grid, rebuilt for the visible area
    vtkNew<vtkActor> grid_actor;
    double grid_spacing = 0.0;      ///< 0: no grid
    ViewTool* tool = nullptr;
    std::shared_ptr<const Preprocessed> scene;
    view::SceneOptions options;
    std::shared_ptr<const ResultSnapshot> result;  ///< shown instead of the model when set
    QString result_file;  ///< a saved step shown instead of the model when set (and no snapshot)
    view::ResultOptions result_options;
    view::ResultProbe probe;  ///< what the result picture shows where (empty for the model)
    view::ResultInfo info;    ///< what the result picture drew (scale, inverted elements)
    bool window_ready = false;    ///< VTK was given our native window
    bool camera_touched = false;  ///< the user navigated since the last fit: resizing keeps the view
    bool panning = false;
    QPointF last_pos;
};

ModelView::ModelView(QWidget* parent) : QWidget(parent), impl_(std::make_unique<Impl>())
{
    // Legend texts in the language of the window (the view library itself knows no Qt).
    view::set_picture_translator([](const char* english) {
        return QCoreApplication::translate("mcdda::view", english).toStdString();
    });
    // Numbers in pictures with the language's decimal separator, as in the forms.
    const QString point = QLocale().decimalPoint();
    view::set_picture_decimal_point(point.size() == 1 && point.at(0).unicode() < 128 ? point.at(0).toLatin1() : '.');
    // Native-child-window route (docs/architecture.md, platform facts): our own X window that VTK draws into; Qt must not paint it.
    setAttribute(Qt::WA_NativeWindow);
    setAttribute(Qt::WA_PaintOnScreen);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(64, 64);

    impl_->window->AddRenderer(impl_->renderer);
    impl_->window->SetMultiSamples(0);  // an X visual with multisampling is not guaranteed
    impl_->renderer->SetBackground(view::palette::background.data());
    impl_->renderer->GetActiveCamera()->ParallelProjectionOn();

    impl_->window->SetNumberOfLayers(2);
    impl_->overlay->SetLayer(1);
    impl_->overlay->InteractiveOff();
    impl_->window->AddRenderer(impl_->overlay);
    // A halo is drawn before (under) its line: same depth, and VTK draws in the order added.
    auto halo = [](vtkActor* actor, vtkPolyData* data, float line, float point) {
        vtkNew<vtkPolyDataMapper> m;
        m->SetInputData(data);
        actor->SetMapper(m);
        const view::Rgb& c = view::palette::query_halo;
        actor->GetProperty()->SetColor(c[0], c[1], c[2]);
        actor->GetProperty()->SetLineWidth(line);
        actor->GetProperty()->SetPointSize(point);
        actor->GetProperty()->LightingOff();
        actor->VisibilityOff();
    };
    halo(impl_->preview_halo_actor, impl_->preview_data, 7.0f, 15.0f);
    impl_->overlay->AddActor(impl_->preview_halo_actor);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(impl_->preview_data);
    impl_->preview_actor->SetMapper(mapper);
    impl_->preview_actor->GetProperty()->SetColor(0.0, 0.45, 0.85);
    impl_->preview_actor->GetProperty()->SetLineWidth(2.0f);
    impl_->preview_actor->GetProperty()->SetPointSize(6.0f);
    impl_->preview_actor->GetProperty()->LightingOff();
    impl_->preview_actor->VisibilityOff();
    impl_->overlay->AddActor(impl_->preview_actor);
    impl_->drawing_axes = view::make_axes_and_scale_bar(view::Box{}, 72.0);
    impl_->overlay->AddViewProp(impl_->drawing_axes);

    halo(impl_->query_halo_actor, impl_->query_data, 7.0f, 15.0f);
    impl_->overlay->AddActor(impl_->query_halo_actor);
    vtkNew<vtkPolyDataMapper> query_mapper;
    query_mapper->SetInputData(impl_->query_data);
    impl_->query_actor->SetMapper(query_mapper);
    {
        const view::Rgb& c = view::palette::query_line;
        impl_->query_actor->GetProperty()->SetColor(c[0], c[1], c[2]);
    }
    impl_->query_actor->GetProperty()->SetLineWidth(3.0f);
    impl_->query_actor->GetProperty()->SetPointSize(9.0f);
    impl_->query_actor->GetProperty()->LightingOff();
    impl_->query_actor->VisibilityOff();
    impl_->overlay->AddActor(impl_->query_actor);

    vtkNew<vtkPolyDataMapper> marker_mapper;
    marker_mapper->SetInputData(impl_->marker_data);
    impl_->marker_actor->SetMapper(marker_mapper);
    {
        const view::Rgb& c = view::palette::snap_marker;
        impl_->marker_actor->GetProperty()->SetColor(c[0], c[1], c[2]);
    }
    impl_->marker_actor->GetProperty()->SetPointSize(9.0f);
    impl_->marker_actor->GetProperty()->LightingOff();
    impl_->marker_actor->VisibilityOff();
    impl_->overlay->AddActor(impl_->marker_actor);

    vtkNew<vtkPolyDataMapper> grid_mapper;
    grid_mapper->SetInputData(impl_->grid_data);
    impl_->grid_actor->SetMapper(grid_mapper);
    {
        const view::Rgb& c = view::palette::grid;
        impl_->grid_actor->GetProperty()->SetColor(c[0], c[1], c[2]);
    }
    impl_->grid_actor->GetProperty()->SetOpacity(0.35);
    impl_->grid_actor->GetProperty()->SetLineWidth(1.0f);
    impl_->grid_actor->GetProperty()->LightingOff();
    impl_->grid_actor->VisibilityOff();
    impl_->overlay->AddActor(impl_->grid_actor);
}

ModelView::~ModelView()
{
    // Release VTK's GL context while the native window still exists (QWidget's destructor
    // destroys it after this body).
    impl_->window->Finalize();
}

bool ModelView::ensureWindow()
{
    if (impl_->window_ready) return true;
    if (!isVisible()) return false;
    auto* x11 = qGuiApp->nativeInterface<QNativeInterface::QX11Application>();
    if (x11 == nullptr || x11->display() == nullptr) {
        static bool warned = false;
        if (!warned) qWarning("ModelView: VTK can only draw into X11 windows; run with QT_QPA_PLATFORM=xcb");
        warned = true;
        return false;
    }
    const WId id = winId();
    if (id == 0) return false;
    impl_->window->SetDisplayId(x11->display());
    impl_->window->SetWindowId(reinterpret_cast<void*>(id));
    impl_->window->SetDPI(static_cast<int>(std::lround(72.0 * devicePixelRatioF())));
    syncSize();
    impl_->window_ready = true;
    return true;
}

void ModelView::syncSize()
{
    const qreal ratio = devicePixelRatioF();
    impl_->window->SetSize(std::max(1, qRound(width() * ratio)), std::max(1, qRound(height() * ratio)));
}

void ModelView::syncOverlay()
{
    // The overlay's own camera follows the model's but fits its clipping range to the rubber band.
    impl_->overlay->GetActiveCamera()->DeepCopy(impl_->renderer->GetActiveCamera());
    rebuildGrid();  // it follows pan and zoom
    const bool query = queryLineShown();
    impl_->query_actor->SetVisibility(query);
    impl_->query_halo_actor->SetVisibility(query);
    if (!impl_->preview.empty() || impl_->marker_shown || impl_->grid_spacing > 0.0 || query)
        impl_->overlay->ResetCameraClippingRange();
}

void ModelView::renderNow()
{
    if (!ensureWindow()) return;
    syncOverlay();
    impl_->window->Render();
}

void ModelView::rebuildGrid()
{
    const double spacing = impl_->grid_spacing;
    impl_->grid_actor->SetVisibility(spacing > 0.0);
    if (!(spacing > 0.0) || width() <= 0 || height() <= 0) return;
    // Every n-th line when zoomed out, so lines stay at least 12 pixels apart.
    double step = spacing;
    const double m = metresPerPixel();
    while (m > 0.0 && step / m < 12.0) step *= 2.0;
    const QPointF a = toModel(QPointF(0, height())), b = toModel(QPointF(width(), 0));
    const double x0 = std::floor(a.x() / step) * step, y0 = std::floor(a.y() / step) * step;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    auto line = [&](double ax, double ay, double bx, double by) {
        const vtkIdType ids[2] = {points->InsertNextPoint(ax, ay, 0.0), points->InsertNextPoint(bx, by, 0.0)};
        lines->InsertNextCell(2, ids);
    };
    for (double x = x0; x <= b.x(); x += step) line(x, a.y(), x, b.y());
    for (double y = y0; y <= b.y(); y += step) line(a.x(), y, b.x(), y);
    impl_->grid_data->SetPoints(points);
    impl_->grid_data->SetLines(lines);
    impl_->grid_data->Modified();
}

void ModelView::setGridSpacing(double metres)
{
    impl_->grid_spacing = metres > 0.0 && std::isfinite(metres) ? metres : 0.0;
    update();
}

double ModelView::gridSpacing() const { return impl_->grid_spacing; }

void ModelView::showSnapMarker(const Point2& p)
{
    impl_->marker_shown = true;
    impl_->marker = p;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(p.x, p.y, 0.0);
    vtkNew<vtkCellArray> verts;
    const vtkIdType id = 0;
    verts->InsertNextCell(1, &id);
    impl_->marker_data->SetPoints(points);
    impl_->marker_data->SetVerts(verts);
    impl_->marker_data->Modified();
    impl_->marker_actor->VisibilityOn();
    update();
}

void ModelView::hideSnapMarker()
{
    if (!impl_->marker_shown) return;
    impl_->marker_shown = false;
    impl_->marker_actor->VisibilityOff();
    update();
}

bool ModelView::snapMarker(Point2* p) const
{
    if (impl_->marker_shown && p) *p = impl_->marker;
    return impl_->marker_shown;
}

void ModelView::rebuild(bool keep_camera)
{
    vtkNew<vtkCamera> saved;
    saved->DeepCopy(impl_->renderer->GetActiveCamera());

    syncSize();
    impl_->renderer->RemoveAllViewProps();
    impl_->probe = view::ResultProbe{};
    impl_->info = view::ResultInfo{};
    bool drawn = false;
    if (impl_->scene && (impl_->result || !impl_->result_file.isEmpty())) {
        try {
            if (impl_->result)
                view::build_result_scene(impl_->renderer, *impl_->scene, *impl_->result, impl_->result_options,
                                         &impl_->probe, &impl_->info);
            else
                view::build_result_scene(impl_->renderer, *impl_->scene, impl_->result_file.toStdString(),
                                         impl_->result_options, &impl_->probe, &impl_->info);
            drawn = true;
        } catch (const std::exception& e) {
            qWarning("ModelView: cannot show the result: %s", e.what());
            impl_->result.reset();
            impl_->result_file.clear();
            impl_->probe = view::ResultProbe{};
            impl_->renderer->RemoveAllViewProps();
        }
    }
    if (impl_->scene && !drawn) view::build_model_scene(impl_->renderer, *impl_->scene, impl_->options);
    if (keep_camera) {
        impl_->renderer->GetActiveCamera()->DeepCopy(saved);
        impl_->renderer->ResetCameraClippingRange();
    }
    update();
}

void ModelView::setScene(const Preprocessed& p, bool keep_camera)
{
    setScene(std::make_shared<const Preprocessed>(p), keep_camera);
}

void ModelView::setScene(std::shared_ptr<const Preprocessed> p, bool keep_camera)
{
    impl_->scene = std::move(p);
    impl_->result.reset();
    impl_->result_file.clear();
    if (!keep_camera) impl_->camera_touched = false;
    rebuild(keep_camera);
}

bool ModelView::setResult(std::shared_ptr<const ResultSnapshot> snapshot, const view::ResultOptions& options)
{
    impl_->result = std::move(snapshot);
    impl_->result_file.clear();
    impl_->result_options = options;
    rebuild(impl_->camera_touched);  // a view nobody navigated in stays fitted (legend included)
    return impl_->result != nullptr;
}

bool ModelView::setResultFile(const QString& vtu_path, const view::ResultOptions& options)
{
    impl_->result.reset();
    impl_->result_file = vtu_path;
    impl_->result_options = options;
    rebuild(impl_->camera_touched);
    return !impl_->result_file.isEmpty();
}

void ModelView::clearResult()
{
    if (!impl_->result && impl_->result_file.isEmpty()) return;
    impl_->result.reset();
    impl_->result_file.clear();
    rebuild(impl_->camera_touched);
}

std::shared_ptr<const ResultSnapshot> ModelView::result() const { return impl_->result; }

QString ModelView::resultFile() const { return impl_->result_file; }

const view::ResultProbe& ModelView::resultProbe() const { return impl_->probe; }

const view::ResultInfo& ModelView::resultInfo() const { return impl_->info; }

QString ModelView::resultValueAt(const QPointF& model_pos) const
{
    return QString::fromStdString(impl_->probe.describe(model_pos.x(), model_pos.y()));
}

void ModelView::clearScene()
{
    impl_->scene.reset();
    impl_->result.reset();
    impl_->result_file.clear();
    impl_->camera_touched = false;
    rebuild(false);
}

std::shared_ptr<const Preprocessed> ModelView::scene() const { return impl_->scene; }

void ModelView::setSceneOptions(const view::SceneOptions& options)
{
    impl_->options = options;
    rebuild(true);
}

view::SceneOptions ModelView::sceneOptions() const { return impl_->options; }

QImage ModelView::grabFrame()
{
    if (!ensureWindow()) return {};
    syncSize();
    syncOverlay();
    impl_->window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(impl_->window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkImageData* image = grab->GetOutput();
    int dims[3] = {0, 0, 0};
    image->GetDimensions(dims);
    if (dims[0] <= 0 || dims[1] <= 0) return {};
    const auto* pixels = static_cast<const unsigned char*>(image->GetScalarPointer());
    QImage frame(dims[0], dims[1], QImage::Format_RGB888);
    const auto row_bytes = static_cast<std::size_t>(dims[0]) * 3;
    for (int y = 0; y < dims[1]; ++y)  // VTK's rows start at the bottom
        std::memcpy(frame.scanLine(dims[1] - 1 - y), pixels + static_cast<std::size_t>(y) * row_bytes, row_bytes);
    return frame;
}

double ModelView::metresPerPixel() const
{
    return 2.0 * impl_->renderer->GetActiveCamera()->GetParallelScale() / std::max(1, height());
}

QPointF ModelView::toModel(const QPointF& widget_pos) const
{
    double focal[3];
    impl_->renderer->GetActiveCamera()->GetFocalPoint(focal);
    const double m = metresPerPixel();
    return {focal[0] + (widget_pos.x() - 0.5 * width()) * m, focal[1] - (widget_pos.y() - 0.5 * height()) * m};
}

QPointF ModelView::toWidget(const QPointF& model_pos) const
{
    double focal[3];
    impl_->renderer->GetActiveCamera()->GetFocalPoint(focal);
    const double m = metresPerPixel();
    return {0.5 * width() + (model_pos.x() - focal[0]) / m, 0.5 * height() - (model_pos.y() - focal[1]) / m};
}

void ModelView::setTool(ViewTool* tool)
{
    if (impl_->tool == tool) return;
    if (impl_->tool) impl_->tool->cancel();
    hideSnapMarker();
    impl_->tool = tool;
    impl_->panning = false;
    if (tool) setCursor(tool->cursorShape()); else unsetCursor();
}

ViewTool* ModelView::tool() const { return impl_->tool; }

void ModelView::setQueryLine(const Point2& from, const Point2& to)
{
    impl_->query_set = true;
    impl_->query_from = from;
    impl_->query_to = to;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(from.x, from.y, 0.0);
    points->InsertNextPoint(to.x, to.y, 0.0);
    const vtkIdType ends[2] = {0, 1};
    vtkNew<vtkCellArray> line;
    line->InsertNextCell(2, ends);
    vtkNew<vtkCellArray> markers;  // the ends, where the plot's distance starts and stops
    markers->InsertNextCell(1, &ends[0]);
    markers->InsertNextCell(1, &ends[1]);
    impl_->query_data->SetPoints(points);
    impl_->query_data->SetLines(line);
    impl_->query_data->SetVerts(markers);
    impl_->query_data->Modified();
    update();
}

void ModelView::clearQueryLine()
{
    if (!impl_->query_set) return;
    impl_->query_set = false;
    impl_->query_data->Initialize();
    impl_->query_data->Modified();
    update();
}

bool ModelView::queryLine(Point2* from, Point2* to) const
{
    if (impl_->query_set) {
        if (from) *from = impl_->query_from;
        if (to) *to = impl_->query_to;
    }
    return impl_->query_set;
}

bool ModelView::queryLineShown() const
{
    return impl_->query_set && impl_->scene && (impl_->result || !impl_->result_file.isEmpty());
}

void ModelView::setPreview(const std::vector<Point2>& points, bool closed, bool emphasised)
{
    impl_->preview = points;
    vtkNew<vtkPoints> pts;
    for (const Point2& p : points) pts->InsertNextPoint(p.x, p.y, 0.0);
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkCellArray> verts;
    const auto n = static_cast<vtkIdType>(points.size());
    for (vtkIdType i = 0; i < n; ++i) verts->InsertNextCell(1, &i);
    if (n >= 2) {
        std::vector<vtkIdType> ids;
        for (vtkIdType i = 0; i < n; ++i) ids.push_back(i);
        if (closed && n >= 3) ids.push_back(0);
        lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }
    impl_->preview_data->SetPoints(pts);
    impl_->preview_data->SetVerts(verts);
    impl_->preview_data->SetLines(lines);
    impl_->preview_data->Modified();
    impl_->preview_actor->SetVisibility(n > 0);
    impl_->preview_halo_actor->SetVisibility(n > 0 && emphasised);
    const view::Rgb plain{0.0, 0.45, 0.85};
    const view::Rgb& c = emphasised ? view::palette::query_line : plain;
    impl_->preview_actor->GetProperty()->SetColor(c[0], c[1], c[2]);
    impl_->preview_actor->GetProperty()->SetLineWidth(emphasised ? 3.0f : 2.0f);
    impl_->preview_actor->GetProperty()->SetPointSize(emphasised ? 9.0f : 6.0f);
    const bool model_empty = !impl_->scene || !view::model_box(*impl_->scene).valid();
    view::Box everywhere;  // the rulers mark whatever is in sight
    if (model_empty && n > 0) everywhere = {-1e300, -1e300, 1e300, 1e300};
    view::set_axes_box(impl_->drawing_axes, everywhere);
    update();
}

void ModelView::keepInView(const std::vector<Point2>& points)
{
    if (points.empty() || width() <= 0 || height() <= 0) return;
    // The rulers take the left and bottom edges: a point under them is not in sight.
    const double dpi = impl_->window->GetDPI() > 0 ? impl_->window->GetDPI() : 72.0;
    const QRectF shown(QPointF(view::axes_left_pixels(dpi), 0),
                       QPointF(width(), height() - view::axes_bottom_pixels(dpi)));
    view::Box box;
    bool outside = false;
    for (const Point2& p : points) {
        box.add(p);
        outside = outside || !shown.contains(toWidget(QPointF(p.x, p.y)));
    }
    if (!outside) return;
    // What is in sight stays in sight (the rest of the model), with the points added.
    const QPointF low = toModel(shown.bottomLeft()), high = toModel(shown.topRight());
    box.add({low.x(), low.y()});
    box.add({high.x(), high.y()});
    showBox(box.xmin, box.ymin, box.xmax, box.ymax);
}

void ModelView::clearPreview() { setPreview({}, false); }

std::vector<Point2> ModelView::preview() const { return impl_->preview; }

void ModelView::showBox(double xmin, double ymin, double xmax, double ymax)
{
    syncSize();
    vtkCamera* camera = impl_->renderer->GetActiveCamera();
    const double cx = 0.5 * (xmin + xmax), cy = 0.5 * (ymin + ymax);
    const double wx = std::max(1e-6, xmax - xmin), wy = std::max(1e-6, ymax - ymin);
    const double aspect = static_cast<double>(std::max(1, width())) / std::max(1, height());
    const double half = 1.05 * std::max(0.5 * wy, 0.5 * wx / aspect);
    const double distance = 10.0 * std::max(wx, wy);
    camera->SetFocalPoint(cx, cy, 0.0);
    camera->SetPosition(cx, cy, distance);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(half);
    impl_->renderer->ResetCameraClippingRange();
    double range[2];
    camera->GetClippingRange(range);
    camera->SetClippingRange(std::min(range[0], 0.5 * distance), std::max(range[1], 2.0 * distance));
    impl_->camera_touched = true;
    update();
}

void ModelView::fitView()
{
    syncSize();
    static const Preprocessed empty;
    view::fit_camera(impl_->renderer, impl_->scene ? *impl_->scene : empty, impl_->options);
    impl_->camera_touched = false;
    update();
}

void ModelView::ensureRegionsVisible()
{
    if (!impl_->scene) return;
    const QRectF shown(QPointF(0, 0), QSizeF(size()));
    for (const Region& region : impl_->scene->model.regions)
        for (const Point2& p : region.boundary)
            if (!shown.contains(toWidget(QPointF(p.x, p.y)))) {
                fitView();
                return;
            }
}

void ModelView::zoomAt(const QPointF& widget_pos, double factor)
{
    if (!(factor > 0.0) || !std::isfinite(factor)) return;
    vtkCamera* camera = impl_->renderer->GetActiveCamera();
    const double scale = camera->GetParallelScale() / factor;
    if (scale < 1e-9 || scale > 1e12) return;  // keep the numbers meaningful
    const QPointF anchor = toModel(widget_pos);
    double focal[3], position[3];
    camera->GetFocalPoint(focal);
    camera->GetPosition(position);
    const double fx = anchor.x() + (focal[0] - anchor.x()) / factor;
    const double fy = anchor.y() + (focal[1] - anchor.y()) / factor;
    camera->SetFocalPoint(fx, fy, focal[2]);
    camera->SetPosition(fx, fy, position[2]);
    camera->SetParallelScale(scale);
    impl_->renderer->ResetCameraClippingRange();
    impl_->camera_touched = true;
    update();
}

void ModelView::panBy(const QPointF& pixels)
{
    vtkCamera* camera = impl_->renderer->GetActiveCamera();
    const double m = metresPerPixel();
    double focal[3], position[3];
    camera->GetFocalPoint(focal);
    camera->GetPosition(position);
    const double dx = -pixels.x() * m, dy = pixels.y() * m;
    camera->SetFocalPoint(focal[0] + dx, focal[1] + dy, focal[2]);
    camera->SetPosition(position[0] + dx, position[1] + dy, position[2]);
    impl_->renderer->ResetCameraClippingRange();
    impl_->camera_touched = true;
    update();
}

void ModelView::paintEvent(QPaintEvent*) { renderNow(); }

void ModelView::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    syncSize();
    if (!impl_->camera_touched) fitView();  // a freshly opened model stays fitted
    update();
}

void ModelView::mousePressEvent(QMouseEvent* event)
{
    bool left_free = event->button() == Qt::LeftButton;
    if (impl_->tool && event->button() == Qt::LeftButton) {
        setFocus(Qt::MouseFocusReason);
        left_free = !impl_->tool->pressed(event->position());
        if (!left_free) {
            event->accept();
            return;
        }
    }
    if (left_free || event->button() == Qt::MiddleButton) {
        impl_->panning = true;
        impl_->last_pos = event->position();
        setCursor(Qt::ClosedHandCursor);
        event->accept();
        return;
    }
    QWidget::mousePressEvent(event);
}

void ModelView::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF pos = event->position();
    if (impl_->panning) {
        panBy(pos - impl_->last_pos);
        impl_->last_pos = pos;
    }
    if (impl_->tool) impl_->tool->moved(pos);
    emit cursorMoved(toModel(pos));
    event->accept();
}

void ModelView::mouseReleaseEvent(QMouseEvent* event)
{
    if (impl_->panning && !(event->buttons() & (Qt::LeftButton | Qt::MiddleButton))) {
        impl_->panning = false;
        if (impl_->tool) setCursor(impl_->tool->cursorShape()); else unsetCursor();
    } else if (impl_->tool && event->button() == Qt::LeftButton) {
        impl_->tool->released(event->position());
    }
    event->accept();
}

void ModelView::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() == Qt::MiddleButton) {
        fitView();
        event->accept();
        return;
    }
    if (impl_->tool && event->button() == Qt::LeftButton) {
        impl_->tool->doubleClicked(event->position());
        event->accept();
        return;
    }
    QWidget::mouseDoubleClickEvent(event);
}

void ModelView::keyPressEvent(QKeyEvent* event)
{
    if (impl_->tool && impl_->tool->keyPressed(event->key())) {
        event->accept();
        return;
    }
    QWidget::keyPressEvent(event);
}

void ModelView::wheelEvent(QWheelEvent* event)
{
    const QPoint delta = event->angleDelta();
    const int steps = delta.y() != 0 ? delta.y() : delta.x();
    if (steps == 0) {
        event->ignore();
        return;
    }
    zoomAt(event->position(), std::pow(1.2, steps / 120.0));  // one notch: 20 %
    emit cursorMoved(toModel(event->position()));
    event->accept();
}

void ModelView::leaveEvent(QEvent* event)
{
    hideSnapMarker();
    emit cursorLeft();
    QWidget::leaveEvent(event);
}

bool ModelView::event(QEvent* event)
{
    if (event->type() == QEvent::WinIdChange && impl_->window_ready) {
        // Reparenting can give us a new native window: let VTK start again on the next paint.
        impl_->window->Finalize();
        impl_->window_ready = false;
    }
    return QWidget::event(event);
}

}  // namespace mcdda::gui

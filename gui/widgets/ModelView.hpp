#pragma once
/// \file ModelView.hpp
/// The model picture inside the Qt 6 window: a native child window that a plain
/// vtkRenderWindow draws into (docs/architecture.md), with 2-D navigation done here in Qt's
/// event handlers (drag pans, wheel zooms about the cursor). VTK stays in the .cpp.

#include "view/ResultSnapshot.hpp"
#include "view/ModelScene.hpp"
#include "view/ResultScene.hpp"

#include <QImage>
#include <QString>
#include <QPointF>
#include <QWidget>

#include <memory>
#include <vector>

namespace mcdda::gui {

class ViewTool;

class ModelView : public QWidget {
    Q_OBJECT

public:
    explicit ModelView(QWidget* parent = nullptr);
    ~ModelView() override;

    /// Shows `p` (copied; the view keeps it to rebuild the picture when options change). The
    /// camera is fitted to the model unless `keep_camera` is set (e.g. on reload).
    void setScene(const Preprocessed& p, bool keep_camera = false);
    /// The same without a copy.
    void setScene(std::shared_ptr<const Preprocessed> p, bool keep_camera = false);
    /// Removes the model: an empty background.
    void clearScene();
    /// The scene shown, or null.
    std::shared_ptr<const Preprocessed> scene() const;

    /// Shows a run's result on the current model's mesh instead of the model (e.g. the latest
    /// snapshot of a running analysis), coloured as `options` say; the camera is kept. Returns
    /// false (and keeps showing the model) when the snapshot does not fit the model or the
    /// field is unknown.
    bool setResult(std::shared_ptr<const ResultSnapshot> snapshot, const view::ResultOptions& options);
    /// The same from a saved step: the .vtu at `vtu_path` (written by a run of this model).
    /// Returns false (and keeps showing the model) when it cannot be read or does not fit.
    bool setResultFile(const QString& vtu_path, const view::ResultOptions& options);
    /// Back to the model picture.
    void clearResult();
    /// The snapshot shown, or null.
    std::shared_ptr<const ResultSnapshot> result() const;
    /// The saved step shown, or empty.
    QString resultFile() const;
    /// What the result picture shows at a model point (m), e.g. "principal stress 1 = -12.3
    /// MPa"; empty over the model picture or outside the mesh.
    QString resultValueAt(const QPointF& model_pos) const;
    /// What the result picture shows where (empty over the model picture): for query lines.
    const view::ResultProbe& resultProbe() const;
    /// What the result picture drew: the deformation scale used, elements drawn inside out, the
    /// colour scale's ends and the title.
    const view::ResultInfo& resultInfo() const;

    /// What is drawn; changing it rebuilds the picture and keeps the camera.
    void setSceneOptions(const view::SceneOptions& options);
    view::SceneOptions sceneOptions() const;

    /// Renders now and reads the frame back from VTK (RGB, top row first, in device pixels).
    /// Null when the widget has no native window yet (never shown).
    QImage grabFrame();

    /// Model coordinates (m) under a point of the widget (logical pixels).
    QPointF toModel(const QPointF& widget_pos) const;
    /// Widget position (logical pixels) of a model point (m).
    QPointF toWidget(const QPointF& model_pos) const;
    /// Size of one logical pixel in the model (m): how precise a cursor position is.
    double metresPerPixel() const;

    /// The editing tool that gets left clicks and keys (not owned); null = navigation only
    /// (left or middle drag pans). With a tool the middle button pans, and so does the left one
    /// where the tool does not take the press (Select on empty space).
    void setTool(ViewTool* tool);
    ViewTool* tool() const;
    /// A rubber band drawn over the picture (model coordinates), e.g. a shape being drawn;
    /// `closed` joins the last point to the first. `emphasised` draws it as a query line (dark
    /// with a white halo and end markers), which stays readable over any colour map.
    void setPreview(const std::vector<Point2>& points, bool closed, bool emphasised = false);
    void clearPreview();
    /// The rubber band's points (empty when none).
    std::vector<Point2> preview() const;
    /// A light grid of lines `metres` apart over the picture (every 2^k-th line when zoomed
    /// out, so lines stay apart); 0 removes it. Drawing tools show their snapping grid so.
    void setGridSpacing(double metres);
    double gridSpacing() const;
    /// A marker where a click would land (the snapped cursor of a drawing tool); hidden when
    /// the cursor leaves the view or the tool changes.
    void showSnapMarker(const Point2& p);
    void hideSnapMarker();
    /// Whether the marker is shown, and where (into `p` when not null).
    bool snapMarker(Point2* p = nullptr) const;
    /// The query line of the Query dock, drawn over result pictures (dark with a white halo and
    /// end markers) until cleared; not over the model picture, whose edits it does not concern.
    void setQueryLine(const Point2& from, const Point2& to);
    void clearQueryLine();
    /// Whether a query line is set (drawn whenever a result is shown), and its ends.
    bool queryLine(Point2* from = nullptr, Point2* to = nullptr) const;
    /// Whether the query line is drawn in the picture now (set, and a result shown).
    bool queryLineShown() const;
    /// Widens the view to show `points` where one of them is out of sight (a point typed far
    /// off), keeping in sight what was; counts as navigating.
    void keepInView(const std::vector<Point2>& points);
    /// Shows the model box [xmin, xmax] × [ymin, ymax] (with a margin); counts as navigating.
    void showBox(double xmin, double ymin, double xmax, double ymax);

    QSize sizeHint() const override { return {800, 600}; }
    /// Null: VTK paints this widget, not QPainter (required by Qt::WA_PaintOnScreen).
    QPaintEngine* paintEngine() const override { return nullptr; }

public slots:
    /// Shows the whole model with a margin.
    void fitView();
    /// Fits the view when part of a region lies outside it (the first region of a new model
    /// may be typed far from the default view).
    void ensureRegionsVisible();
    /// Zooms by `factor` (> 1 magnifies) keeping the model point under `widget_pos` in place.
    void zoomAt(const QPointF& widget_pos, double factor);
    /// Moves the picture by a widget-pixel offset (as if dragged by it).
    void panBy(const QPointF& pixels);

signals:
    /// The cursor is over the model point `model_pos` (m).
    void cursorMoved(const QPointF& model_pos);
    /// The cursor left the view.
    void cursorLeft();

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void leaveEvent(QEvent* event) override;
    bool event(QEvent* event) override;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;

    bool ensureWindow();
    void syncSize();
    void rebuild(bool keep_camera);
    void renderNow();
    void syncOverlay();
    /// The grid lines over the visible area (each render: they follow pan and zoom).
    void rebuildGrid();
};

}  // namespace mcdda::gui

#pragma once
/// \file JointSetPreview.hpp
/// The Add Joint Set dialog's picture: the model's regions (rock grey, holes white) and the
/// traces the set would add, drawn only where they cut rock, as the cutter uses them. QPainter
/// only, so the dialog stays light and is tested without a display.

#include "model/Model.hpp"

#include <QWidget>

namespace mcdda::gui {

class JointSetPreview : public QWidget {
    Q_OBJECT

public:
    /// `model` (copied) gives the regions and the box that the set is expanded in.
    explicit JointSetPreview(const Model& model, QWidget* parent = nullptr);

    /// Shows `set` in place of the previous one.
    void setJointSet(const JointSet& set);
    /// How many traces (or segments) the set gives.
    int traceCount() const { return static_cast<int>(traces_.size()); }
    /// Where the model point `p` is drawn (widget pixels).
    QPointF toPixel(const Point2& p) const;

    QSize sizeHint() const override { return {320, 220}; }

    /// Colours of the picture (tests look for them).
    static QColor rockColor();
    static QColor traceColor();

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    Model model_;
    std::vector<Joint> traces_;
    double xmin_ = 0.0, ymin_ = 0.0, xmax_ = 1.0, ymax_ = 1.0;  ///< the regions' box (m)
};

}  // namespace mcdda::gui

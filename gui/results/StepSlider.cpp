#include "results/StepSlider.hpp"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>

namespace mcdda::gui {

StepSlider::StepSlider(QWidget* parent) : QWidget(parent)
{
    slider_ = new QSlider(Qt::Horizontal, this);
    slider_->setObjectName(QStringLiteral("stepSlider"));
    slider_->setToolTip(tr("Saved step shown"));
    slider_->setPageStep(1);
    slider_->setTickPosition(QSlider::TicksBelow);
    label_ = new QLabel(this);
    label_->setObjectName(QStringLiteral("stepLabel"));
    label_->setMinimumWidth(160);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->addWidget(new QLabel(tr("Step:"), this));
    layout->addWidget(slider_, 1);
    layout->addWidget(label_);
    connect(slider_, &QSlider::valueChanged, this, [this](int index) {
        showLabel();
        if (index >= 0 && index < count()) emit stepChosen(entries_[index].file, entries_[index].time);
    });
    clear();
}

int StepSlider::load(const QString& pvd_path, bool keep_current)
{
    const int kept = currentIndex();
    entries_ = QFileInfo::exists(pvd_path) ? read_pvd(pvd_path) : std::vector<PvdEntry>{};
    const QSignalBlocker block(slider_);
    slider_->setRange(0, std::max(0, count() - 1));
    slider_->setValue(keep_current && kept >= 0 ? std::min(kept, slider_->maximum()) : slider_->maximum());
    slider_->setEnabled(count() > 0);
    showLabel();
    return count();
}

void StepSlider::clear()
{
    entries_.clear();
    const QSignalBlocker block(slider_);
    slider_->setRange(0, 0);
    slider_->setEnabled(false);
    showLabel();
}

int StepSlider::currentIndex() const { return count() > 0 ? slider_->value() : -1; }

void StepSlider::setCurrentIndex(int index)
{
    if (index < 0 || index >= count()) return;
    if (slider_->value() == index)
        emit stepChosen(entries_[index].file, entries_[index].time);
    else
        slider_->setValue(index);
}

void StepSlider::showLabel()
{
    const int index = currentIndex();
    if (index < 0) {
        label_->setText(tr("no saved steps"));
        return;
    }
    // The step number is in the file's name (<model>_NNNNNN.vtu, RunOutput).
    const QString base = QFileInfo(entries_[index].file).completeBaseName();
    const int underscore = base.lastIndexOf(QLatin1Char('_'));
    bool numbered = false;
    const int step = underscore >= 0 ? base.mid(underscore + 1).toInt(&numbered) : 0;
    if (load_steps_) {  // a static run: load steps, no time
        const QString where = tr("%1 of %2").arg(index + 1).arg(count());
        label_->setText(numbered ? tr("load step %1 (%2)").arg(step).arg(where) : where);
        return;
    }
    const QString where = tr("%1 of %2, t = %3 s").arg(index + 1).arg(count()).arg(QLocale().toString(entries_[index].time, 'g', 6));
    label_->setText(numbered ? tr("step %1 (%2)").arg(step).arg(where) : where);
}

}  // namespace mcdda::gui

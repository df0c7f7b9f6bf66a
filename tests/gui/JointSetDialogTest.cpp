// Edit ▸ Add Joint Set: persistence (%), trace length (m) and stagger (%) of a set, entered in
// the dialog and given back as Model stores them. No display needed.

#include "dialogs/JointSetDialog.hpp"

#include <QApplication>
#include "dialogs/JointSetPreview.hpp"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QtTest>

using namespace mcdda;
using mcdda::gui::JointSetDialog;

class JointSetDialogTest : public QObject {
    Q_OBJECT

private slots:
    void persistentByDefaultWithSegmentFieldsDisabled();
    void enteredPersistenceGivesSegments();
    void setJointSetFillsTheFields();
    void refusesZeroPersistenceAndMissingTraceLength();
    void defaultsFollowTheModelAndTheConventionIsStated();
    void previewDrawsTracesOnlyInRock();
};

namespace {

QDoubleSpinBox* box(const JointSetDialog& dialog, const char* name)
{
    auto* found = dialog.findChild<QDoubleSpinBox*>(QString::fromLatin1(name));
    if (!found) qWarning("no spin box \"%s\"", name);
    return found;
}

/// A 20 m square of rock at (x0, y0) with a 4 m square opening in its middle.
Model block_with_opening(double x0, double y0)
{
    Model m;
    m.materials.push_back(Material{});
    m.joint_materials.push_back(JointMaterial{});
    Region r;
    r.material = 0;
    r.boundary = {{x0, y0}, {x0 + 20, y0}, {x0 + 20, y0 + 20}, {x0, y0 + 20}};
    r.holes = {{{x0 + 8, y0 + 8}, {x0 + 12, y0 + 8}, {x0 + 12, y0 + 12}, {x0 + 8, y0 + 12}}};
    m.regions.push_back(r);
    return m;
}

/// Pixels of the traces' colour within 3 pixels of the model point p.
int trace_pixels_near(const gui::JointSetPreview& preview, const QImage& image, Point2 p)
{
    const QPoint c = preview.toPixel(p).toPoint();
    int n = 0;
    for (int y = c.y() - 3; y <= c.y() + 3; ++y)
        for (int x = c.x() - 3; x <= c.x() + 3; ++x) {
            if (!image.rect().contains(x, y)) continue;
            const QColor px = image.pixelColor(x, y);
            const QColor want = gui::JointSetPreview::traceColor();
            if (std::abs(px.red() - want.red()) < 40 && std::abs(px.green() - want.green()) < 40 &&
                std::abs(px.blue() - want.blue()) < 40)
                ++n;
        }
    return n;
}

}  // namespace

void JointSetDialogTest::persistentByDefaultWithSegmentFieldsDisabled()
{
    JointSetDialog dialog(Model{});
    QDoubleSpinBox* persistence = box(dialog, "persistenceBox");
    QDoubleSpinBox* trace_length = box(dialog, "traceLengthBox");
    QDoubleSpinBox* stagger = box(dialog, "staggerBox");
    QVERIFY(persistence && trace_length && stagger);
    QCOMPARE(persistence->value(), 100.0);
    QCOMPARE(persistence->suffix(), QStringLiteral(" %"));
    QCOMPARE(trace_length->suffix(), QStringLiteral(" m"));
    QCOMPARE(stagger->suffix(), QStringLiteral(" %"));
    QVERIFY(!trace_length->isEnabled());
    QVERIFY(!stagger->isEnabled());
    // A persistent set is what it was before persistence existed: defaults in every new field.
    const JointSet set = dialog.jointSet();
    QCOMPARE(set.persistence, 1.0);
    QCOMPARE(set.trace_length, JointSet{}.trace_length);
    QCOMPARE(set.stagger, JointSet{}.stagger);
    QVERIFY(dialog.validationError().isEmpty());
}

void JointSetDialogTest::enteredPersistenceGivesSegments()
{
    JointSetDialog dialog(Model{});
    QDoubleSpinBox* persistence = box(dialog, "persistenceBox");
    QDoubleSpinBox* trace_length = box(dialog, "traceLengthBox");
    QDoubleSpinBox* stagger = box(dialog, "staggerBox");
    QVERIFY(persistence && trace_length && stagger);
    persistence->setValue(40.0);
    QVERIFY(trace_length->isEnabled());
    QVERIFY(stagger->isEnabled());
    trace_length->setValue(2.5);
    stagger->setValue(25.0);
    const JointSet set = dialog.jointSet();
    QCOMPARE(set.persistence, 0.4);
    QCOMPARE(set.trace_length, 2.5);
    QCOMPARE(set.stagger, 0.25);
    QVERIFY(dialog.validationError().isEmpty());
    // Back to 100 %: the fields are disabled again and no longer count.
    persistence->setValue(100.0);
    QVERIFY(!trace_length->isEnabled());
    QCOMPARE(dialog.jointSet().persistence, 1.0);
    QCOMPARE(dialog.jointSet().trace_length, 0.0);
}

void JointSetDialogTest::setJointSetFillsTheFields()
{
    JointSetDialog dialog(Model{});
    JointSet preset;
    preset.spacing = 2.0;
    preset.persistence = 0.75;
    preset.trace_length = 6.0;
    preset.stagger = 0.1;
    dialog.setJointSet(preset);
    QCOMPARE(box(dialog, "persistenceBox")->value(), 75.0);
    QCOMPARE(box(dialog, "traceLengthBox")->value(), 6.0);
    QCOMPARE(box(dialog, "staggerBox")->value(), 10.0);
    QVERIFY(box(dialog, "traceLengthBox")->isEnabled());
    const JointSet entered = dialog.jointSet();
    QCOMPARE(entered.persistence, 0.75);
    QCOMPARE(entered.trace_length, 6.0);
    QCOMPARE(entered.stagger, 0.1);
}

void JointSetDialogTest::refusesZeroPersistenceAndMissingTraceLength()
{
    JointSetDialog dialog(Model{});
    box(dialog, "persistenceBox")->setValue(0.0);
    dialog.accept();
    QVERIFY(dialog.result() != int(QDialog::Accepted));
    QVERIFY(dialog.validationError().contains(QStringLiteral("persistence")));

    JointSetDialog no_length(Model{});
    box(no_length, "persistenceBox")->setValue(50.0);
    box(no_length, "traceLengthBox")->setValue(0.0);
    no_length.accept();
    QVERIFY(no_length.result() != int(QDialog::Accepted));
    QVERIFY(no_length.validationError().contains(QStringLiteral("trace length")));
    box(no_length, "traceLengthBox")->setValue(3.0);
    no_length.accept();
    QCOMPARE(no_length.result(), int(QDialog::Accepted));
}

// The box and the origin come from the model (not 0–10 m and a corner), the
// set has a name, and the angle convention is written beside the angle.
void JointSetDialogTest::defaultsFollowTheModelAndTheConventionIsStated()
{
    const Model model = block_with_opening(100.0, 20.0);
    JointSetDialog dialog(model);
    QCOMPARE(box(dialog, "xminBox")->value(), 100.0);
    QCOMPARE(box(dialog, "yminBox")->value(), 20.0);
    QCOMPARE(box(dialog, "xmaxBox")->value(), 120.0);
    QCOMPARE(box(dialog, "ymaxBox")->value(), 40.0);
    QCOMPARE(box(dialog, "originXBox")->value(), 110.0);
    QCOMPARE(box(dialog, "originYBox")->value(), 30.0);
    auto* name = dialog.findChild<QLineEdit*>(QStringLiteral("nameEdit"));
    QVERIFY(name);
    QCOMPARE(name->text(), QStringLiteral("set 1"));
    name->setText(QStringLiteral("J1 bedding"));
    QCOMPARE(dialog.jointSet().name, std::string("J1 bedding"));
    auto* convention = dialog.findChild<QLabel*>(QStringLiteral("angleConvention"));
    QVERIFY(convention);
    QVERIFY(convention->text().contains(QStringLiteral("from the horizontal")));
    QVERIFY(convention->text().contains(QStringLiteral("counter-clockwise")));
}

// The preview draws the set's traces where they cut rock, not across the opening, and counts them.
void JointSetDialogTest::previewDrawsTracesOnlyInRock()
{
    const Model model = block_with_opening(0.0, 0.0);
    JointSetDialog dialog(model);
    box(dialog, "angleBox")->setValue(0.0);  // horizontal traces at y = 0.5, 1.5, ... 19.5
    box(dialog, "spacingBox")->setValue(1.0);
    box(dialog, "originXBox")->setValue(0.0);
    box(dialog, "originYBox")->setValue(10.5);
    gui::JointSetPreview* preview = dialog.preview();
    QVERIFY(preview);
    preview->resize(400, 400);
    const int dense = preview->traceCount();
    QVERIFY2(dense >= 18, qPrintable(QString::number(dense)));
    const QImage image = preview->grab().toImage();
    QVERIFY(trace_pixels_near(*preview, image, {4.0, 10.5}) > 0);   // in rock, left of the opening
    QVERIFY(trace_pixels_near(*preview, image, {16.0, 10.5}) > 0);  // in rock, right of it
    QCOMPARE(trace_pixels_near(*preview, image, {10.0, 10.5}), 0);   // none across the opening
    auto* count = dialog.findChild<QLabel*>(QStringLiteral("traceCount"));
    QVERIFY(count->text().contains(QString::number(dense)));
    box(dialog, "spacingBox")->setValue(2.0);
    QVERIFY(preview->traceCount() < dense);
    QVERIFY(count->text().contains(QString::number(preview->traceCount())));
}

QTEST_MAIN(JointSetDialogTest)
#include "JointSetDialogTest.moc"

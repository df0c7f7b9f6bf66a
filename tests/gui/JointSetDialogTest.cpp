// Edit ▸ Add Joint Set: persistence (%), trace length (m) and stagger (%) of a set, entered in
// the dialog and given back as Model stores them. No display needed.

#include "dialogs/JointSetDialog.hpp"

#include <QApplication>
#include <QDoubleSpinBox>
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
};

namespace {

QDoubleSpinBox* box(const JointSetDialog& dialog, const char* name)
{
    auto* found = dialog.findChild<QDoubleSpinBox*>(QString::fromLatin1(name));
    if (!found) qWarning("no spin box \"%s\"", name);
    return found;
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

QTEST_MAIN(JointSetDialogTest)
#include "JointSetDialogTest.moc"

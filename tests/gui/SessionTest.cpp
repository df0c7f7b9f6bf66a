// The desktop program's logic without widgets (gui/session, Qt Core only): a run session on
// its worker thread, background pre-processing after edits, and the texts of the log. No
// display: QCoreApplication.

#include "model/Defaults.hpp"
#include "session/DisplayUnits.hpp"
#include "session/PreprocessScheduler.hpp"
#include "session/RunMessages.hpp"
#include "session/RunSession.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace mcdda;
using mcdda::gui::PreprocessScheduler;
using mcdda::gui::RunProgress;
using mcdda::gui::RunSession;

namespace {

// A block resting on a slope flatter than its friction angle. A few steps do not settle it, so
// the equilibrium check is relaxed: these tests are about the session, not about equilibrium.
const QString incline = QStringLiteral(MCDDA_EXAMPLES_DIR "/incline-stable.json");

Preprocessed incline_with(std::vector<std::string> overrides)
{
    overrides.push_back("/analysis/equilibrium_ratio=1e6");
    return preprocess_file(incline.toStdString(), overrides);
}

}  // namespace

class SessionTest : public QObject {
    Q_OBJECT

private slots:
    void resultsFolderFollowsTheModelFile();
    void runCompletesAndKeepsItsFiles();
    void stopEndsTheRunAfterAStep();
    void pauseHoldsTheRun();
    void abandonedRunSendsNothingMore();
    void modelWithErrorsIsNotStarted();
    void newerRequestSupersedesTheWaitingOne();
    void droppedRequestIsNeverShown();
    void readFileReportsProblemsAsDiagnostics();
    void messagesSayHowTheRunEnded();
    void newModelDefaults();
    void unitChoiceIsSharedAndKept();
};

void SessionTest::resultsFolderFollowsTheModelFile()
{
    RunSession session;
    session.setSourcePath(QStringLiteral("/data/models/slope.json"));
    QCOMPARE(session.runFolder(), QStringLiteral("/data/models/slope-results"));
    QCOMPARE(session.stem(), QStringLiteral("slope"));
    session.setOutputFolder(QStringLiteral("/elsewhere"));
    QCOMPARE(session.runFolder(), QStringLiteral("/elsewhere"));
    session.setSourcePath({});
    session.setOutputFolder({});
    QCOMPARE(session.stem(), QStringLiteral("model"));
    QCOMPARE(session.runFolder(), QDir::current().absoluteFilePath(QStringLiteral("model-results")));
}

void SessionTest::runCompletesAndKeepsItsFiles()
{
    const Preprocessed model = incline_with({"/analysis/steps=6", "/analysis/output_every=2"});
    QVERIFY(model.ok);
    QTemporaryDir out;
    RunSession session;
    session.setSourcePath(QStringLiteral("/any/incline.json"));
    session.setOutputFolder(out.path());
    session.setThrottle(0, 0);
    QSignalSpy started(&session, &RunSession::started);
    QSignalSpy progress(&session, &RunSession::progress);
    QSignalSpy snapshots(&session, &RunSession::snapshot);
    QSignalSpy finished(&session, &RunSession::finished);
    QVERIFY(session.start(model));
    QVERIFY(session.isRunning());
    QVERIFY(!session.start(model));  // one at a time
    QCOMPARE(started.count(), 1);
    QCOMPARE(started.at(0).at(0).toInt(), 6);
    QCOMPARE(started.at(0).at(1).toString(), out.path());
    QVERIFY(finished.wait(120000));
    QVERIFY(!session.isRunning());
    QCOMPARE(finished.at(0).at(0).value<RunStatus>(), RunStatus::Completed);
    QCOMPARE(progress.last().at(0).value<RunProgress>().step, 6);
    QVERIFY(snapshots.count() >= 2);  // the initial state and at least the last step
    QVERIFY(session.lastSnapshot());
    QCOMPARE(session.lastSnapshot()->step, 6);
    QCOMPARE(session.resultsFolder(), out.path());
    QCOMPARE(QFileInfo(session.resultsPvdPath()).fileName(), QStringLiteral("incline.pvd"));
    QVERIFY(QFileInfo::exists(session.resultsPvdPath()));
    QVERIFY(QFileInfo::exists(session.resultsHistoryPath()));
    session.clearResults();
    QVERIFY(session.resultsPvdPath().isEmpty());
    QVERIFY(!session.lastSnapshot());
}

void SessionTest::stopEndsTheRunAfterAStep()
{
    const Preprocessed model = incline_with({"/analysis/steps=100000"});
    QTemporaryDir out;
    RunSession session;
    session.setOutputFolder(out.path());
    session.setThrottle(0, 0);
    QSignalSpy progress(&session, &RunSession::progress);
    QSignalSpy finished(&session, &RunSession::finished);
    QVERIFY(session.start(model));
    QVERIFY(progress.wait(60000));
    session.stop();
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(0).at(0).value<RunStatus>(), RunStatus::Cancelled);
    QVERIFY(session.lastSnapshot()->step < 100000);
    QVERIFY(QFileInfo::exists(session.resultsHistoryPath()));
    QVERIFY(QFileInfo::exists(session.resultsPvdPath()));
}

void SessionTest::pauseHoldsTheRun()
{
    const Preprocessed model = incline_with({"/analysis/steps=100000"});
    QTemporaryDir out;
    RunSession session;
    session.setOutputFolder(out.path());
    session.setThrottle(0, 0);
    QSignalSpy progress(&session, &RunSession::progress);
    QSignalSpy paused(&session, &RunSession::pausedChanged);
    QSignalSpy finished(&session, &RunSession::finished);
    QVERIFY(session.start(model));
    QVERIFY(progress.wait(60000));
    session.togglePause();
    QVERIFY(session.isPaused());
    QCOMPARE(paused.count(), 1);
    QCOMPARE(paused.at(0).at(0).toBool(), true);
    QTest::qWait(300);  // a step under way when pausing still reports
    const int before = progress.count();
    QTest::qWait(500);
    QCOMPARE(progress.count(), before);  // nothing moves while paused
    session.togglePause();
    QVERIFY(!session.isPaused());
    QVERIFY(progress.wait(60000));  // and it goes on
    session.stop();
    QVERIFY(finished.wait(60000));
}

void SessionTest::abandonedRunSendsNothingMore()
{
    const Preprocessed model = incline_with({"/analysis/steps=100000"});
    QTemporaryDir out;
    RunSession session;
    session.setOutputFolder(out.path());
    session.setThrottle(0, 0);
    QSignalSpy progress(&session, &RunSession::progress);
    QSignalSpy finished(&session, &RunSession::finished);
    QVERIFY(session.start(model));
    QVERIFY(progress.wait(60000));
    session.abandon();
    QVERIFY(!session.isRunning());
    const int seen = progress.count();
    QTest::qWait(300);  // calls queued by the joined run are delivered now, and dropped
    QCOMPARE(progress.count(), seen);
    QCOMPARE(finished.count(), 0);
    // A new run starts cleanly after it.
    const Preprocessed small = incline_with({"/analysis/steps=2"});
    QVERIFY(session.start(small));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(0).at(0).value<RunStatus>(), RunStatus::Completed);
}

void SessionTest::modelWithErrorsIsNotStarted()
{
    const Preprocessed broken = incline_with({"/materials/0/poisson_ratio=0.5"});
    QVERIFY(!broken.ok);
    RunSession session;
    QSignalSpy started(&session, &RunSession::started);
    QVERIFY(!session.start(broken));
    QVERIFY(!session.isRunning());
    QCOMPARE(started.count(), 0);
}

void SessionTest::newerRequestSupersedesTheWaitingOne()
{
    const Model base = incline_with({}).model;
    PreprocessScheduler scheduler;
    QSignalSpy ready(&scheduler, &PreprocessScheduler::ready);
    QSignalSpy busy(&scheduler, &PreprocessScheduler::busyChanged);
    // A burst of edits: mesh sizes 1.0, 0.9, ..., 0.5; only the last is to be shown.
    for (int i = 0; i < 6; ++i) {
        Model m = base;
        m.mesh.size = 1.0 - 0.1 * i;
        scheduler.request(m);
        QVERIFY(scheduler.isBusy());
    }
    QTRY_VERIFY_WITH_TIMEOUT(!scheduler.isBusy(), 60000);
    QCOMPARE(ready.count(), 1);
    const auto shown = ready.at(0).at(0).value<std::shared_ptr<const Preprocessed>>();
    QVERIFY(shown && shown->ok);
    QCOMPARE(shown->model.mesh.size, 0.5);
    QCOMPARE(busy.count(), 2);  // busy once, idle once
    QCOMPARE(busy.at(0).at(0).toBool(), true);
    QCOMPARE(busy.at(1).at(0).toBool(), false);
}

void SessionTest::droppedRequestIsNeverShown()
{
    PreprocessScheduler scheduler;
    QSignalSpy ready(&scheduler, &PreprocessScheduler::ready);
    scheduler.request(incline_with({}).model);
    scheduler.drop();
    QVERIFY(!scheduler.isBusy());
    scheduler.waitForFinished();
    QTest::qWait(100);
    QCOMPARE(ready.count(), 0);
}

void SessionTest::readFileReportsProblemsAsDiagnostics()
{
    const auto missing = PreprocessScheduler::readFile(QStringLiteral("/no/such/model.json"));
    QVERIFY(missing);
    QVERIFY(!missing->ok);
    QVERIFY(!missing->diagnostics.empty());
    const auto good = PreprocessScheduler::readFile(incline);
    QVERIFY(good->ok);
    QVERIFY(good->statistics.elements > 0);
}

void SessionTest::messagesSayHowTheRunEnded()
{
    using gui::end_line;
    QVERIFY(end_line(RunStatus::Completed, 12, {}).contains(QStringLiteral("12")));
    QVERIFY(end_line(RunStatus::Cancelled, 7, {}).contains(QStringLiteral("7")));
    const QString unbalanced = end_line(
        RunStatus::Unbalanced, 5, QStringLiteral("not in equilibrium: the unbalanced-force ratio after step 5 is 0.14 (limit 0.01)"));
    QCOMPARE(unbalanced.count(QStringLiteral("not in equilibrium")), 1);  // said once
    QVERIFY(unbalanced.endsWith(QStringLiteral("ratio after step 5 is 0.14 (limit 0.01)")));
    QVERIFY(end_line(RunStatus::Collapsed, 5, QStringLiteral("at load 0.8")).contains(QStringLiteral("collapsed")));
    QVERIFY(end_line(RunStatus::Failed, 5, QStringLiteral("disk full")).contains(QStringLiteral("disk full")));

    RunProgress p;
    p.step = 3;
    p.total_steps = 10;
    p.open = 4;
    p.sliding = 5;
    p.locked = 6;
    QVERIFY(gui::progress_line(p).startsWith(QStringLiteral("step 3/10")));
    QVERIFY(gui::progress_line(p).contains(QStringLiteral("4/5/6")));

    const Preprocessed broken = incline_with({"/materials/0/poisson_ratio=0.5", "/materials/0/young_modulus=-1"});
    QCOMPARE(gui::mesh_summary(broken), QStringLiteral("Not meshed: 2 error(s)"));
    const QStringList report = gui::preprocess_report(broken, QStringLiteral("x.json"));
    QCOMPARE(report.first(), QStringLiteral("Model: x.json"));
    // In words: the material by name and the field by its name, no JSON pointer.
    QVERIFY2(report.join(QLatin1Char('\n')).contains(QStringLiteral("Poisson's ratio")), qPrintable(report.join(QLatin1Char('\n'))));
    QVERIFY(!report.join(QLatin1Char('\n')).contains(QStringLiteral("/materials/0")));
    const Preprocessed good = incline_with({});
    QVERIFY(gui::mesh_summary(good).contains(QStringLiteral("%1 elements").arg(good.statistics.elements)));
}

void SessionTest::newModelDefaults()
{
    const Model m = new_model("rock", "joint");
    QCOMPARE(m.materials.size(), std::size_t(1));
    QCOMPARE(m.materials[0].density * standard_gravity, 25.5e3);  // typed as 25.5 kN/m³
    QCOMPARE(m.materials[0].parameter("friction_angle"), 35.0 * degree);
    QCOMPARE(m.joint_materials[0].friction_angle, 30.0 * degree);
    QCOMPARE(m.default_joint_material, 0);
    QCOMPARE(m.gravity.y, -standard_gravity);
    QCOMPARE(m.analysis.kind, AnalysisSettings::Kind::Static);
    QCOMPARE(m.analysis.steps, 20);
    QCOMPARE(m.analysis.time_step, 1.0);  // load steps counted in seconds, not 0.01 s
}

// One choice of units for the whole program: stored in the settings, told to
// everyone once when it changes, and giving the forms their stress and modulus units.
void SessionTest::unitChoiceIsSharedAndKept()
{
    QStandardPaths::setTestModeEnabled(true);
    gui::DisplayUnits* units = gui::DisplayUnits::instance();
    units->set(view::StressUnit::Automatic, view::LengthUnit::Metre);
    QSignalSpy changed(units, &gui::DisplayUnits::changed);
    QCOMPARE(units->formStressUnit(), QStringLiteral("kPa"));   // automatic: strengths in kPa,
    QCOMPARE(units->formModulusUnit(), QStringLiteral("MPa"));  // moduli in MPa
    units->set(view::StressUnit::MPa, view::LengthUnit::Millimetre);
    QCOMPARE(changed.count(), 1);
    units->set(view::StressUnit::MPa, view::LengthUnit::Millimetre);
    QCOMPARE(changed.count(), 1);  // no change, no news
    QCOMPARE(units->formStressUnit(), QStringLiteral("MPa"));
    QCOMPARE(units->formStressFactor(), 1e6);
    QCOMPARE(QSettings().value(QStringLiteral("units/stress")).toInt(), int(view::StressUnit::MPa));
    QCOMPARE(QSettings().value(QStringLiteral("units/length")).toInt(), int(view::LengthUnit::Millimetre));
    units->set(view::StressUnit::KPa, view::LengthUnit::Metre);
    QCOMPARE(units->formModulusUnit(), QStringLiteral("kPa"));
    QCOMPARE(units->formModulusFactor(), 1e3);
    units->set(view::StressUnit::Automatic, view::LengthUnit::Metre);
    QCOMPARE(changed.count(), 3);
}

QTEST_GUILESS_MAIN(SessionTest)
#include "SessionTest.moc"

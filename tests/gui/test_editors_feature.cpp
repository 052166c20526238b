// A tool-table edit (the number of teeth) re-runs every view built on the tools, and each then shows
// what the CLI computes on the saved project: the lobe readout's power, the simulation, the expert
// ranking (rubio2006-adaptive-control; its control view: test_control_gui.cpp), the Pareto choice
// (rubio-pareto-case), the optimised part program (cus-zuperl-sdnrp) and the supervisor comparison
// (landers-face-milling). Each number is also checked to differ from the one before the edit. Bad input
// in the tool table is answered in the window, under the cell, at once.
#include <QFile>
#include <QLabel>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <cmath>

#include "input_feedback.h"
#include "machining_feature.h"
#include "main_window.h"
#include "pareto_runner.h"
#include "part_program_panel.h"
#include "ranking_table.h"
#include "simulation_runner.h"
#include "supervisor_comparison.h"
#include "supervisor_feature.h"
#include "supervisor_view.h"
#include "support/cli_runner.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"
#include "tool_library_editor.h"
#include "tool_table_model.h"

using namespace mx;

namespace {

constexpr int kWaitMs = 60000;

bool openForEditing(gui::MainWindow& w, const char* project) {
  w.setQuiet(true);
  w.resize(1600, 950);
  w.show();
  w.document()->setAutosaveInterval(0);  // the runs outlast 30 s: no autosave next to the example
  return w.openProject(mx::test::exampleCopy(project));
}

// Sets the teeth of tool `id` in the tool table, as the user would.
bool setTeeth(gui::MainWindow& w, const QString& id, int teeth) {
  widgets::ToolTableModel* tools = test::editorsOf(w)->toolEditor()->toolModel();
  for (int row = 0; row < tools->rowCount(); ++row)
    if (tools->index(row, widgets::ToolTableModel::Id).data().toString() == id)
      return tools->setData(tools->index(row, widgets::ToolTableModel::Teeth), teeth, Qt::EditRole) &&
             w.project()->findTool(id)->teeth == teeth;
  return false;
}

QString saved(gui::MainWindow& w, const QTemporaryDir& dir) {
  QString path = dir.filePath("edited.mxproj");
  w.document()->save(path);
  return path;
}

QString number(double v) {
  return QString::number(v, 'g', 17);
}

bool near(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

// The lines of a written program but its "(date: ...)" header line.
QStringList programBody(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  QStringList lines = QString::fromUtf8(f.readAll()).split('\n');
  lines.removeIf([](const QString& l) { return l.startsWith("(date: "); });
  return lines;
}

// Waits until `done` holds, spinning the event loop on `spy`.
template <class Done>
bool waitFor(QSignalSpy& spy, Done done) {
  for (int i = 0; i < kWaitMs / 500 && !done(); ++i) spy.wait(500);
  return done();
}

}  // namespace

class TestEditorsFeature : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  void lobesSimulationAndRankingReRun() {
    gui::MainWindow window;
    QSignalSpy lobes(test::lobesOf(window), &gui::LobesFeature::lobesShown);
    QSignalSpy refined(test::expertOf(window), &gui::ExpertFeature::refinementShown);
    QSignalSpy simulated(test::simulationOf(window)->runner(), &gui::SimulationRunner::finished);
    QVERIFY(openForEditing(window, "rubio2006-adaptive-control.mxproj"));
    QVERIFY(waitFor(simulated, [&] { return lobes.count() > 0 && simulated.count() > 0 && refined.count() > 0; }));
    const double four_power = test::lobesOf(window)->readout()->readout().peak_power_w;
    const auto four_sim = simulated.last().at(1).value<gui::SimulationSummary>();
    QCOMPARE(four_sim.teeth, 4);
    const widgets::RankingRow four_rank = test::windowPart<widgets::RankingTable>(window)->rows().front();

    lobes.clear();
    refined.clear();
    simulated.clear();
    QVERIFY(setTeeth(window, "C1", 2));
    QVERIFY(waitFor(simulated, [&] { return lobes.count() > 0 && simulated.count() > 0 && refined.count() > 0; }));
    QTemporaryDir dir;
    const QString path = saved(window, dir);
    const app::PickedPoint pt = window.document()->point();
    const QStringList cut{"--tool",  "C1",
                          "--speed", number(pt.speed_rpm),
                          "--depth", number(pt.depth_mm),
                          "--feed",  number(pt.feed_mm_per_tooth)};

    // The lobes' readout: the power at the operating point.
    const mx::test::CliRun point = mx::test::runCli(QStringList{"point", path} + cut);
    QCOMPARE(point.code, 0);
    const double power = test::lobesOf(window)->readout()->readout().peak_power_w;
    QVERIFY2(near(power, point.json.value("peak_power_W").toDouble()), qPrintable(number(power)));
    QVERIFY(!near(power, four_power));

    // The simulation of the operating point.
    const auto sim = simulated.last().at(1).value<gui::SimulationSummary>();
    QCOMPARE(sim.teeth, 2);
    const mx::test::CliRun simulate = mx::test::runCli(QStringList{"simulate", path} + cut);
    QCOMPARE(simulate.code, 0);
    QVERIFY2(near(sim.peak_force_n, simulate.json.value("peak_force_N").toDouble()),
             qPrintable(number(sim.peak_force_n)));
    QVERIFY(near(sim.tooth_passing_hz, simulate.json.value("tooth_passing_Hz").toDouble()));
    QVERIFY(!near(sim.peak_force_n, four_sim.peak_force_n));

    // The expert ranking (Rules 4-6).
    const mx::test::CliRun rank = mx::test::runCli({"rank", path});
    QCOMPARE(rank.code, 0);
    const QJsonObject best = rank.json.value("ranking").toArray().at(0).toObject();
    const widgets::RankingRow row = test::windowPart<widgets::RankingTable>(window)->rows().front();
    QVERIFY2(near(row.min_cost, best.value("min_cost").toDouble()), qPrintable(number(row.min_cost)));
    QCOMPARE(row.speed_rpm, best.value("q").toObject().value("speed_rpm").toDouble());
    QVERIFY(near(row.depth_mm, best.value("q").toObject().value("depth_mm").toDouble()));
    QVERIFY(!near(row.min_cost, four_rank.min_cost) || row.depth_mm != four_rank.depth_mm);
  }

  // The note is the window's: it stays under the cell after the editor closes. 0 passes the box and
  // is refused by the project's rules, with their message.
  void badInputIsAnsweredUnderTheCell() {
    gui::MainWindow window;
    QVERIFY(openForEditing(window, "rubio2006-adaptive-control.mxproj"));
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    widgets::ToolLibraryEditor* editor = test::editorsOf(window)->toolEditor();
    QTableView* view = editor->toolView();
    const auto typeInto = [view](const QModelIndex& cell, const QString& text) {
      view->setCurrentIndex(cell);
      view->edit(cell);
      auto* box = view->viewport()->findChild<QAbstractSpinBox*>();
      if (!box) return false;
      box->selectAll();
      QTest::keyClicks(box, text);
      return true;
    };
    const auto noteAtCell = [view](const QModelIndex& cell) {
      const QLabel* note = widgets::inputNote(view);
      const QRect rect = view->visualRect(cell);
      const int cellBottom = view->viewport()->mapToGlobal(rect.bottomLeft()).y();
      return note && note->isVisible() && note->mapToGlobal(QPoint(0, 0)).y() == cellBottom + 1;
    };
    const QModelIndex teeth = editor->toolModel()->index(0, widgets::ToolTableModel::Teeth);
    const int before = window.project()->tools[0].teeth;
    QVERIFY(typeInto(teeth, "abc"));
    const QLabel* note = widgets::inputNote(view);
    QCOMPARE(note->parentWidget(), &window);
    QCOMPARE(note->text(), QString("Teeth must be a whole number from 1 to 100; \"abc\" is not a number."));
    QVERIFY(noteAtCell(teeth));
    QTest::keyClick(view->viewport()->findChild<QSpinBox*>(), Qt::Key_Return);
    QCoreApplication::processEvents();  // the view commits and closes its editor through queued calls
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    QCOMPARE(window.project()->tools[0].teeth, before);
    QVERIFY(noteAtCell(teeth));

    const QModelIndex diameter = editor->toolModel()->index(0, widgets::ToolTableModel::Diameter);
    QVERIFY(typeInto(diameter, "0"));
    QTest::keyClick(view->viewport()->findChild<QAbstractSpinBox*>(), Qt::Key_Return);
    QCoreApplication::processEvents();
    QCOMPARE(note->text(), QString("tools[0].diameter_mm = 0: must be in (0, 1000]. The cell keeps its value."));
    QVERIFY(noteAtCell(diameter));
  }

  void paretoStudyReRuns() {
    gui::MainWindow window;
    QSignalSpy shown(test::paretoOf(window), &gui::ParetoFeature::paretoShown);
    QVERIFY(openForEditing(window, "rubio-pareto-case.mxproj"));
    QVERIFY(
        waitFor(shown, [&] { return test::paretoOf(window)->runner()->study() && test::paretoOf(window)->choice(); }));
    const auto before = test::paretoOf(window)->runner()->study();
    const double three_mrr = test::paretoOf(window)->choice()->point().mrr();

    QVERIFY(setTeeth(window, "R1", 2));
    QVERIFY(waitFor(shown, [&] {
      return test::paretoOf(window)->runner()->study() != before && test::paretoOf(window)->choice();
    }));
    QTemporaryDir dir;
    const mx::test::CliRun cli = mx::test::runCli({"pareto", saved(window, dir)});
    QCOMPARE(cli.code, 0);
    const ParetoPoint& q = test::paretoOf(window)->choice()->point();
    const QJsonObject cli_q = cli.json.value("q").toObject();
    QVERIFY(near(revPerSToRpm(q.speed_rev_per_s), cli_q.value("speed_rpm").toDouble()));
    QVERIFY(near(q.depth_m * 1e3, cli_q.value("depth_mm").toDouble()));
    QVERIFY(near(q.feed_per_tooth_m * 1e3, cli_q.value("feed_mm_per_tooth").toDouble()));
    QVERIFY2(near(q.mrr() * 1e6, cli.json.value("mrr_cm3_s").toDouble()), qPrintable(number(q.mrr() * 1e6)));
    QVERIFY(!near(q.mrr(), three_mrr));
  }

  void partProgramOverrideReRuns() {
    gui::MainWindow window;
    auto* machining = window.findChild<gui::MachiningFeature*>("machiningFeature");
    QSignalSpy shown(machining, &gui::MachiningFeature::partProgramShown);
    QVERIFY(openForEditing(window, "cus-zuperl-sdnrp.mxproj"));
    const QString program = MX_TEST_DATA_DIR "/gcode/pocket_mm.nc";
    machining->openPartProgram(program);
    QVERIFY(shown.wait(kWaitMs));
    QTemporaryDir dir;
    QVERIFY(machining->exportPartProgram(dir.filePath("two-teeth.nc")));

    QVERIFY(setTeeth(window, "R216-16B20-040", 4));
    QVERIFY(shown.wait(kWaitMs));
    const QString path = saved(window, dir);  // first: the exported header names the saved file
    QVERIFY(machining->exportPartProgram(dir.filePath("gui.nc")));
    const mx::test::CliRun cli = mx::test::runCli({"override", program, path, "--out", dir.filePath("cli.nc")});
    QCOMPARE(cli.code, 0);
    QCOMPARE(machining->programPanel()->changedCount(), cli.json.value("changed_blocks").toInt());
    const QString force = QString::number(cli.json.value("max_predicted_force_N").toDouble(), 'f', 1);
    QVERIFY2(machining->programPanel()->statusText().contains("largest predicted force " + force + " N"),
             qPrintable(machining->programPanel()->statusText() + " / CLI " + force));
    // The optimised program, header date aside, is the CLI's, and not the two-tooth one.
    QCOMPARE(programBody(dir.filePath("gui.nc")), programBody(dir.filePath("cli.nc")));
    QVERIFY(programBody(dir.filePath("gui.nc")) != programBody(dir.filePath("two-teeth.nc")));
  }

  void supervisorComparisonReRuns() {
    gui::MainWindow window;
    auto* supervisor = window.findChild<gui::SupervisorFeature*>("supervisorFeature");
    QSignalSpy compared(supervisor, &gui::SupervisorFeature::comparisonResult);
    QVERIFY(openForEditing(window, "landers-face-milling.mxproj"));
    supervisor->compare();
    QVERIFY(waitFor(compared, [&] { return compared.count() >= 3; }));
    widgets::SupervisorComparison* table = supervisor->view()->comparison();
    const QString four_power = table->metricText("none", "max_power_pct_of_limit");
    const QString four_cycle = table->metricText("none", "cycle_time_s");

    compared.clear();
    QVERIFY(setTeeth(window, "FM50", 2));
    QVERIFY(waitFor(compared, [&] { return compared.count() >= 3; }));
    QTemporaryDir dir;
    const mx::test::CliRun cli = mx::test::runCli({"supervise", saved(window, dir), "--controller", "none"});
    QCOMPARE(cli.code, 0);
    QCOMPARE(table->metricText("none", "max_power_pct_of_limit"),
             QString::number(cli.json.value("max_power_pct_of_limit").toDouble(), 'f', 0));
    QCOMPARE(table->metricText("none", "cycle_time_s"),
             QString::number(cli.json.value("cycle_time_s").toDouble(), 'f', 2));
    QVERIFY(table->metricText("none", "max_power_pct_of_limit") != four_power ||
            table->metricText("none", "cycle_time_s") != four_cycle);
  }
};

MX_REGISTER_TEST(TestEditorsFeature)
#include "test_editors_feature.moc"

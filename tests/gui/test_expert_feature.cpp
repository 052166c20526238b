// The expert system in the main window: the ranking table and q* / q** markers appear,
// a weight change re-ranks from the cached session (no lobes, grids or simulations recomputed), a
// committed weight change (one per drag) is an undoable project edit that recomputes no lobes, and the
// heat map covers the admissible cells. A session that ends just after an edit is dropped, not shown.
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>

#include "expert_runner.h"
#include "main_window.h"
#include "ranking_table.h"
#include "support/cli_runner.h"
#include "support/engine_hold.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"
#include "weights_panel.h"

using namespace mx;

class TestExpertFeature : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  void rankingAppearsAndWeightChangesOnlyReweigh() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.resize(1600, 950);
    window.show();
    QSignalSpy ranked(test::expertOf(window), &gui::ExpertFeature::rankingShown);
    QSignalSpy refined(test::expertOf(window), &gui::ExpertFeature::refinementShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QVERIFY(refined.wait(60000));  // session built, ranked, then Rules 5-6 with simulations
    QCOMPARE(test::windowPart<widgets::RankingTable>(window)->selectedTool(), QString("R1"));
    QCOMPARE(test::windowPart<widgets::RankingTable>(window)->rows().size(), 2);
    QCOMPARE(test::windowPart<widgets::RankingTable>(window)->rows().front().speed_rpm, 5800.0);
    QVERIFY(
        std::isfinite(test::windowPart<widgets::RankingTable>(window)->rows().front().resultant_cost));  // q** known

    const ExpertSession* session = test::expertOf(window)->runner()->session().get();
    const std::size_t simulations = session->simulations().simulationsRun();
    ranked.clear();
    // Live change: c2 up to 0.9; the table follows, nothing is recomputed.
    QSlider* c2 = test::windowPart<widgets::WeightsPanel>(window)->slider(widgets::WeightsPanel::Group::Tool, 1);
    QSignalSpy lobes(test::lobesOf(window), &gui::LobesFeature::lobesShown);
    c2->setSliderDown(true);
    c2->setValue(800);
    c2->setValue(900);
    QVERIFY(ranked.count() >= 2);
    QCOMPARE(test::expertOf(window)->runner()->session().get(), session);
    QCOMPARE(session->simulations().simulationsRun(), simulations);
    QCOMPARE_LE(std::abs(test::windowPart<widgets::WeightsPanel>(window)->weights().c[1] - 0.9), 1e-9);
    c2->setSliderDown(false);  // commit: an undoable edit of the project's weights
    QVERIFY(window.document()->isDirty());
    QCOMPARE_LE(std::abs(window.project()->expert->c[1] - 0.9), 1e-9);
    QCOMPARE(test::expertOf(window)->runner()->session().get(), session);  // still the same session
    QCOMPARE(window.document()->undoStack()->count(), 1);                  // the drag is one step
    QTest::qWait(300);  // past the lobes' 120 ms debounce: weights alone recompute no lobes
    QCOMPARE(lobes.count(), 0);
    window.document()->undoStack()->undo();
    QCOMPARE_LE(std::abs(window.project()->expert->c[1] - 0.725), 1e-12);
    QCOMPARE_LE(std::abs(test::windowPart<widgets::WeightsPanel>(window)->weights().c[1] - 0.725), 1e-12);
    QCOMPARE(test::expertOf(window)->runner()->session().get(), session);
  }

  // The Report chatter button without a Pareto study is Rule 6 evidence for the 2006 ranking: the
  // report at q** joins expert.reported_chatter (one undo step) and the re-run moves q** out of it.
  void reportedChatterFeedsRule6() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.show();
    QSignalSpy refined(test::expertOf(window), &gui::ExpertFeature::refinementShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QVERIFY(refined.wait(60000));
    const auto& first = test::expertOf(window)->runner()->session();
    QVERIFY(first);
    const CostWeights w = test::expertOf(window)->weights();
    ExpertResult before = first->run(w, true);
    const ExpertPoint q = before.chosenPoint();
    window.document()->setPoint({q.speed_rev_per_s * 60.0, q.depth_m * 1e3, q.feed_per_tooth_m * 1e3});
    auto* button = window.findChild<QPushButton*>("report_chatter_button");
    QVERIFY(button && button->isEnabled());
    refined.clear();
    button->click();
    QCOMPARE(window.project()->expert->reported_chatter.size(), std::size_t(1));
    const app::ChatterReportSpec& report = window.project()->expert->reported_chatter.front();
    QCOMPARE(report.tool, QString("R1"));
    QCOMPARE_LE(std::abs(report.depth_mm - q.depth_m * 1e3), 1e-9);
    QVERIFY(refined.wait(120000));
    ChatterReport heard;
    heard.tool = 0;
    heard.speed_rev_per_s = report.speed_rpm / 60.0;
    heard.depth_m = report.depth_mm * 1e-3;
    const ExpertResult after = test::expertOf(window)->runner()->session()->run(w, true, {heard});
    QVERIFY(after.malfunction_iterations > 0);
    QVERIFY(!chatterRegionOf(heard).contains(after.chosenPoint().speed_rev_per_s, after.chosenPoint().depth_m));
    QVERIFY(std::abs(test::expertOf(window)->weights().c[2] - w.c[2]) > 1e-6);  // the table shows Rule 6's c
    window.document()->undoStack()->undo();
    QVERIFY(window.project()->expert->reported_chatter.empty());
  }

  // Re-ranking the 20-tool library after a weight change (target 100 ms; reported, not gated: docs/performance.md).
  // Operator rules (Rule 18) bound the GUI's ranking exactly as they bound `rank`: with a speed rule on
  // big cutters and a depth rule, q* of every tool obeys them and equals the CLI's on the same file.
  void operatorRulesBoundTheRankingAsInTheCli() {
    QTemporaryDir dir;
    gui::MainWindow window;
    window.setQuiet(true);
    window.show();
    QSignalSpy ranked(test::expertOf(window), &gui::ExpertFeature::rankingShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio-pareto-case.mxproj")));
    QVERIFY(ranked.wait(60000));
    const double unruled_speed = test::windowPart<widgets::RankingTable>(window)->rows().front().speed_rpm;
    QVERIFY2(unruled_speed > 1200.0, qPrintable(QString::number(unruled_speed)));
    app::Project edited = *window.project();
    edited.operator_rules =
        QStringList{R"(if tool.diameter_mm > 10 then speed_rpm <= 1200 because "big cutter")", "depth_mm <= 0.5"};
    ranked.clear();
    QCOMPARE(window.document()->applyEdit(edited, "rules"), QString());
    QVERIFY(test::windowPart<widgets::RankingTable>(window)->isStale());  // at once: the rules bound it
    QVERIFY(ranked.wait(60000));
    QVERIFY(!test::windowPart<widgets::RankingTable>(window)->isStale());
    const QVector<widgets::RankingRow> rows = test::windowPart<widgets::RankingTable>(window)->rows();
    QVERIFY(!rows.isEmpty());
    for (const widgets::RankingRow& r : rows) {
      QVERIFY2(r.speed_rpm <= 1200.0 + 1e-9, qPrintable(QString::number(r.speed_rpm)));
      QVERIFY2(r.depth_mm <= 0.5 + 1e-12, qPrintable(QString::number(r.depth_mm)));
    }
    const QString saved = dir.filePath("ruled.mxproj");
    QVERIFY(window.saveProject(saved));
    const test::CliRun cli = test::runCli({"rank", saved, "--no-simulation"});
    QCOMPARE(cli.code, 0);
    const QJsonObject q = cli.json["q_star"].toObject();
    QCOMPARE(test::windowPart<widgets::RankingTable>(window)->selectedTool(), cli.json["selected"].toString());
    QCOMPARE_LE(std::abs(rows.front().speed_rpm - q["speed_rpm"].toDouble()), 1e-6);
    QCOMPARE_LE(std::abs(rows.front().depth_mm - q["depth_mm"].toDouble()), 1e-9);
  }

  // A report exported from the window names the project's own file (never the temporary snapshot it is
  // computed from), and says when the open project has unsaved changes.
  void exportedReportNamesTheProjectFile() {
    QTemporaryDir dir;
    const QString project = dir.filePath("shop.mxproj");
    QVERIFY(QFile::copy(MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj", project));
    QFile(project).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
    gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy ranked(test::expertOf(window), &gui::ExpertFeature::rankingShown);
    QVERIFY(window.openProject(project));
    QVERIFY(ranked.wait(60000));
    gui::ExpertFeature* expert = test::expertOf(window);
    expert->setReportProgram(QFileInfo(MX_CLI_PATH).absoluteDir().filePath("gui/millexpert-report"));
    auto exportHtml = [&](const QString& name) {
      QSignalSpy written(expert, &gui::ExpertFeature::reportWritten);
      expert->exportReportTo(dir.filePath(name));
      if (!written.wait(120000)) return QString();
      QFile file(dir.filePath(name));
      return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
    };
    const QString saved = exportHtml("saved.html");
    QVERIFY2(saved.contains("Project file: " + project + "</p>"), qPrintable(saved.left(2000)));
    QVERIFY(!saved.contains("millexpert-report-"));
    app::Project edited = *window.project();
    edited.name += " (edited)";
    QCOMPARE(window.document()->applyEdit(edited, "name"), QString());
    const QString dirty = exportHtml("dirty.html");
    QVERIFY2(dirty.contains("Project file: " + project + " (with unsaved changes)"), qPrintable(dirty.left(2000)));
    QCOMPARE(gui::reportProjectName(*window.document()), project + " (with unsaved changes)");
  }

  // A project without a stored operating point opens at q* of the active tool; a later ranking (other
  // weights) leaves the point there.
  void opensAtQStar() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.show();
    QSignalSpy refined(test::expertOf(window), &gui::ExpertFeature::refinementShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QVERIFY(refined.wait(60000));
    const gui::ExpertFeature* expert = test::expertOf(window);
    auto qStar = [&]() {
      const std::optional<Ranking> ranking = expert->runner()->rank(expert->weights().c);
      const qsizetype tool = expert->runner()->toolIds().indexOf(test::contextOf(window)->activeTool());
      for (const ToolChoice& t : ranking->tools)
        if (static_cast<qsizetype>(t.tool) == tool)
          return app::PickedPoint{t.q.speed_rev_per_s * 60.0, t.q.depth_m * 1e3, t.q.feed_per_tooth_m * 1e3};
      return app::PickedPoint{};
    };
    // The point is q* in shop units to 12 significant digits (no noise of the SI conversion in the file).
    auto isAt = [](const app::PickedPoint& p, const app::PickedPoint& q) {
      const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-11 * std::abs(b); };
      return near(p.speed_rpm, q.speed_rpm) && near(p.depth_mm, q.depth_mm) &&
             near(p.feed_mm_per_tooth, q.feed_mm_per_tooth);
    };
    QCOMPARE(test::contextOf(window)->activeTool(), QString("R1"));
    const app::PickedPoint first = qStar();
    QCOMPARE(window.document()->point().speed_rpm, 5800.0);
    QVERIFY(isAt(window.document()->point(), first));
    QVERIFY(!window.document()->isDirty());
    QCOMPARE(window.document()->undoStack()->count(), 0);

    app::Project edited = *window.project();
    edited.expert->c = {0.9, 0.05, 0.05};  // tool life first: another q*
    QCOMPARE(window.document()->applyEdit(edited, "weights"), QString());
    QVERIFY(!isAt(qStar(), first));
    QVERIFY(isAt(window.document()->point(), first));
  }

  // A session that ends just after an edit is of the project before it: dropped, so that the table
  // stays stale until the edited project's ranking (here one tool left of two) shows.
  void aSessionOfTheProjectBeforeAnEditIsDropped() {
    gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy refined(test::expertOf(window), &gui::ExpertFeature::refinementShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QVERIFY(refined.wait(60000));
    app::Project edited = *window.project();
    edited.tools[0].teeth = 4;  // a session of 2 tools
    QCOMPARE(test::applyEditAndHoldItsResults(window, edited, [&] { return test::expertOf(window)->runner()->busy(); }),
             QString());
    edited.tools.resize(1);
    QSignalSpy ranked(test::expertOf(window), &gui::ExpertFeature::rankingShown);
    QCOMPARE(window.document()->applyEdit(edited, "remove tool"), QString());
    QVERIFY(ranked.wait(60000));
    QCOMPARE(test::expertOf(window)->runner()->toolIds(), QStringList{"R1"});
    QCOMPARE(test::windowPart<widgets::RankingTable>(window)->rows().size(), 1);
  }

  // A point the user moves before the ranking arrives stays where it was moved.
  void aPointMovedBeforeTheRankingStays() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.show();
    QSignalSpy ranked(test::expertOf(window), &gui::ExpertFeature::rankingShown);
    QSignalSpy refined(test::expertOf(window), &gui::ExpertFeature::refinementShown);
    const app::PickedPoint moved{3000.0, 0.2, 0.1};
    int ranked_before_move = -1;
    connect(
        test::lobesOf(window), &gui::LobesFeature::lobesShown, this,
        [&] {
          ranked_before_move = static_cast<int>(ranked.count());
          window.document()->setPoint(moved);
        },
        Qt::SingleShotConnection);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QVERIFY(refined.wait(60000));
    QCOMPARE(ranked_before_move, 0);  // the lobes come first: the session needs them too
    QVERIFY(ranked.count() > 0);
    QCOMPARE(window.document()->point(), moved);
  }

  void reRankTwentyTools() {
    gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy ranked(test::expertOf(window), &gui::ExpertFeature::rankingShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("library-20-tools.mxproj")));
    QVERIFY(ranked.wait(60000));
    QCOMPARE(test::windowPart<widgets::RankingTable>(window)->rows().size(), 20);
    QSlider* c1 = test::windowPart<widgets::WeightsPanel>(window)->slider(widgets::WeightsPanel::Group::Tool, 0);
    c1->setSliderDown(true);
    QElapsedTimer clock;
    clock.start();
    for (int v = 100; v < 600; v += 50) c1->setValue(v);
    const double per_change = clock.nsecsElapsed() / 1e6 / 10.0;
    c1->setSliderDown(false);
    qInfo("re-rank of 20 tools after a weight change: %.2f ms (table and chart included)", per_change);
    QVERIFY(ranked.count() >= 10);
  }
};

MX_REGISTER_TEST(TestExpertFeature)
#include "test_expert_feature.moc"

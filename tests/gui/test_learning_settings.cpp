// Settings > Learning database in the main window: the Settings menu holds Shop units and Learning
// database (Edit > Preferences stays); accepting the dialog stores the setting learning/database and
// points the Pareto feature's history at it; Record point and the history go through the learning
// thread to an SQLite file and to a real PostgreSQL server, the status line naming the location
// (never options or a password); Test connection answers in the dialog while the GUI stays
// responsive.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <QAction>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTimer>

#include "history_view.h"
#include "learning_database_dialog.h"
#include "main_window.h"
#include "pareto_runner.h"
#include "pareto_weights_panel.h"
#include "services/learning_database.h"
#include "services/learning_location.h"
#include "shop_units_dialog.h"
#include "support/event_loop_probe.h"
#include "support/pareto_window.h"
#include "support/postgres_server.h"
#include "support/window_features.h"
#include "test_registry.h"

using namespace mx;

namespace {

QAction* menuActionByName(const gui::MainWindow& window, const QString& menu_name, const QString& text) {
  for (QAction* m : window.menuBar()->actions())
    if (m->menu() && m->menu()->objectName() == menu_name)
      for (QAction* a : m->menu()->actions())
        if (a->text() == text) return a;
  return nullptr;
}

}  // namespace

class TestLearningSettings : public QObject {
  Q_OBJECT
  std::unique_ptr<test::PostgresServer> server_;

 private slots:
  void init() { app::setConfiguredLearningDatabase({}); }

  void settingsMenu() {
    gui::MainWindow window;
    window.setQuiet(true);
    QAction* units = menuActionByName(window, "settingsMenu", "Shop &units...");
    QAction* learning = menuActionByName(window, "settingsMenu", "&Learning database...");
    QVERIFY(units);
    QVERIFY(learning);
    QVERIFY(!learning->toolTip().isEmpty());
    units->trigger();
    auto* preferences = window.findChild<widgets::ShopUnitsDialog*>();
    QVERIFY(preferences && preferences->isVisible());
    preferences->reject();
    learning->trigger();
    auto* dialog = window.findChild<widgets::LearningDatabaseDialog*>();
    QVERIFY(dialog && dialog->isVisible());
    QCOMPARE(dialog->location(), app::LearningDatabase::defaultPath());  // nothing configured yet
    dialog->reject();
  }

  // OK stores the setting and moves the history to the chosen file; the default file is stored as
  // "no choice".
  void acceptingSetsTheSettingAndTheFeature() {
    QTemporaryDir dir;
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    gui::ParetoFeature* pareto = test::paretoOf(window);
    const QString file = dir.filePath("shop/learning.sqlite");
    QVERIFY(QDir().mkpath(dir.filePath("shop")));
    widgets::LearningDatabaseDialog* dialog = pareto->openLearningDatabaseSettings();
    dialog->fileEdit()->setText(file);
    QVERIFY(dialog->okButton()->isEnabled());
    QSignalSpy shown(pareto, &gui::ParetoFeature::historyShown);
    dialog->okButton()->click();
    QCOMPARE(app::configuredLearningDatabase(), file);
    QCOMPARE(app::LearningDatabase::configuredOrDefault(), file);
    QCOMPARE(pareto->learningDatabasePath(), file);
    QVERIFY(shown.count() > 0 || shown.wait(10000));
    QVERIFY(test::waitForLearning(window));
    auto* history = test::windowPart<widgets::HistoryView>(window);
    QCOMPARE(history->statusLabel()->text(), QString("0 of 0 entries - %1").arg(file));
    // Reopened, the dialog shows the stored choice.
    dialog = pareto->openLearningDatabaseSettings();
    QCOMPARE(dialog->fileEdit()->text(), file);
    dialog->fileEdit()->clear();  // the default file
    dialog->okButton()->click();
    QCOMPARE(app::configuredLearningDatabase(), QString());
    QCOMPARE(pareto->learningDatabasePath(), app::LearningDatabase::defaultPath());
    QVERIFY(test::waitForLearning(window));
  }

  void recordThroughTheWorker_data() {
    QTest::addColumn<bool>("postgres");
    QTest::newRow("sqlite") << false;
    QTest::newRow("postgresql") << true;
  }
  void recordThroughTheWorker() {
    QFETCH(bool, postgres);
    QTemporaryDir dir;
    QString location = dir.filePath("learning.sqlite");
    if (postgres) {
      if (!server_) {
        server_ = std::make_unique<test::PostgresServer>();
        const QString why = server_->start();
        if (!why.isEmpty()) server_.reset();
        QVERIFY2(why.isEmpty(), qPrintable("the PostgreSQL server did not start: " + why));
      }
      QString why;
      QVERIFY2(server_->createDatabase("gui_history", &why), qPrintable(why));
      location = server_->url("gui_history") + "?connect_timeout=5";
    }
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    gui::ParetoFeature* pareto = test::paretoOf(window);
    auto* history = test::windowPart<widgets::HistoryView>(window);
    pareto->setLearningDatabasePath(location);
    const QString shown = app::parseLearningLocation(location).display();
    QCOMPARE(history->statusLabel()->text(), QString("Loading history from %1...").arg(shown));
    QVERIFY(test::waitForLearning(window));
    QCOMPARE(history->rows().size(), 0);
    QSignalSpy status(pareto, &gui::ParetoFeature::statusMessage);
    pareto->moveToChoice();
    pareto->recordOperatingPoint();
    QCOMPARE(status.last().at(0).toString(), QString("Recording the point in %1...").arg(shown));
    QVERIFY(!pareto->learningIdle());
    QVERIFY(test::waitForLearning(window));
    QCOMPARE(status.last().at(0).toString(), QString("Recorded point 1 in %1").arg(shown));
    QCOMPARE(history->rows().size(), 1);
    QCOMPARE(history->rows().front().source, QString("automatic"));
    QCOMPARE(history->rows().front().machine, QString());  // the case names no machine
    QCOMPARE(history->table()->item(0, widgets::HistoryView::MachineColumn)->text(), QString::fromUtf8("\u2014"));
    QCOMPARE(history->statusLabel()->text(), QString("1 of 1 entries - %1").arg(shown));
    QVERIFY(!history->statusLabel()->text().contains("connect_timeout"));
    pareto->recordOperatingPoint();
    QVERIFY(test::waitForLearning(window));
    QCOMPARE(history->rows().size(), 2);
    app::LearningDatabase db(location, app::LearningDatabase::OpenMode::ExistingOnly);
    QCOMPARE(db.count(), 2);
  }

  // The dialog's Test connection against a server that never answers: "Testing..." while the GUI
  // keeps handling events within 100 ms, then the failure naming the URL, and the button back.
  void testConnectionKeepsTheGuiResponsive() {
    const mx::test::LoopbackPort silent(mx::test::LoopbackPort::Mode::Listening);
    QVERIFY(silent.port() > 0);
    gui::MainWindow window;
    window.setQuiet(true);
    window.show();
    widgets::LearningDatabaseDialog* dialog = test::paretoOf(window)->openLearningDatabaseSettings();
    const QString url = QString("postgresql://planner@127.0.0.1:%1/learning?connect_timeout=2").arg(silent.port());
    dialog->serverChoice()->click();
    dialog->urlEdit()->setText(url);
    test::EventLoopProbe probe;
    QTimer::singleShot(0, dialog->testButton(), [dialog] { dialog->testButton()->click(); });
    QTest::qWait(300);
    QCOMPARE(dialog->testButton()->text(), QString("Testing..."));
    QVERIFY(!dialog->testButton()->isEnabled());
    QVERIFY(QTest::qWaitFor([dialog] { return dialog->testButton()->isEnabled(); }, 15000));
    QCOMPARE(dialog->testButton()->text(), QString("Test connection"));
    const QString result = dialog->resultLabel()->text();
    QVERIFY2(result.contains(QString("postgresql://planner@127.0.0.1:%1/learning").arg(silent.port())),
             qPrintable(result));
    QVERIFY2(!result.startsWith("Connected"), qPrintable(result));
    QVERIFY2(probe.longestMs() < 100 * MX_TIMING_SCALE,
             qPrintable(QString("%1 ms in %2").arg(probe.longestMs()).arg(probe.longestEvent())));
    dialog->reject();
    QCOMPARE(app::configuredLearningDatabase(), QString());  // Cancel stores nothing
  }
};

MX_REGISTER_TEST(TestLearningSettings)
#include "test_learning_settings.moc"

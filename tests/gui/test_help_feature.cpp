// Help in the main window: the Help menu after View, whose User guide (F1) opens the guide compiled
// into the program in a window of its own; What's This on ROS, ΔN_s, q*, q**, η and J_c wherever they
// are shown; the Examples menu; and the start page of an empty project (at start and after File > New)
// over the chart, whose choices open an example or a recent project, import a tap test or a tool
// library, or open a file, and which gives way once the project has a tool.
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTimer>
#include <QUndoStack>
#include <functional>

#include "glossary.h"
#include "guide_window.h"
#include "help_feature.h"
#include "indicator_gauge.h"
#include "jc_curve_plot.h"
#include "main_window.h"
#include "ranking_table.h"
#include "ranking_table_model.h"
#include "start_screen.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"
#include "tool_library_transfer.h"

using namespace mx;
using widgets::Term;

namespace {

gui::HelpFeature* helpOf(const gui::MainWindow& window) {
  return test::windowPart<gui::HelpFeature>(window, "helpFeature");
}

QAction* actionWithShortcut(const gui::MainWindow& window, QKeySequence::StandardKey key) {
  for (QAction* action : window.findChildren<QAction*>())
    if (action->shortcut() == QKeySequence(key)) return action;
  return nullptr;
}

// The title of the modal dialog that `act` opens, closed as soon as it shows; "" when none opens.
QString modalTitle(const std::function<void()>& act) {
  QString title;
  QTimer poll;
  poll.setInterval(20);
  QObject::connect(&poll, &QTimer::timeout, [&title] {
    QWidget* modal = QApplication::activeModalWidget();
    if (!modal) return;
    title = modal->windowTitle();
    if (auto* dialog = qobject_cast<QDialog*>(modal))
      dialog->reject();
    else
      modal->close();
  });
  poll.start();
  act();
  return title;
}

QByteArray readAll(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}
}  // namespace

class TestHelpFeature : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
    QSettings().remove("recentFiles");
  }

  void theHelpMenuComesAfterView() {
    gui::MainWindow window;
    QStringList menus;
    for (QAction* a : window.menuBar()->actions()) menus << a->text();
    QCOMPARE(menus, QStringList({"&File", "&Edit", "&View", "&Settings", "&Help"}));
    QMenu* help = window.menuBar()->actions().last()->menu();
    QStringList entries;
    for (QAction* a : help->actions())
      if (!a->isSeparator()) entries << a->text();
    QCOMPARE(entries.mid(0, 3), QStringList({"&User guide", "What's This?", "&Examples"}));
    QVERIFY(entries.contains("&About MillExpert"));
    QCOMPARE(window.findChild<QAction*>("whatsThisAction")->shortcut(), QKeySequence("Shift+F1"));
    const QString about = gui::HelpFeature::aboutText();
    QVERIFY2(about.contains(QRegularExpression(R"(MillExpert \d+\.\d+\.\d+)")) && about.contains(qVersion()) &&
                 about.contains("QCustomPlot") && about.contains("GPL"),
             qPrintable(about));
  }

  void theUserGuideOpensInAWindowOfItsOwn() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.show();
    QAction* guide = window.findChild<QAction*>("userGuideAction");
    QVERIFY(guide);
    QCOMPARE(guide->shortcut(), QKeySequence(QKeySequence::HelpContents));
    QCOMPARE(guide->shortcut(), QKeySequence("F1"));
    guide->trigger();
    auto* shown = window.findChild<widgets::GuideWindow*>("guideWindow");
    QVERIFY(shown);
    QVERIFY(shown->isVisible() && shown->isWindow());
    QCOMPARE(shown->windowModality(), Qt::NonModal);
    const QString text = shown->browser()->toPlainText();
    QVERIFY(text.startsWith("MillExpert user guide"));
    QVERIFY(text.contains("stability lobe"));
    QVERIFY(text.contains("Getting help"));
    const QStringList headings = shown->headings();
    QCOMPARE(headings.value(0), QString("MillExpert user guide"));
    QVERIFY(headings.contains("Getting help") && headings.contains("Glossary"));
    shown->followLink(QUrl("#glossary"));
    QCOMPARE(shown->browser()->textCursor().block().text(), QString("Glossary"));
    guide->trigger();  // again: the same window, raised
    QCOMPARE(window.findChildren<widgets::GuideWindow*>().size(), 1);
  }

  // The guide in the program is docs/user-guide.md, with every picture it shows.
  void theGuideIsCompiledInWithItsPictures() {
    const QUrl url = gui::HelpFeature::guideUrl();
    QCOMPARE(url.scheme(), QString("qrc"));
    const QByteArray shipped = readAll(":" + url.path());
    QVERIFY(!shipped.isEmpty());
    QCOMPARE(shipped, readAll(MX_PROJECTS_DIR "/../docs/user-guide.md"));
    const QRegularExpression picture(R"(\]\((screenshots/[^)]+\.png)\))");
    int pictures = 0;
    for (const QRegularExpressionMatch& m : picture.globalMatch(QString::fromUtf8(shipped))) {
      const QString resource = ":/help/" + m.captured(1);
      QVERIFY2(!QImage(resource).isNull(), qPrintable(resource + " is not in app/gui/help.qrc"));
      ++pictures;
    }
    QVERIFY(pictures >= 6);
  }

  void whatsThisExplainsTheSixTerms() {
    gui::MainWindow window;
    auto label = [&window](const char* name) {
      auto* l = window.findChild<QLabel*>(name);
      return l ? l->whatsThis() : QString("no %1").arg(name);
    };
    const QString ros = widgets::glossaryText(Term::Ros), dns = widgets::glossaryText(Term::DeltaNs);
    const QString eta = widgets::glossaryText(Term::Eta), jc = widgets::glossaryText(Term::Jc);
    QCOMPARE(label("readout_ros"), ros);
    QCOMPARE(label("readout_dns"), dns);
    QCOMPARE(label("readout_simulation"), eta);
    QCOMPARE(label("monitoring_ros"), ros);
    QCOMPARE(label("monitoring_eta"), eta);
    QCOMPARE(label("control_metric_jc"), jc);
    QCOMPARE(window.findChild<widgets::IndicatorGauge*>("etaGauge")->whatsThis(), eta);
    QCOMPARE(window.findChild<widgets::JcCurvePlot*>()->whatsThis(), jc);
    auto* ranking = window.findChild<widgets::RankingTable*>();
    auto header = [ranking](int column) {
      return ranking->model()->headerData(column, Qt::Horizontal, Qt::WhatsThisRole).toString();
    };
    using Model = widgets::RankingTableModel;
    QCOMPARE(header(Model::Speed), widgets::glossaryText(Term::QStar));
    QCOMPARE(header(Model::Feed), widgets::glossaryText(Term::QStar));
    QCOMPARE(header(Model::ResultantCost), widgets::glossaryText(Term::QStarStar));
    QCOMPARE(header(Model::Dns), dns);
    QVERIFY(header(Model::Tool).isEmpty());
    QVERIFY(ranking->whatsThis().contains(widgets::glossaryText(Term::QStarStar)));
    for (Term term : widgets::kGlossaryTerms) QVERIFY(!widgets::glossaryText(term).isEmpty());
  }

  void aWindowWithoutAProjectShowsTheStartScreen() {
    gui::MainWindow window;
    window.show();
    gui::HelpFeature* help = helpOf(window);
    QVERIFY(help->startScreenShown());
    widgets::StartScreen* start = help->startScreen();
    QVERIFY(start->isVisible());
    QTRY_COMPARE(start->geometry(), window.centralWidget()->geometry());  // over the chart, not the docks
    QCOMPARE(window.centralWidget(), test::lobesOf(window)->chart());
  }

  void newProjectShowsTheStartScreenAndAnExampleOpensFromIt() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    window.show();
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    gui::HelpFeature* help = helpOf(window);
    QVERIFY(!help->startScreenShown());
    QAction* create = actionWithShortcut(window, QKeySequence::New);
    QVERIFY(create);
    create->trigger();
    QVERIFY(window.project()->tools.empty());
    QVERIFY(help->startScreenShown());
    widgets::StartScreen* start = help->startScreen();
    QVERIFY(start->isVisible());
    QCOMPARE(start->recentList()->count(), 1);  // the project opened above
    QCOMPARE(start->recentList()->item(0)->text(), QString("rubio2006-tool-selection.mxproj"));

    QListWidget* examples = start->exampleList();
    int rubio = -1;
    for (int row = 0; row < examples->count(); ++row)
      if (examples->item(row)->data(Qt::UserRole).toString().endsWith("/rubio2006-tool-selection.mxproj")) rubio = row;
    QVERIFY2(rubio >= 0, "rubio2006-tool-selection.mxproj is not among the examples");
    QVERIFY(examples->count() >= 5);
    examples->setCurrentRow(rubio);
    start->button("startOpenExample")->click();
    QVERIFY(window.document()->filePath().endsWith("/rubio2006-tool-selection.mxproj"));
    QCOMPARE(window.project()->tools.size(), std::size_t(2));
    QVERIFY(!help->startScreenShown());
    QVERIFY(!start->isVisible());
  }

  void theExamplesMenuOpensAnExample() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    auto* menu = window.findChild<QMenu*>("examplesMenu");
    QVERIFY(menu);
    QAction* tap_test = nullptr;
    for (QAction* a : menu->actions())
      if (a->data().toString().endsWith("/tap-test-example.mxproj")) tap_test = a;
    QVERIFY(tap_test);
    QVERIFY(tap_test->text().startsWith("Tap-test example"));
    tap_test->trigger();
    QVERIFY(window.document()->filePath().endsWith("/tap-test-example.mxproj"));
    QVERIFY(!helpOf(window)->startScreenShown());
  }

  void aRecentProjectOpensFromTheStartScreen() {
    const QString project = mx::test::exampleCopy("rubio2006-tool-selection.mxproj");
    QSettings().setValue("recentFiles", QStringList{project});
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    window.show();
    QListWidget* recent = helpOf(window)->startScreen()->recentList();
    QCOMPARE(recent->count(), 1);
    emit recent->itemClicked(recent->item(0));
    QCOMPARE(window.document()->filePath(), project);
    QVERIFY(!helpOf(window)->startScreenShown());
  }

  // Each button opens the dialog of the window's own action for it.
  void theButtonsOpenTheirActionsDialogs_data() {
    QTest::addColumn<QString>("button");
    QTest::addColumn<QString>("dialog");
    QTest::newRow("tap test") << "startImportTapTest"
                              << "Import tap test";
    QTest::newRow("tool library") << "startImportToolLibrary"
                                  << "Import tool library";
    QTest::newRow("open") << "startOpenProject"
                          << "Open project";
  }
  void theButtonsOpenTheirActionsDialogs() {
    QFETCH(QString, button);
    QFETCH(QString, dialog);
    gui::MainWindow window;
    window.setQuiet(true);
    window.show();
    QPushButton* b = helpOf(window)->startScreen()->button(button);
    QVERIFY(b);
    QCOMPARE(modalTitle([b] { b->click(); }), dialog);
    QVERIFY(helpOf(window)->startScreenShown());  // cancelled: the project is still empty
  }

  // An empty library's "Add a tool": one undoable new tool, the lobes instead of the page.
  void addAToolFromTheStartScreen() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    window.show();
    QVERIFY(helpOf(window)->startScreenShown());
    helpOf(window)->startScreen()->button("startAddTool")->click();
    QCOMPARE(window.project()->tools.size(), std::size_t{1});
    QVERIFY(!helpOf(window)->startScreenShown());
    window.document()->undoStack()->undo();
    QVERIFY(helpOf(window)->startScreenShown());
  }

  void anImportedToolLibraryHidesTheStartScreen() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    window.show();
    QVERIFY(helpOf(window)->startScreenShown());
    gui::ToolLibraryTransfer* transfer = test::editorsOf(window)->libraryTransfer();
    QSignalSpy finished(transfer, &gui::ToolLibraryTransfer::importFinished);
    transfer->importFile(MX_PROJECTS_DIR "/libraries/fusion-endmills.json", std::nullopt, {},
                         [](const QString&, const app::ImportedLibrary&) {
                           return std::optional<gui::ToolLibraryTransfer::Choice>(gui::ToolLibraryTransfer::Choice{});
                         });
    QVERIFY(finished.wait(30000));
    QCOMPARE(finished.at(0).at(0).toString(), QString());
    QVERIFY(!window.project()->tools.empty());
    QVERIFY(!helpOf(window)->startScreenShown());
    window.document()->undoStack()->undo();  // no tool again: the page is back
    QVERIFY(window.project()->tools.empty());
    QVERIFY(helpOf(window)->startScreenShown());
  }
};

MX_REGISTER_TEST(TestHelpFeature)
#include "test_help_feature.moc"

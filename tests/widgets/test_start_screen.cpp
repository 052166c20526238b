// The start page of an empty project: the examples listed by name with the selected one's description,
// Open an example project (and a double click) asking for the selected example, the three other
// buttons each asking for their action, and the recent projects that still exist, a click opening one.
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>

#include "start_screen.h"
#include "test_registry.h"

using mx::widgets::StartEntry;
using mx::widgets::StartScreen;

namespace {
const QVector<StartEntry> kExamples = {
    {"/examples/a.mxproj", "Example A", "The first example."},
    {"/examples/b.mxproj", "", "No name: listed by its file."},
};
}  // namespace

class TestStartScreen : public QObject {
  Q_OBJECT
 private slots:
  void examplesAreListedWithTheSelectedDescription() {
    StartScreen screen;
    screen.setExamples(kExamples);
    QListWidget* list = screen.exampleList();
    QCOMPARE(list->count(), 2);
    QCOMPARE(list->item(0)->text(), QString("Example A"));
    QCOMPARE(list->item(1)->text(), QString("b.mxproj"));
    QCOMPARE(list->currentRow(), 0);
    auto* description = screen.findChild<QLabel*>("startExampleDescription");
    QCOMPARE(description->text(), QString("The first example."));
    list->setCurrentRow(1);
    QCOMPARE(description->text(), QString("No name: listed by its file."));
  }

  void openingAnExampleAsksForItsPath() {
    StartScreen screen;
    screen.setExamples(kExamples);
    QSignalSpy chosen(&screen, &StartScreen::projectChosen);
    screen.button("startOpenExample")->click();
    screen.exampleList()->setCurrentRow(1);
    emit screen.exampleList()->itemActivated(screen.exampleList()->item(1));  // a double click
    QCOMPARE(chosen.count(), 2);
    QCOMPARE(chosen.at(0).at(0).toString(), QString("/examples/a.mxproj"));
    QCOMPARE(chosen.at(1).at(0).toString(), QString("/examples/b.mxproj"));
  }

  void noExamplesDisablesOpen() {
    StartScreen screen;
    screen.setExamples({});
    QVERIFY(!screen.button("startOpenExample")->isEnabled());
    QCOMPARE(screen.findChild<QLabel*>("startExampleDescription")->text(), QString("No example projects were found."));
  }

  void eachButtonAsksForItsAction_data() {
    QTest::addColumn<QString>("button");
    QTest::addColumn<QString>("text");
    QTest::newRow("tap test") << "startImportTapTest"
                              << "Import a tap test...";
    QTest::newRow("tool library") << "startImportToolLibrary"
                                  << "Import a tool library...";
    QTest::newRow("add tool") << "startAddTool"
                              << "Add a tool";
    QTest::newRow("open") << "startOpenProject"
                          << "Open a project...";
  }
  void eachButtonAsksForItsAction() {
    QFETCH(QString, button);
    QFETCH(QString, text);
    StartScreen screen;
    QSignalSpy tap(&screen, &StartScreen::tapTestImportRequested);
    QSignalSpy library(&screen, &StartScreen::toolLibraryImportRequested);
    QSignalSpy open(&screen, &StartScreen::openProjectRequested);
    QSignalSpy add(&screen, &StartScreen::addToolRequested);
    QPushButton* b = screen.button(button);
    QVERIFY(b);
    QCOMPARE(b->text(), text);
    b->click();
    QCOMPARE(tap.count(), button == "startImportTapTest" ? 1 : 0);
    QCOMPARE(library.count(), button == "startImportToolLibrary" ? 1 : 0);
    QCOMPARE(open.count(), button == "startOpenProject" ? 1 : 0);
    QCOMPARE(add.count(), button == "startAddTool" ? 1 : 0);
  }

  void recentProjectsThatExistOpenOnAClick() {
    QTemporaryDir dir;
    const QString kept = dir.filePath("kept.mxproj");
    QFile file(kept);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.close();
    StartScreen screen;
    screen.show();
    screen.setRecentFiles({kept, dir.filePath("deleted.mxproj")});
    QListWidget* recent = screen.recentList();
    QCOMPARE(recent->count(), 1);
    QCOMPARE(recent->item(0)->text(), QString("kept.mxproj"));
    QVERIFY(recent->isVisible());
    QSignalSpy chosen(&screen, &StartScreen::projectChosen);
    emit recent->itemClicked(recent->item(0));
    QCOMPARE(chosen.count(), 1);
    QCOMPARE(chosen.at(0).at(0).toString(), kept);

    screen.setRecentFiles({});
    QVERIFY(!recent->isVisible());
    QLabel* none = nullptr;
    for (QLabel* label : screen.findChildren<QLabel*>())
      if (label->text() == "No recent projects yet.") none = label;
    QVERIFY(none && none->isVisible());
  }
};

MX_REGISTER_TEST(TestStartScreen)
#include "test_start_screen.moc"

// The tool list beside the lobe chart: filling it signals nothing, a tick does; the pockets list names
// the best pocket, caps at kMaxPockets, says when there is none, and emits the pocket clicked; the
// cursor line falls back to its hint.
#include <QListWidget>
#include <QSignalSpy>
#include <QTest>

#include "lobe_tool_panel.h"
#include "test_registry.h"

using mx::widgets::LobeToolPanel;
using mx::widgets::StabilityPocket;

class TestLobeToolPanel : public QObject {
  Q_OBJECT

 private slots:
  void fillingSignalsNothingATickDoes() {
    LobeToolPanel panel;
    QSignalSpy toggled(&panel, &LobeToolPanel::toolVisibilityToggled);
    panel.setTools({{"R1", "R1 tip", {}, true}, {"R2", "R2 tip", {}, false}});
    panel.setToolVisible(0, false);
    QCOMPARE(toggled.count(), 0);
    QCOMPARE(panel.toolList()->item(1)->checkState(), Qt::Unchecked);
    QCOMPARE(panel.toolList()->item(1)->toolTip(), QString("R2 tip"));
    panel.toolList()->item(1)->setCheckState(Qt::Checked);
    QCOMPARE(toggled.count(), 1);
    QCOMPARE(toggled.front()[0].toInt(), 1);
    QCOMPARE(toggled.front()[1].toBool(), true);
  }

  void pocketsAreNamedAndCapped_data() {
    QTest::addColumn<int>("count");
    QTest::addColumn<int>("rows");
    QTest::addColumn<QString>("first");
    QTest::newRow("none") << 0 << 1 << "none in the computed speed range";
    QTest::newRow("one") << 1 << 1 << "best: 1000 rpm, 2.00 mm";
    QTest::newRow("more than the cap") << 20 << LobeToolPanel::kMaxPockets << "best: 1000 rpm, 2.00 mm";
  }
  void pocketsAreNamedAndCapped() {
    QFETCH(int, count);
    QFETCH(int, rows);
    QFETCH(QString, first);
    QVector<StabilityPocket> pockets;
    for (int i = 0; i < count; ++i) pockets.push_back({1000.0 + 100.0 * i, 2.0 - 0.05 * i});
    LobeToolPanel panel;
    panel.setPockets("R1", pockets, 1.0, "mm");
    QCOMPARE(panel.pocketList()->count(), rows);
    QCOMPARE(panel.pocketList()->item(0)->text(), first);
    if (count > 1) QCOMPARE(panel.pocketList()->item(1)->text(), QString("1100 rpm, 1.95 mm"));
  }

  void aClickedPocketIsEmitted() {
    LobeToolPanel panel;
    panel.resize(240, 500);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setPockets("R1", {{4200.0, 1.385}, {3100.0, 1.1}}, 1.0, "mm");
    QSignalSpy chosen(&panel, &LobeToolPanel::pocketChosen);
    QListWidget* list = panel.pocketList();
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(list->item(1)).center());
    QCOMPARE(chosen.count(), 1);
    QCOMPARE(chosen.front()[0].toDouble(), 3100.0);
    QCOMPARE(chosen.front()[1].toDouble(), 1.1);
    panel.setPockets("R1", {}, 1.0, "mm");  // "none": a click moves nothing
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(list->item(0)).center());
    QCOMPARE(chosen.count(), 1);
  }

  void cursorTextFallsBackToItsHint() {
    LobeToolPanel panel;
    const QString hint = panel.cursorText();
    QVERIFY(hint.contains("b_lim"));
    panel.setCursorText("Cursor: N = 3000 rpm");
    QCOMPARE(panel.cursorText(), QString("Cursor: N = 3000 rpm"));
    panel.setCursorText({});
    QCOMPARE(panel.cursorText(), hint);
  }
};

MX_REGISTER_TEST(TestLobeToolPanel)
#include "test_lobe_tool_panel.moc"

// The part-program override panel: the table (columns with units, "=" for kept values, highlighted
// changes, read-only), the header with the changed count, the changed-only filter, the warnings and
// their activation, the buttons and signals, and a 100 000-block program set in well under a second.
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>

#include "display_units.h"
#include "part_program_panel.h"
#include "support/optional_double_metatype.h"
#include "test_registry.h"

using mx::widgets::PartProgramPanel;
using mx::widgets::PartProgramRow;
using mx::widgets::PartProgramWarningView;

namespace {

PartProgramRow row(int line, const QString& text, OptD f, OptD f_new, OptD s, OptD s_new, OptD depth, OptD force,
                   const QString& reason, bool changed) {
  PartProgramRow r;
  r.line = line;
  r.text = text;
  r.original_feed = f;
  r.new_feed = f_new;
  r.speed_rpm = s;
  r.new_speed_rpm = s_new;
  r.depth_mm = depth;
  r.predicted_force_n = force;
  r.reason = reason;
  r.changed = changed;
  return r;
}

QVector<PartProgramRow> partProgramRows() {
  return {
      row(1, "%", {}, {}, {}, {}, {}, {}, {}, false),
      row(2, "G21 G90", {}, {}, {}, {}, {}, {}, {}, false),
      row(3, "S2000 M3", {}, {}, 2000.0, 2500.0, {}, {}, "chatter-free lobe at 2500 rpm", true),
      row(4, "G1 X50 Z-2 F1200", 1200.0, 900.0, 2000.0, {}, 2.0, 812.345, "force above the limit", true),
      row(5, "G1 X100 F1200", 1200.0, 1200.0, 2000.0, 2000.0, 1.0, 402.0, {}, false),
      row(6, "G1 X120", {}, 850.5, {}, {}, 3.0, 799.99, "inserted F: deeper cut", true),
      row(7, "M30", {}, {}, {}, {}, {}, {}, {}, false),
  };
}

QVector<PartProgramWarningView> sampleWarnings() {
  return {{5, 9, "F1200", "feed above the machine limit"}, {6, 1, "G1 X120", "no feed in effect"}};
}

QString cell(const PartProgramPanel& p, int r, int c, int role = Qt::DisplayRole) {
  return p.table()->model()->index(r, c).data(role).toString();
}

QColor background(const PartProgramPanel& p, int r, int c) {
  return p.table()->model()->index(r, c).data(Qt::BackgroundRole).value<QColor>();
}

// A display path inside the test's temporary folder (the runner's TMPDIR); the file is never opened.
QString programPath(const QString& name) {
  return QDir::temp().filePath(name);
}

void loadSample(PartProgramPanel& panel, const QString& unit = "mm/min") {
  panel.setProgram(programPath("part.nc"), partProgramRows(), sampleWarnings(), unit, "Fanuc");
}

}  // namespace

class TestPartProgramPanel : public QObject {
  Q_OBJECT
 private slots:
  void emptyPanel() {
    PartProgramPanel panel;
    QVERIFY(!panel.hasProgram());
    QCOMPARE(panel.table()->model()->rowCount(), 0);
    QCOMPARE(panel.table()->model()->columnCount(), 9);
    QCOMPARE(panel.changedCount(), 0);
    QVERIFY(panel.openButton()->isEnabled());
    QVERIFY(!panel.exportProgramButton()->isEnabled());
    QVERIFY(!panel.exportCsvButton()->isEnabled());
    QVERIFY(panel.headerText().contains("No program"));
    QCOMPARE(panel.warningList()->count(), 0);
  }

  void headers_data() {
    QTest::addColumn<QString>("unit");
    QTest::newRow("metric") << "mm/min";
    QTest::newRow("inch") << "in/min";
  }
  void headers() {
    QFETCH(QString, unit);
    PartProgramPanel panel;
    loadSample(panel, unit);
    // Shown in the shop units (metric without DisplayUnits), whatever the program's unit.
    const QStringList want = {"Line",    "Block",       QString("F [mm/min]"), QString("F new [mm/min]"),
                              "S [rpm]", "S new [rpm]", "Depth [mm]",          "Predicted force [N]",
                              "Reason"};
    QAbstractItemModel* m = panel.table()->model();
    for (int c = 0; c < want.size(); ++c) {
      QCOMPARE(m->headerData(c, Qt::Horizontal).toString(), want[c]);
      QVERIFY(!m->headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString().isEmpty());
    }
    QCOMPARE(panel.feedUnit(), unit);
  }

  // The dialect to read programs in: detect by default, one entry per dialect; the AFC export is
  // offered for a shown Heidenhain program only; the header names the dialect read.
  void dialectChoiceAndAfcButton() {
    PartProgramPanel panel;
    QCOMPARE(panel.dialectChoice(), QString());
    QCOMPARE(panel.dialectBox()->count(), 5);
    QSignalSpy changed(&panel, &PartProgramPanel::dialectChanged);
    panel.setDialectChoice("sinumerik");
    QCOMPARE(panel.dialectChoice(), QString("sinumerik"));
    QCOMPARE(changed.size(), 1);
    QCOMPARE(changed.at(0).at(0).toString(), QString("sinumerik"));
    panel.setDialect("Heidenhain Klartext, detected at line 1: BEGIN PGM", true);
    QVERIFY(!panel.exportAfcButton()->isEnabled());  // no program shown
    loadSample(panel);
    panel.setDialect("Heidenhain Klartext, detected at line 1: BEGIN PGM", true);
    QVERIFY(panel.exportAfcButton()->isEnabled());
    QVERIFY(panel.headerText().startsWith(programPath("part.nc") + " \u2014 Heidenhain Klartext, detected at line 1"));
    QSignalSpy afc(&panel, &PartProgramPanel::exportAfcRequested);
    QTest::mouseClick(panel.exportAfcButton(), Qt::LeftButton);
    QCOMPARE(afc.size(), 1);
    panel.setDialect("ISO / Fanuc (chosen)", false);
    QVERIFY(!panel.exportAfcButton()->isEnabled());
    panel.clear();
    QVERIFY(!panel.exportAfcButton()->isEnabled());
  }
  void rowsAndChangedCount() {
    PartProgramPanel panel;
    loadSample(panel);
    QVERIFY(panel.hasProgram());
    QCOMPARE(panel.rows().size(), 7);
    QCOMPARE(panel.table()->model()->rowCount(), 7);
    QCOMPARE(panel.changedCount(), 3);
    QCOMPARE(panel.headerText(),
             QString(programPath("part.nc") + " \u2014 controller: Fanuc \u2014 3 of 7 blocks changed"));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kLine), QString("4"));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kBlock), QString("G1 X50 Z-2 F1200"));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kFeed), QString("1200"));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kNewFeed), QString("900.0"));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kDepth), QString("2.000"));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kForce), QString("812.3"));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kReason), QString("force above the limit"));
    QCOMPARE(cell(panel, 2, PartProgramPanel::kNewSpeed), QString("2500"));
    QCOMPARE(cell(panel, 0, PartProgramPanel::kFeed), QString());  // no value: empty, not "0"
    QVERIFY(!(panel.table()->model()->flags(panel.table()->model()->index(3, 3)) & Qt::ItemIsEditable));
    QCOMPARE(panel.table()->editTriggers(), QAbstractItemView::NoEditTriggers);
  }

  // The proposal columns: "=" when the programmed value is kept, the new value when changed, empty
  // with neither.
  void proposalCells_data() {
    QTest::addColumn<OptD>("original");
    QTest::addColumn<OptD>("proposed");
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("highlighted");
    QTest::newRow("kept, same value") << OptD(1200.0) << OptD(1200.0) << QString("=") << false;
    QTest::newRow("kept, no proposal") << OptD(1200.0) << OptD() << QString("=") << false;
    QTest::newRow("same at shown precision") << OptD(1200.0) << OptD(1200.04) << QString("=") << false;
    QTest::newRow("lowered") << OptD(1200.0) << OptD(900.0) << QString("900.0") << true;
    QTest::newRow("raised") << OptD(12.5) << OptD(14.25) << QString("14.25") << true;
    QTest::newRow("inserted") << OptD() << OptD(850.5) << QString("850.5") << true;
    QTest::newRow("neither") << OptD() << OptD() << QString() << false;
  }
  void proposalCells() {
    QFETCH(OptD, original);
    QFETCH(OptD, proposed);
    QFETCH(QString, text);
    QFETCH(bool, highlighted);
    PartProgramPanel panel;
    panel.setProgram("p.nc", {row(1, "G1 X1", original, proposed, original, proposed, {}, {}, {}, highlighted)}, {},
                     "mm/min", "ISO");
    QCOMPARE(cell(panel, 0, PartProgramPanel::kNewFeed), text);
    QCOMPARE(cell(panel, 0, PartProgramPanel::kNewSpeed), text);
    QCOMPARE(background(panel, 0, PartProgramPanel::kNewFeed).isValid(), highlighted);
    QCOMPARE(background(panel, 0, PartProgramPanel::kNewSpeed).isValid(), highlighted);
    if (highlighted) QCOMPARE(background(panel, 0, PartProgramPanel::kNewFeed), PartProgramPanel::highlightColor());
  }

  void highlights() {
    PartProgramPanel panel;
    loadSample(panel);
    QCOMPARE(background(panel, 3, PartProgramPanel::kNewFeed), PartProgramPanel::highlightColor());
    QVERIFY(background(panel, 3, PartProgramPanel::kReason).isValid());
    QCOMPARE(cell(panel, 3, PartProgramPanel::kNewSpeed), QString("="));
    QVERIFY(!background(panel, 3, PartProgramPanel::kNewSpeed).isValid());
    QVERIFY(background(panel, 2, PartProgramPanel::kNewSpeed).isValid());
    QCOMPARE(cell(panel, 4, PartProgramPanel::kNewFeed), QString("="));
    for (int c = 0; c < PartProgramPanel::kColumnCount; ++c) {
      QVERIFY(!background(panel, 4, c).isValid());  // an unchanged block: nothing highlighted
      QVERIFY(!background(panel, 3, c).isValid() || c == PartProgramPanel::kNewFeed || c == PartProgramPanel::kReason);
    }
  }

  // A modal proposal: the block has no F of its own and inherits the F proposed on an earlier line. The
  // cell shows the value in effect (not "="), in italics, and its tooltip names that line.
  void modalProposalShowsTheValueInEffect() {
    QVector<PartProgramRow> rows = partProgramRows();
    PartProgramRow inherited = row(8, "G1 Y40", 1200.0, 900.0, 2000.0, {}, 2.0, 700.0, {}, false);
    inherited.new_feed_from_line = 4;
    rows.append(inherited);
    PartProgramPanel panel;
    panel.setProgram(programPath("part.nc"), rows, sampleWarnings(), "mm/min", "Fanuc");
    const int last = static_cast<int>(rows.size()) - 1;
    QCOMPARE(cell(panel, last, PartProgramPanel::kNewFeed), cell(panel, 3, PartProgramPanel::kNewFeed));
    QVERIFY(cell(panel, last, PartProgramPanel::kNewFeed) != QString("="));
    QVERIFY(panel.table()->model()->index(last, PartProgramPanel::kNewFeed).data(Qt::FontRole).value<QFont>().italic());
    QVERIFY(cell(panel, last, PartProgramPanel::kNewFeed, Qt::ToolTipRole).contains("line 4"));
    QVERIFY(!panel.table()->model()->index(3, PartProgramPanel::kNewFeed).data(Qt::FontRole).value<QFont>().italic());
  }

  void filter() {
    PartProgramPanel panel;
    loadSample(panel);
    QVERIFY(!panel.showChangedOnly());
    panel.setShowChangedOnly(true);
    QVERIFY(panel.showChangedOnly());
    QVERIFY(panel.findChild<QCheckBox*>("partProgramChangedOnly")->isChecked());
    QCOMPARE(panel.visibleRowCount(), 3);
    QCOMPARE(cell(panel, 0, PartProgramPanel::kLine), QString("3"));
    QCOMPARE(cell(panel, 1, PartProgramPanel::kLine), QString("4"));
    QCOMPARE(cell(panel, 2, PartProgramPanel::kLine), QString("6"));
    QCOMPARE(panel.rows().size(), 7);  // the data are kept
    QSignalSpy spy(&panel, &PartProgramPanel::lineActivated);
    emit panel.table()->doubleClicked(panel.table()->model()->index(2, 1));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).toInt(), 6);  // the line of the filtered row
    panel.findChild<QCheckBox*>("partProgramChangedOnly")->setChecked(false);
    QVERIFY(!panel.showChangedOnly());
    QCOMPARE(panel.visibleRowCount(), 7);
    panel.setShowChangedOnly(true);
    loadSample(panel);  // a new program keeps the filter
    QCOMPARE(panel.visibleRowCount(), 3);
  }

  void warnings() {
    PartProgramPanel panel;
    loadSample(panel);
    QListWidget* list = panel.warningList();
    QCOMPARE(list->count(), 2);
    QCOMPARE(list->item(0)->text(), QString("line 5, column 9: F1200 \u2014 feed above the machine limit"));
    QCOMPARE(list->item(1)->text(), QString("line 6, column 1: G1 X120 \u2014 no feed in effect"));
    QSignalSpy spy(&panel, &PartProgramPanel::lineActivated);
    emit list->itemDoubleClicked(list->item(0));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).toInt(), 5);
    QCOMPARE(panel.selectedLine(), 5);
    // A warning on a block hidden by the filter clears the filter to select it.
    panel.setShowChangedOnly(true);
    emit list->itemDoubleClicked(list->item(0));
    QVERIFY(!panel.showChangedOnly());
    QCOMPARE(panel.selectedLine(), 5);
    emit list->itemDoubleClicked(list->item(1));
    QCOMPARE(panel.selectedLine(), 6);
    QCOMPARE(spy.count(), 3);
    QVERIFY(!panel.selectLine(99));
  }

  void signalsAndButtons() {
    PartProgramPanel panel;
    QSignalSpy open(&panel, &PartProgramPanel::openRequested);
    QSignalSpy program(&panel, &PartProgramPanel::exportProgramRequested);
    QSignalSpy csv(&panel, &PartProgramPanel::exportCsvRequested);
    QSignalSpy line(&panel, &PartProgramPanel::lineActivated);
    panel.openButton()->click();
    panel.exportProgramButton()->click();  // disabled: no signal
    panel.exportCsvButton()->click();
    QCOMPARE(open.count(), 1);
    QCOMPARE(program.count(), 0);
    QCOMPARE(csv.count(), 0);
    loadSample(panel);
    QVERIFY(panel.exportProgramButton()->isEnabled());
    QVERIFY(panel.exportCsvButton()->isEnabled());
    panel.exportProgramButton()->click();
    panel.exportCsvButton()->click();
    QCOMPARE(program.count(), 1);
    QCOMPARE(csv.count(), 1);
    emit panel.table()->doubleClicked(panel.table()->model()->index(3, 0));
    QCOMPARE(line.count(), 1);
    QCOMPARE(line.at(0).at(0).toInt(), 4);
    panel.setStatus("Exported 7 blocks");
    QCOMPARE(panel.statusText(), QString("Exported 7 blocks"));
    panel.clear();
    QVERIFY(!panel.hasProgram());
    QCOMPARE(panel.table()->model()->rowCount(), 0);
    QCOMPARE(panel.warningList()->count(), 0);
    QCOMPARE(panel.changedCount(), 0);
    QVERIFY(!panel.exportProgramButton()->isEnabled());
    QVERIFY(!panel.exportCsvButton()->isEnabled());
    QVERIFY(panel.openButton()->isEnabled());
    for (QPushButton* b : {panel.openButton(), panel.exportProgramButton(), panel.exportCsvButton()})
      QVERIFY(!b->toolTip().isEmpty());
  }

  void largeProgramIsFast() {
    QVector<PartProgramRow> rows;
    constexpr int kRows = 100000;
    rows.reserve(kRows);
    for (int i = 0; i < kRows; ++i) {
      const bool changed = i % 3 == 0;
      rows.push_back(row(i + 1, QString("N%1 G1 X%2 Y%3 F1200").arg(i + 1).arg(i % 400).arg(i % 77), 1200.0,
                         changed ? OptD(950.0) : OptD(1200.0), 2000.0, {}, 1.5, 700.0 + i % 100,
                         changed ? QString("force above the limit") : QString(), changed));
    }
    PartProgramPanel panel;
    panel.resize(1600, 900);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QElapsedTimer clock;
    clock.start();
    panel.setProgram(programPath("big.nc"), rows, {{50000, 1, "G1", "no feed"}}, "mm/min", "Heidenhain");
    QCoreApplication::processEvents();  // includes the repaint
    const qint64 ms = clock.elapsed();
    qInfo("setProgram with %d rows: %lld ms", kRows, static_cast<long long>(ms));
    QVERIFY2(ms < 3000, qPrintable(QString("%1 ms").arg(ms)));
    QCOMPARE(panel.table()->model()->rowCount(), kRows);
    QCOMPARE(panel.changedCount(), 33334);
    QVERIFY(panel.headerText().endsWith("33334 of 100000 blocks changed"));
    clock.restart();
    panel.setShowChangedOnly(true);
    QCoreApplication::processEvents();
    qInfo("changed-only filter on 100000 rows: %lld ms", static_cast<long long>(clock.elapsed()));
    QCOMPARE(panel.visibleRowCount(), 33334);
    QVERIFY(clock.elapsed() < 3000);
    emit panel.warningList()->itemDoubleClicked(panel.warningList()->item(0));
    QCOMPARE(panel.selectedLine(), 50000);
  }

  // Shop units: F in IPM, depth in in and force in lbf, whatever the program's unit; an inch program
  // (F in in/min) shows in mm/min with metric units.
  void followsShopUnits() {
    mx::widgets::DisplayUnits units;
    PartProgramPanel panel;
    panel.setUnits(&units);
    loadSample(panel);
    units.setShop(mx::widgets::ShopUnits::inch());
    QAbstractItemModel* m = panel.table()->model();
    QCOMPARE(m->headerData(PartProgramPanel::kFeed, Qt::Horizontal).toString(), QString("F [IPM]"));
    QCOMPARE(m->headerData(PartProgramPanel::kDepth, Qt::Horizontal).toString(), QString("Depth [in]"));
    QCOMPARE(m->headerData(PartProgramPanel::kForce, Qt::Horizontal).toString(), QString("Predicted force [lbf]"));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kFeed), QString("47.24"));     // 1200 mm/min
    QCOMPARE(cell(panel, 3, PartProgramPanel::kNewFeed), QString("35.43"));  // 900 mm/min
    QCOMPARE(cell(panel, 4, PartProgramPanel::kNewFeed), QString("="));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kDepth), QString("0.07874"));
    QCOMPARE(cell(panel, 3, PartProgramPanel::kForce), QString("182.6"));
    units.setShop(mx::widgets::ShopUnits::metric());
    loadSample(panel, "in/min");
    QCOMPARE(cell(panel, 3, PartProgramPanel::kFeed), QString("30480"));  // 1200 in/min
    QCOMPARE(panel.feedUnit(), QString("in/min"));
  }
};

MX_REGISTER_TEST(TestPartProgramPanel)
#include "test_part_program_panel.moc"

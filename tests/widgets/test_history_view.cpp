// The Rule 14 history view: rows formatted in the C locale (weights of Pareto and 2006 points, "–" for
// missing objectives, "—" for a record without a machine), the filter widgets (tool, material, machine,
// source, MRR band) produce the right HistoryFilter with one filterChanged() per
// user change and none from setFilter(), the apply button and double-click emit the selected Pareto
// row's weights, and setRows() keeps the selection by id.
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <limits>

#include "display_units.h"
#include "history_view.h"
#include "support/shown_texts.h"
#include "test_registry.h"

using mx::widgets::HistoryFilter;
using mx::widgets::HistoryRow;
using mx::widgets::HistoryView;

namespace {

using mx::test::kDash;

HistoryRow row(qint64 id, const QString& tool, QVector<double> weights, std::optional<double> tol = 38.71,
               const QString& machine = {}) {
  HistoryRow r;
  r.machine = machine;
  r.id = id;
  r.time = QString("2024-05-0%1T08:00:00.125Z").arg(id % 10);
  r.tool = tool;
  r.material = "Al 7075";
  r.source = "automatic";
  r.weights = std::move(weights);
  r.speed_rpm = 4540.4;
  r.depth_mm = 1.76;
  r.feed_mm_per_tooth = 0.11;
  r.mrr_cm3_s = 2.0412;
  r.tol = tol;
  r.surf = 0.8123;
  r.ros = 0.3456;
  return r;
}

QVector<HistoryRow> historyRows() {
  return {row(12, "R1", {0.1, 0.6, 0.1, 0.2}, 38.71, "VMC-7 Hermle C42"),
          row(11, "R2", {0.2, 0.725, 0.075}, std::nullopt), row(10, "R1", {0.25, 0.25, 0.25, 0.25})};
}

const QString kNoMachine = QStringLiteral("\u2014");

enum Action { ChooseTool, ChooseMaterial, ChooseMachine, ChooseSource, CheckMrr, EditMrrLo, EditMrrHi };

}  // namespace

class TestHistoryView : public QObject {
  Q_OBJECT
 private slots:
  void columns() {
    HistoryView view;
    const QStringList want = {"Time",
                              "Tool",
                              "Material",
                              "Machine",
                              "Source",
                              "w_TOL [\u2013]",
                              "w_MRR [\u2013]",
                              "w_SURF [\u2013]",
                              "w_ROS [\u2013]",
                              "Speed [rpm]",
                              "Depth [mm]",
                              "Feed [mm/tooth]",
                              "MRR [cm\u00b3/min]",
                              "TOL [min]",
                              "SURF [\u00b5m]",
                              "ROS [\u2013]"};
    QCOMPARE(view.table()->columnCount(), want.size());
    for (int c = 0; c < want.size(); ++c) {
      QCOMPARE(view.table()->horizontalHeaderItem(c)->text(), want[c]);
      QVERIFY(!view.table()->horizontalHeaderItem(c)->toolTip().isEmpty());
    }
    QVERIFY(!view.table()->isSortingEnabled());
    QCOMPARE(view.table()->editTriggers(), QAbstractItemView::NoEditTriggers);
    QCOMPARE(view.table()->selectionBehavior(), QAbstractItemView::SelectRows);
  }

  void rowsFormatted_data() {
    QTest::addColumn<int>("row");
    QTest::addColumn<QStringList>("cells");
    QTest::newRow("Pareto point") << 0
                                  << QStringList{"2024-05-02T08:00:00.125Z",
                                                 "R1",
                                                 "Al 7075",
                                                 "VMC-7 Hermle C42",
                                                 "automatic",
                                                 "0.100",
                                                 "0.600",
                                                 "0.100",
                                                 "0.200",
                                                 "4540",
                                                 "1.7600",
                                                 "0.1100",
                                                 "122.5",
                                                 "38.71",
                                                 "0.8123",
                                                 "0.3456"};
    QTest::newRow("2006 point, TOL missing") << 1
                                             << QStringList{"2024-05-01T08:00:00.125Z",
                                                            "R2",
                                                            "Al 7075",
                                                            kNoMachine,
                                                            "automatic",
                                                            "0.200",
                                                            "0.725",
                                                            "0.075",
                                                            "",
                                                            "4540",
                                                            "1.7600",
                                                            "0.1100",
                                                            "122.5",  // 2.0412 cm³/s in cm³/min
                                                            kDash,
                                                            "0.8123",
                                                            "0.3456"};
  }
  void rowsFormatted() {
    QFETCH(int, row);
    QFETCH(QStringList, cells);
    HistoryView view;
    view.setRows(historyRows());
    QCOMPARE(view.rows().size(), 3);
    QCOMPARE(view.table()->rowCount(), 3);
    for (int c = 0; c < cells.size(); ++c)
      QVERIFY2(view.table()->item(row, c)->text() == cells[c],
               qPrintable(
                   QString("column %1: '%2', expected '%3'").arg(c).arg(view.table()->item(row, c)->text(), cells[c])));
    QVERIFY(!(view.table()->item(row, 0)->flags() & Qt::ItemIsEditable));
  }

  void orderAsGivenAndNonFinite() {
    HistoryView view;
    auto rows = historyRows();
    rows[2].ros = std::numeric_limits<double>::quiet_NaN();
    rows[2].weights = {0.5, 0.5, 0.0, 0.0, 0.9};  // extra entries are not shown
    view.setRows(rows);
    QCOMPARE(view.table()->item(0, 1)->text(), QString("R1"));
    QCOMPARE(view.table()->item(1, 1)->text(), QString("R2"));
    QCOMPARE(view.table()->item(2, HistoryView::RosColumn)->text(), kDash);
    QCOMPARE(view.table()->item(2, HistoryView::WeightColumn0 + 3)->text(), QString("0.000"));
    view.setRows({});
    QCOMPARE(view.table()->rowCount(), 0);
    QCOMPARE(view.selectedRow(), -1);
  }

  void defaultFilterIsAny() {
    HistoryView view;
    QCOMPARE(view.filter(), HistoryFilter{});
    QCOMPARE(view.toolCombo()->itemText(0), QString("Any"));
    QCOMPARE(view.machineCombo()->itemText(0), QString("Any"));
    QCOMPARE(view.machineCombo()->count(), 1);
    QCOMPARE(view.sourceCombo()->count(), 5);
    QVERIFY(!view.mrrLoSpin()->isEnabled());
  }

  void filterFromWidgets_data() {
    QTest::addColumn<int>("action");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("tool");
    QTest::addColumn<QString>("material");
    QTest::addColumn<QString>("machine");
    QTest::addColumn<QString>("source");
    QTest::addColumn<double>("lo");  // NaN = no band
    QTest::addColumn<double>("hi");
    const double none = std::numeric_limits<double>::quiet_NaN();
    // Start: tool R1, material Any, source Any, band [1, 3] unchecked.
    const QString any;
    QTest::newRow("tool R2") << int(ChooseTool) << 2.0 << QString("R2") << any << any << any << none << none;
    QTest::newRow("tool Any") << int(ChooseTool) << 0.0 << any << any << any << any << none << none;
    QTest::newRow("material") << int(ChooseMaterial) << 2.0 << QString("R1") << QString("Steel") << any << any << none
                              << none;
    QTest::newRow("machine") << int(ChooseMachine) << 2.0 << QString("R1") << any << QString("VMC-7 Hermle C42") << any
                             << none << none;
    QTest::newRow("source feedback") << int(ChooseSource) << 4.0 << QString("R1") << any << any << QString("feedback")
                                     << none << none;
    QTest::newRow("source operator") << int(ChooseSource) << 1.0 << QString("R1") << any << any << QString("operator")
                                     << none << none;
    QTest::newRow("MRR band on") << int(CheckMrr) << 1.0 << QString("R1") << any << any << any << 1.0 << 3.0;
    QTest::newRow("MRR lo") << int(EditMrrLo) << 2.5 << QString("R1") << any << any << any << 2.5 << 3.0;
    QTest::newRow("MRR lo above hi") << int(EditMrrLo) << 5.0 << QString("R1") << any << any << any << 5.0 << 5.0;
    QTest::newRow("MRR hi below lo") << int(EditMrrHi) << 0.5 << QString("R1") << any << any << any << 0.5 << 0.5;
    QTest::newRow("MRR hi to 0") << int(EditMrrHi) << 0.0 << QString("R1") << any << any << any << 0.0 << 0.0;
  }
  void filterFromWidgets() {
    QFETCH(int, action);
    QFETCH(double, value);
    QFETCH(QString, tool);
    QFETCH(QString, material);
    QFETCH(QString, machine);
    QFETCH(QString, source);
    QFETCH(double, lo);
    QFETCH(double, hi);
    HistoryView view;
    view.setToolChoices({"R1", "R2", "R3"});
    view.setMaterialChoices({"Al 7075", "Steel"});
    view.setMachineChoices({"DMU 50", "VMC-7 Hermle C42"});
    HistoryFilter start;
    start.tool = "R1";
    view.setFilter(start);
    // The band in cm³/s; the spin boxes show cm³/min (60 times as much).
    view.mrrLoSpin()->blockSignals(true);
    view.mrrLoSpin()->setValue(60.0);
    view.mrrLoSpin()->blockSignals(false);
    view.mrrHiSpin()->blockSignals(true);
    view.mrrHiSpin()->setValue(180.0);
    view.mrrHiSpin()->blockSignals(false);
    if (action == EditMrrLo || action == EditMrrHi) view.mrrBox()->setChecked(true);
    QSignalSpy changed(&view, &HistoryView::filterChanged);
    const int index = static_cast<int>(value);
    switch (action) {
      case ChooseTool:
        view.toolCombo()->setCurrentIndex(index);
        break;
      case ChooseMaterial:
        view.materialCombo()->setCurrentIndex(index);
        break;
      case ChooseMachine:
        view.machineCombo()->setCurrentIndex(index);
        break;
      case ChooseSource:
        view.sourceCombo()->setCurrentIndex(index);
        break;
      case CheckMrr:
        view.mrrBox()->click();
        break;
      case EditMrrLo:
        view.mrrLoSpin()->setValue(60.0 * value);
        break;
      case EditMrrHi:
        view.mrrHiSpin()->setValue(60.0 * value);
        break;
    }
    HistoryFilter want;
    want.tool = tool;
    want.material = material;
    want.machine = machine;
    want.source = source;
    if (!std::isnan(lo)) {
      want.mrr_lo = lo;
      want.mrr_hi = hi;
    }
    QCOMPARE(view.filter(), want);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.at(0).at(0).value<HistoryFilter>(), want);
    QCOMPARE(view.mrrLoSpin()->isEnabled(), want.mrr_lo.has_value());
  }

  void noSignalWithoutAChange() {
    HistoryView view;
    view.setToolChoices({"R1", "R2"});
    QSignalSpy changed(&view, &HistoryView::filterChanged);
    view.toolCombo()->setCurrentIndex(0);  // already Any
    view.mrrLoSpin()->setValue(2.0);       // band off: the filter does not change
    QCOMPARE(changed.count(), 0);
    view.mrrBox()->click();
    view.mrrBox()->click();
    QCOMPARE(changed.count(), 2);
    QCOMPARE(changed.at(1).at(0).value<HistoryFilter>(), HistoryFilter{});
  }

  void setFilterIsSilentRoundTrip() {
    HistoryView view;
    view.setToolChoices({"R1", "R2"});
    view.setMaterialChoices({"Steel"});
    view.setMachineChoices({"DMU 50"});
    QSignalSpy changed(&view, &HistoryView::filterChanged);
    HistoryFilter f;
    f.tool = "R9";  // not among the choices: added
    f.material = "Steel";
    f.machine = "VMC-7";  // not among the choices: added
    f.source = "rule";
    f.mrr_lo = 0.5;
    f.mrr_hi = 2.25;
    view.setFilter(f);
    QCOMPARE(view.filter(), f);
    QCOMPARE(view.toolCombo()->currentText(), QString("R9"));
    QCOMPARE(view.machineCombo()->currentText(), QString("VMC-7"));
    QVERIFY(view.mrrBox()->isChecked());
    QVERIFY(view.mrrHiSpin()->isEnabled());
    // Choices replaced: the current tool is kept, no signal.
    view.setToolChoices({"R2", "R3"});
    QCOMPARE(view.filter(), f);
    view.setToolChoices({"R1", "R9"});
    QCOMPARE(view.toolCombo()->count(), 3);
    // Only one bound: no band; swapped bounds are ordered.
    HistoryFilter half;
    half.mrr_lo = 1.0;
    view.setFilter(half);
    QCOMPARE(view.filter(), HistoryFilter{});
    HistoryFilter swapped;
    swapped.mrr_lo = 4.0;
    swapped.mrr_hi = 2.0;
    view.setFilter(swapped);
    QCOMPARE(view.filter().mrr_lo, std::optional<double>(2.0));
    QCOMPARE(view.filter().mrr_hi, std::optional<double>(4.0));
    QCOMPARE(changed.count(), 0);
    // A later user change compares with the filter set, not the older one.
    view.mrrBox()->click();
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.at(0).at(0).value<HistoryFilter>(), HistoryFilter{});
  }

  // The machine choices as given after "Any", no empty entry (records without a machine); a record
  // without a machine shows "—" in its column.
  void machineColumnAndChoices() {
    HistoryView view;
    view.setMachineChoices({"DMU 50", "", "VMC-7 Hermle C42", "DMU 50"});
    QCOMPARE(view.machineCombo()->count(), 3);
    QCOMPARE(view.machineCombo()->itemText(1), QString("DMU 50"));
    QCOMPARE(view.machineCombo()->itemText(2), QString("VMC-7 Hermle C42"));
    view.setRows(historyRows());
    QCOMPARE(view.table()->item(0, HistoryView::MachineColumn)->text(), QString("VMC-7 Hermle C42"));
    QCOMPARE(view.table()->item(1, HistoryView::MachineColumn)->text(), kNoMachine);
    QCOMPARE(view.table()->item(2, HistoryView::MachineColumn)->text(), kNoMachine);
    QCOMPARE(HistoryView::MachineColumn, HistoryView::MaterialColumn + 1);
    QVERIFY(view.table()->horizontalHeaderItem(HistoryView::MachineColumn)->toolTip().contains("machine"));
  }

  void applyButton() {
    HistoryView view;
    QSignalSpy apply(&view, &HistoryView::applyWeightsRequested);
    QVERIFY(!view.applyButton()->isEnabled());  // no rows
    view.setRows(historyRows());
    QCOMPARE(view.selectedRow(), -1);
    QVERIFY(!view.applyButton()->isEnabled());  // no selection
    view.selectRow(1);                          // 2006 point: three weights
    QCOMPARE(view.selectedRow(), 1);
    QVERIFY(!view.applyButton()->isEnabled());
    view.selectRow(0);
    QVERIFY(view.applyButton()->isEnabled());
    view.applyButton()->click();
    QCOMPARE(apply.count(), 1);
    QCOMPARE(apply.at(0).at(0).value<QVector<double>>(), (QVector<double>{0.1, 0.6, 0.1, 0.2}));
    view.selectRow(7);  // out of range: none
    QCOMPARE(view.selectedRow(), -1);
    QVERIFY(!view.applyButton()->isEnabled());
  }

  void clickSelectsAndDoubleClickApplies() {
    HistoryView view;
    view.resize(1200, 400);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setRows(historyRows());
    QSignalSpy apply(&view, &HistoryView::applyWeightsRequested);
    QTableWidget* t = view.table();
    const QPoint at2 = t->visualRect(t->model()->index(2, 1)).center();
    QTest::mouseClick(t->viewport(), Qt::LeftButton, {}, at2);
    QCOMPARE(view.selectedRow(), 2);
    QVERIFY(view.applyButton()->isEnabled());
    QTest::mouseDClick(t->viewport(), Qt::LeftButton, {}, at2);
    QCOMPARE(apply.count(), 1);
    QCOMPARE(apply.at(0).at(0).value<QVector<double>>(), (QVector<double>{0.25, 0.25, 0.25, 0.25}));
    const QPoint at1 = t->visualRect(t->model()->index(1, 1)).center();
    QTest::mouseDClick(t->viewport(), Qt::LeftButton, {}, at1);  // 2006 point: nothing to apply
    QCOMPARE(apply.count(), 1);
  }

  void selectionKeptById_data() {
    QTest::addColumn<int>("selected");
    QTest::addColumn<bool>("prepend");
    QTest::addColumn<bool>("dropSelected");
    QTest::addColumn<int>("want");
    QTest::newRow("same rows") << 1 << false << false << 1;
    QTest::newRow("new row on top") << 0 << true << false << 1;
    QTest::newRow("last row, new on top") << 2 << true << false << 3;
    QTest::newRow("selected row gone") << 1 << true << true << -1;
    QTest::newRow("none selected") << -1 << true << false << -1;
  }
  void selectionKeptById() {
    QFETCH(int, selected);
    QFETCH(bool, prepend);
    QFETCH(bool, dropSelected);
    QFETCH(int, want);
    HistoryView view;
    auto rows = historyRows();
    view.setRows(rows);
    view.selectRow(selected);
    const qint64 id = selected >= 0 ? rows[selected].id : -1;
    if (dropSelected) rows.removeAt(selected);
    if (prepend) rows.prepend(row(13, "R3", {0.4, 0.3, 0.2, 0.1}));
    view.setRows(rows);
    QCOMPARE(view.selectedRow(), want);
    if (want >= 0) QCOMPARE(view.rows()[want].id, id);
    QCOMPARE(view.applyButton()->isEnabled(), want >= 0 && view.rows()[want].weights.size() == 4);
  }

  void refreshAndStatus() {
    HistoryView view;
    QSignalSpy refresh(&view, &HistoryView::refreshRequested);
    QSignalSpy changed(&view, &HistoryView::filterChanged);
    view.refreshButton()->click();
    QCOMPARE(refresh.count(), 1);
    QCOMPARE(changed.count(), 0);
    const QString status = QDir::temp().filePath("learning.sqlite") + ": 3 points";
    view.setStatus(status);
    QCOMPARE(view.statusLabel()->text(), status);
  }

  // Shop units: the columns and the band convert, the filter stays in cm³/s and keeps its bounds.
  void followsShopUnits() {
    mx::widgets::DisplayUnits units;
    HistoryView view;
    view.setUnits(&units);
    view.setRows(historyRows());
    HistoryFilter f;
    f.mrr_lo = 0.12345;
    f.mrr_hi = 2.5;
    view.setFilter(f);
    QSignalSpy changed(&view, &HistoryView::filterChanged);
    units.setShop(mx::widgets::ShopUnits::inch());
    QCOMPARE(changed.count(), 0);
    QCOMPARE(view.filter(), f);
    QCOMPARE(view.mrrLoSpin()->suffix(), QString::fromUtf8(" in³/min"));
    QCOMPARE(view.mrrHiSpin()->value(), 9.1536);  // 2.5 cm³/s = 150 cm³/min, 4 decimals
    QCOMPARE(view.table()->horizontalHeaderItem(HistoryView::DepthColumn)->text(), QString("Depth [in]"));
    QCOMPARE(view.table()->item(0, HistoryView::DepthColumn)->text(), QString("0.06929"));
    QCOMPARE(view.table()->item(0, HistoryView::FeedColumn)->text(), QString("0.00433"));
    QCOMPARE(view.table()->item(0, HistoryView::MrrColumn)->text(), QString("7.474"));
    view.mrrHiSpin()->setValue(6.1024);  // 100 cm³/min
    QCOMPARE(changed.count(), 1);
    QVERIFY(std::abs(*view.filter().mrr_hi - 6.1024 * 16.387064 / 60.0) < 1e-12);
    QCOMPARE(*view.filter().mrr_lo, 0.12345);
  }

  void everyControlHasATooltip() {
    HistoryView view;
    for (QWidget* w : std::initializer_list<QWidget*>{
             view.table(), view.applyButton(), view.refreshButton(), view.toolCombo(), view.materialCombo(),
             view.machineCombo(), view.sourceCombo(), view.mrrBox(), view.mrrLoSpin(), view.mrrHiSpin()})
      QVERIFY2(!w->toolTip().isEmpty(), qPrintable(w->objectName()));
    QCOMPARE(view.mrrLoSpin()->suffix(), QString(" cm\u00b3/min"));
    QVERIFY(view.mrrBox()->text().contains("[cm\u00b3/min]"));
  }
};

MX_REGISTER_TEST(TestHistoryView)
#include "test_history_view.moc"

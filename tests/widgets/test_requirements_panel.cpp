// The requirements panel (Rule 11 bounds, Rule 12 button): round trip through setRequirement(), the
// bounds stay ordered when the user edits one past the other, one requirementChanged() per user edit
// and none from setRequirement(), units and ranges follow the objective, coloured status lines.
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <cmath>
#include <limits>

#include "display_units.h"
#include "indicator_gauge.h"
#include "requirements_panel.h"
#include "support/test_constants.h"
#include "test_registry.h"

using mx::widgets::IndicatorGauge;
using mx::widgets::RequirementsPanel;
using mx::widgets::RequirementView;

namespace {
using mx::test::kInf;
using mx::test::kNaN;
}  // namespace

class TestRequirementsPanel : public QObject {
  Q_OBJECT
 private slots:
  void defaults() {
    RequirementsPanel panel;
    QCOMPARE(panel.requirement(), std::nullopt);
    QVERIFY(!panel.enableBox()->isChecked());
    QCOMPARE(panel.objectiveCombo()->count(), 4);
    QCOMPARE(panel.objectiveCombo()->currentIndex(), 1);  // MRR
    QCOMPARE(panel.loSpin()->value(), 0.0);
    QCOMPARE(panel.hiSpin()->value(), 6e5);  // 1e4 cm³/s, shown in cm³/min
    QVERIFY(!panel.loSpin()->isEnabled());   // off: bounds greyed out
    QVERIFY(panel.autoWeightsButton()->isEnabled());
    QVERIFY(panel.statusLabel()->text().isEmpty());
  }

  void roundTrip_data() {
    QTest::addColumn<int>("objective");
    QTest::addColumn<double>("lo");
    QTest::addColumn<double>("hi");
    QTest::addColumn<int>("wantObjective");
    QTest::addColumn<double>("wantLo");
    QTest::addColumn<double>("wantHi");
    QTest::newRow("TOL full range") << 0 << 0.0 << 1e6 << 0 << 0.0 << 1e6;
    QTest::newRow("TOL 1 decimal") << 0 << 12.5 << 240.0 << 0 << 12.5 << 240.0;
    QTest::newRow("MRR 4 decimals") << 1 << 0.1234 << 2.5 << 1 << 0.1234 << 2.5;
    QTest::newRow("MRR lo == hi") << 1 << 3.0 << 3.0 << 1 << 3.0 << 3.0;
    QTest::newRow("SURF edges") << 2 << 0.001 << 1000.0 << 2 << 0.001 << 1000.0;
    QTest::newRow("ROS") << 3 << 0.25 << 10.0 << 3 << 0.25 << 10.0;
    QTest::newRow("MRR kept exact though shown in cm³/min") << 1 << 0.12344 << 1.0 << 1 << 0.12344 << 1.0;
    QTest::newRow("lo > hi swapped") << 2 << 5.0 << 1.5 << 2 << 1.5 << 5.0;
    QTest::newRow("clamped to range") << 3 << -1.0 << 20.0 << 3 << 0.0 << 10.0;
    QTest::newRow("infinite hi: maximum") << 1 << 1.0 << kInf << 1 << 1.0 << 1e4;
    QTest::newRow("NaN: full range") << 2 << kNaN << kNaN << 2 << 0.0 << 1000.0;
    QTest::newRow("objective below 0 clamped") << -3 << 1.0 << 2.0 << 0 << 1.0 << 2.0;
    QTest::newRow("objective above 3 clamped") << 7 << 1.0 << 2.0 << 3 << 1.0 << 2.0;
  }
  void roundTrip() {
    QFETCH(int, objective);
    QFETCH(double, lo);
    QFETCH(double, hi);
    QFETCH(int, wantObjective);
    QFETCH(double, wantLo);
    QFETCH(double, wantHi);
    RequirementsPanel panel;
    QSignalSpy changed(&panel, &RequirementsPanel::requirementChanged);
    panel.setRequirement(RequirementView{objective, lo, hi});
    const auto got = panel.requirement();
    QVERIFY(got.has_value());
    QCOMPARE(got->objective, wantObjective);
    QCOMPARE(got->lo, wantLo);
    QCOMPARE(got->hi, wantHi);
    QCOMPARE(panel.objectiveCombo()->currentIndex(), wantObjective);
    QVERIFY(panel.enableBox()->isChecked());
    QVERIFY(panel.hiSpin()->isEnabled());
    panel.setRequirement(std::nullopt);
    QCOMPARE(panel.requirement(), std::nullopt);
    QVERIFY(!panel.enableBox()->isChecked());
    QCOMPARE(changed.count(), 0);  // setRequirement() is silent
  }

  void exactRoundTrip() {
    RequirementsPanel panel;
    const RequirementView r{2, 0.8, 3.2};
    panel.setRequirement(r);
    QCOMPARE(panel.requirement(), std::optional<RequirementView>(r));
  }

  void boundsStayOrdered_data() {
    QTest::addColumn<bool>("editLower");
    QTest::addColumn<double>("value");
    QTest::addColumn<double>("wantLo");
    QTest::addColumn<double>("wantHi");
    // MRR in cm³/s; the spin boxes show cm³/min (60 times as much).
    QTest::newRow("lo above hi moves hi") << true << 3.0 << 3.0 << 3.0;
    QTest::newRow("lo equal to hi") << true << 2.0 << 2.0 << 2.0;
    QTest::newRow("lo inside") << true << 1.5 << 1.5 << 2.0;
    QTest::newRow("hi below lo moves lo") << false << 0.5 << 0.5 << 0.5;
    QTest::newRow("hi to 0") << false << 0.0 << 0.0 << 0.0;
    QTest::newRow("hi inside") << false << 1.5 << 1.0 << 1.5;
    QTest::newRow("lo past maximum clamped") << true << 2e4 << 1e4 << 1e4;
  }
  void boundsStayOrdered() {
    QFETCH(bool, editLower);
    QFETCH(double, value);
    QFETCH(double, wantLo);
    QFETCH(double, wantHi);
    RequirementsPanel panel;
    panel.setRequirement(RequirementView{1, 1.0, 2.0});
    QSignalSpy changed(&panel, &RequirementsPanel::requirementChanged);
    (editLower ? panel.loSpin() : panel.hiSpin())->setValue(60.0 * value);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(panel.requirement(), std::optional<RequirementView>(RequirementView{1, wantLo, wantHi}));
    QCOMPARE(panel.loSpin()->value(), 60.0 * wantLo);
    QCOMPARE(panel.hiSpin()->value(), 60.0 * wantHi);
  }

  void typedBoundCommitsOnEditingFinished() {
    RequirementsPanel panel;
    panel.setRequirement(RequirementView{1, 1.0, 2.0});
    QSignalSpy changed(&panel, &RequirementsPanel::requirementChanged);
    QVERIFY(!panel.loSpin()->keyboardTracking());
    panel.loSpin()->selectAll();
    QTest::keyClicks(panel.loSpin(), "150");  // cm³/min: 2.5 cm³/s
    QCOMPARE(changed.count(), 0);             // still typing
    QTest::keyClick(panel.loSpin(), Qt::Key_Return);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(panel.requirement(), std::optional<RequirementView>(RequirementView{1, 2.5, 2.5}));
  }

  void toggleEmitsOnce() {
    RequirementsPanel panel;
    QSignalSpy changed(&panel, &RequirementsPanel::requirementChanged);
    panel.enableBox()->click();
    QCOMPARE(changed.count(), 1);
    QVERIFY(panel.requirement().has_value());
    QCOMPARE(panel.requirement()->objective, 1);
    QVERIFY(panel.loSpin()->isEnabled());
    QVERIFY(panel.objectiveCombo()->isEnabled());
    panel.enableBox()->click();
    QCOMPARE(changed.count(), 2);
    QCOMPARE(panel.requirement(), std::nullopt);
    QVERIFY(!panel.hiSpin()->isEnabled());
  }

  void autoWeightsButton() {
    RequirementsPanel panel;
    QSignalSpy requested(&panel, &RequirementsPanel::autoWeightsRequested);
    QSignalSpy changed(&panel, &RequirementsPanel::requirementChanged);
    panel.autoWeightsButton()->click();
    QCOMPARE(requested.count(), 1);
    QCOMPARE(changed.count(), 0);
    QVERIFY(panel.autoWeightsButton()->text().contains("Rule 12"));
  }

  void unitsFollowObjective_data() {
    QTest::addColumn<int>("objective");
    QTest::addColumn<QString>("suffix");
    QTest::addColumn<QString>("unit");
    QTest::addColumn<int>("decimals");
    QTest::addColumn<double>("maximum");
    QTest::newRow("TOL") << 0 << QString(" min") << QString("min") << 1 << 1e6;
    QTest::newRow("SURF") << 2 << QString(" \u00b5m") << QString("\u00b5m") << 3 << 1000.0;
    QTest::newRow("ROS") << 3 << QString() << QString("\u2013") << 3 << 10.0;
  }
  void unitsFollowObjective() {
    QFETCH(int, objective);
    QFETCH(QString, suffix);
    QFETCH(QString, unit);
    QFETCH(int, decimals);
    QFETCH(double, maximum);
    RequirementsPanel panel;
    panel.setRequirement(RequirementView{1, 1.5, 2.5});
    QCOMPARE(panel.loSpin()->suffix(), QString(" cm\u00b3/min"));
    QCOMPARE(panel.loSpin()->decimals(), 3);
    QSignalSpy changed(&panel, &RequirementsPanel::requirementChanged);
    panel.objectiveCombo()->setCurrentIndex(objective);
    QCOMPARE(changed.count(), 1);
    for (QDoubleSpinBox* spin : {panel.loSpin(), panel.hiSpin()}) {
      QCOMPARE(spin->suffix(), suffix);
      QCOMPARE(spin->decimals(), decimals);
      QCOMPARE(spin->minimum(), 0.0);
      QCOMPARE(spin->maximum(), maximum);
    }
    QCOMPARE(RequirementsPanel::unit(objective), unit);
    const QString bracket = QString("[%1]").arg(unit);
    QVERIFY(panel.objectiveCombo()->currentText().endsWith(bracket));
    auto* loLabel = panel.findChild<QLabel*>("requirement_lo_label");
    auto* hiLabel = panel.findChild<QLabel*>("requirement_hi_label");
    QVERIFY(loLabel && hiLabel);
    QCOMPARE(loLabel->text(), QString("Lower bound ") + bracket);
    QCOMPARE(hiLabel->text(), QString("Upper bound ") + bracket);
    QCOMPARE(panel.requirement()->objective, objective);
    // Fresh objective: its whole range; going back to MRR restores the MRR bounds.
    QCOMPARE(panel.requirement()->lo, 0.0);
    QCOMPARE(panel.requirement()->hi, maximum);
    panel.objectiveCombo()->setCurrentIndex(1);
    QCOMPARE(changed.count(), 2);
    QCOMPARE(panel.requirement(), std::optional<RequirementView>(RequirementView{1, 1.5, 2.5}));
    QCOMPARE(panel.loSpin()->suffix(), QString(" cm\u00b3/min"));
  }

  // Shop units: the MRR bounds show in the unit chosen, and a change of units keeps them exactly.
  void followsShopUnits() {
    mx::widgets::DisplayUnits units;
    RequirementsPanel panel;
    panel.setUnits(&units);
    const RequirementView r{1, 0.12345, 2.5};  // cm³/s
    panel.setRequirement(r);
    QCOMPARE(panel.hiSpin()->value(), 150.0);  // cm³/min
    units.setShop(mx::widgets::ShopUnits::inch());
    QCOMPARE(panel.loSpin()->suffix(), QString::fromUtf8(" in³/min"));
    QCOMPARE(panel.hiSpin()->decimals(), 4);
    QCOMPARE(panel.hiSpin()->value(), 9.1536);
    QCOMPARE(panel.objectiveCombo()->itemText(1), QString::fromUtf8("MRR [in³/min]"));
    QCOMPARE(panel.requirement(), std::optional<RequirementView>(r));
    units.setShop(mx::widgets::ShopUnits::metric());
    QCOMPARE(panel.requirement(), std::optional<RequirementView>(r));
    QSignalSpy changed(&panel, &RequirementsPanel::requirementChanged);
    panel.hiSpin()->setValue(60.0);  // 1 cm³/s
    QCOMPARE(changed.count(), 1);
    QCOMPARE(panel.requirement(), std::optional<RequirementView>(RequirementView{1, 0.12345, 1.0}));
  }

  void status_data() {
    QTest::addColumn<bool>("satisfied");
    QTest::addColumn<bool>("weightsChanged");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("color");
    const QString ok = IndicatorGauge::okColor().name();
    const QString alarm = IndicatorGauge::alarmColor().name();
    QTest::newRow("met") << true << false << QString("Requirement met") << ok;
    QTest::newRow("met, Rule 11") << true << true << QString("Requirement met: weights changed by Rule 11") << ok;
    QTest::newRow("unreachable") << false << false << QString("Requirement not reachable by the weights alone")
                                 << alarm;
    QTest::newRow("unreachable, Rule 11")
        << false << true << QString("Requirement not reachable by the weights alone (weights changed by Rule 11)")
        << alarm;
  }
  void status() {
    QFETCH(bool, satisfied);
    QFETCH(bool, weightsChanged);
    QFETCH(QString, text);
    QFETCH(QString, color);
    RequirementsPanel panel;
    panel.setStatus(satisfied, weightsChanged);
    QCOMPARE(panel.statusLabel()->text(), text);
    QVERIFY2(panel.statusLabel()->styleSheet().contains(color), qPrintable(panel.statusLabel()->styleSheet()));
    panel.clearStatus();
    QVERIFY(panel.statusLabel()->text().isEmpty());
    QVERIFY(panel.statusLabel()->styleSheet().isEmpty());
  }

  void autoWeightsResult_data() {
    QTest::addColumn<int>("iterations");
    QTest::addColumn<bool>("converged");
    QTest::addColumn<QString>("text");
    QTest::newRow("converged") << 12 << true << QString("Automatic weights (Rule 12): converged after 12 iterations");
    QTest::newRow("one") << 1 << true << QString("Automatic weights (Rule 12): converged after 1 iteration");
    QTest::newRow("not converged") << 200 << false
                                   << QString("Automatic weights (Rule 12): not converged after 200 iterations");
  }
  void autoWeightsResult() {
    QFETCH(int, iterations);
    QFETCH(bool, converged);
    QFETCH(QString, text);
    RequirementsPanel panel;
    panel.setAutoWeightsResult(iterations, converged);
    QCOMPARE(panel.statusLabel()->text(), text);
    const QColor want = converged ? IndicatorGauge::okColor() : QColor(230, 120, 0);
    QVERIFY(panel.statusLabel()->styleSheet().contains(want.name()));
  }

  void everyControlHasATooltip() {
    RequirementsPanel panel;
    for (QWidget* w : std::initializer_list<QWidget*>{panel.enableBox(), panel.objectiveCombo(), panel.loSpin(),
                                                      panel.hiSpin(), panel.autoWeightsButton(), panel.statusLabel()})
      QVERIFY2(!w->toolTip().isEmpty(), qPrintable(w->objectName()));
    QCOMPARE(panel.loSpin()->objectName(), QString("requirement_lo"));
  }
};

MX_REGISTER_TEST(TestRequirementsPanel)
#include "test_requirements_panel.moc"

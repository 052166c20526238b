// ControlSettingsEditor: every field shows its value in the C locale (P(0) scientific, the reset
// threshold in %), typed values are checked against their ranges at the edge values, an invalid entry
// is refused in place with the reason and emits nothing, a valid change emits settingsEdited once.
#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>

#include "control_settings_editor.h"
#include "test_registry.h"

using mx::widgets::ControllerSettingsView;
using mx::widgets::ControlSettingsEditor;

namespace {
// Types `text` into a field and finishes the edit as Return does.
void type(ControlSettingsEditor& editor, const QString& key, const QString& text) {
  QLineEdit* edit = editor.field(key);
  QVERIFY(edit);
  edit->setText(text);
  emit edit->editingFinished();
}
}  // namespace

class TestControlSettingsEditor : public QObject {
  Q_OBJECT
 private slots:
  void showsDefaults() {
    ControlSettingsEditor editor;
    QCOMPARE(editor.settings(), ControllerSettingsView{});
    QCOMPARE(editor.field("lambda")->text(), QString("1"));
    QCOMPARE(editor.field("p0")->text(), QString("1e+05"));
    QCOMPARE(editor.field("theta0")->text(), QString("0.2"));
    QCOMPARE(editor.field("reset_fraction")->text(), QString("5"));
    QCOMPARE(editor.field("xi")->text(), QString("0.75"));
    QCOMPARE(editor.field("tr_periods")->text(), QString("4"));
    QCOMPARE(editor.field("tau_c_ms")->text(), QString("0"));
    QCOMPARE(editor.field("feed_max_mm_s")->text(), QString("1800"));  // 30 mm/s in mm/min
    QCOMPARE(editor.field("force_reference_n")->text(), QString("1200"));
    QCOMPARE(editor.resetCombo()->currentIndex(), 1);
    QVERIFY(editor.field("reset_fraction")->isEnabled());
    QCOMPARE(editor.fieldKeys().size(), 9);
    QVERIFY(editor.field("nope") == nullptr);
  }

  void format_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("text");
    QTest::newRow("P0 1e5") << "p0" << 1e5 << "1e+05";
    QTest::newRow("P0 2.5e6") << "p0" << 2.5e6 << "2.5e+06";
    QTest::newRow("P0 1") << "p0" << 1.0 << "1e+00";
    QTest::newRow("P0 123456") << "p0" << 123456.0 << "1.23456e+05";
    QTest::newRow("fraction in %") << "reset_fraction" << 0.05 << "5";
    QTest::newRow("lambda") << "lambda" << 0.995 << "0.995";
    QTest::newRow("unknown") << "nope" << 1.0 << "";
  }
  void format() {
    QFETCH(QString, key);
    QFETCH(double, value);
    QFETCH(QString, text);
    QCOMPARE(ControlSettingsEditor::format(key, value), text);
  }

  void parse_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("valid");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("reason");
    const QString lam = QString("Forgetting factor \u03bb [\u2013]");
    QTest::newRow("lambda 1 (upper, closed)") << "lambda"
                                              << "1" << true << 1.0 << "";
    QTest::newRow("lambda 0.5 (lower, open)") << "lambda"
                                              << "0.5" << false << 0.0 << lam + " = 0.5: must be in (0.5, 1]";
    QTest::newRow("lambda 0.5001") << "lambda"
                                   << "0.5001" << true << 0.5001 << "";
    QTest::newRow("lambda 1.01") << "lambda"
                                 << "1.01" << false << 0.0 << lam + " = 1.01: must be in (0.5, 1]";
    QTest::newRow("lambda text") << "lambda"
                                 << "abc" << false << 0.0 << lam + " = abc: not a number";
    QTest::newRow("lambda empty") << "lambda"
                                  << "  " << false << 0.0 << lam + " = (empty): not a number";
    QTest::newRow("lambda nan") << "lambda"
                                << "nan" << false << 0.0 << lam + " = nan: not a number";
    QTest::newRow("P0 1 (lower)") << "p0"
                                  << "1" << true << 1.0 << "";
    QTest::newRow("P0 1e9 (upper)") << "p0"
                                    << "1e9" << true << 1e9 << "";
    QTest::newRow("P0 1.1e9") << "p0"
                              << "1.1e9" << false << 0.0
                              << "Initial covariance P(0) [\u2013] = 1.1e9: must be in [1, 1e+09]";
    QTest::newRow("P0 0.5") << "p0"
                            << "0.5" << false << 0.0 << "Initial covariance P(0) [\u2013] = 0.5: must be in [1, 1e+09]";
    QTest::newRow("theta0 negative") << "theta0"
                                     << "-0.3" << true << -0.3 << "";
    QTest::newRow("fraction 5 %") << "reset_fraction"
                                  << "5" << true << 0.05 << "";
    QTest::newRow("fraction 100 %") << "reset_fraction"
                                    << "100" << true << 1.0 << "";
    QTest::newRow("fraction 0 %") << "reset_fraction"
                                  << "0" << false << 0.0 << "Reset threshold [% of F_r] = 0: must be in (0, 100]";
    QTest::newRow("xi 0.1") << "xi"
                            << "0.1" << true << 0.1 << "";
    QTest::newRow("xi 0.09") << "xi"
                             << "0.09" << false << 0.0
                             << QString("Model damping \u03be [\u2013] = 0.09: must be in [0.1, 2]");
    QTest::newRow("xi 2") << "xi"
                          << "2" << true << 2.0 << "";
    QTest::newRow("T_r 1") << "tr_periods"
                           << "1" << true << 1.0 << "";
    QTest::newRow("T_r 50") << "tr_periods"
                            << "50" << true << 50.0 << "";
    QTest::newRow("T_r 51") << "tr_periods"
                            << "51" << false << 0.0 << "Model rise time T_r [spindle periods] = 51: must be in [1, 50]";
    QTest::newRow("tau_c 0 = default") << "tau_c_ms"
                                       << "0" << true << 0.0 << "";
    QTest::newRow("tau_c negative") << "tau_c_ms"
                                    << "-1" << false << 0.0
                                    << QString(
                                           "Cutting time constant \u03c4_c [ms] (0 = default) = -1: must be in "
                                           "[0, 10000]");
    QTest::newRow("f_max 0") << "feed_max_mm_s"
                             << "0" << false << 0.0 << "Feed limit f_max [mm/min] = 0: must be in (0, 600000]";
    QTest::newRow("F_r 1200") << "force_reference_n"
                              << "1200" << true << 1200.0 << "";
    QTest::newRow("F_r -5") << "force_reference_n"
                            << "-5" << false << 0.0 << "Force reference F_r [N] = -5: must be in (0, 1e+06]";
  }
  void parse() {
    QFETCH(QString, key);
    QFETCH(QString, text);
    QFETCH(bool, valid);
    QFETCH(double, value);
    QFETCH(QString, reason);
    QString why;
    const std::optional<double> v = ControlSettingsEditor::parse(key, text, &why);
    QCOMPARE(v.has_value(), valid);
    if (valid) {
      QCOMPARE(*v, value);
    } else {
      QCOMPARE(why, reason);
    }
  }

  void roundTripWithoutSignal() {
    ControlSettingsEditor editor;
    QSignalSpy spy(&editor, &ControlSettingsEditor::settingsEdited);
    ControllerSettingsView s;
    s.lambda = 0.97;
    s.p0 = 3e7;
    s.theta0 = 0.1;
    s.reset = 0;
    s.reset_fraction = 0.02;
    s.xi = 0.9;
    s.tr_periods = 6.0;
    s.tau_c_ms = 1.25;
    s.feed_max_mm_s = 40.0;
    s.force_reference_n = 1000.0;
    editor.setSettings(s);
    QCOMPARE(editor.settings(), s);
    QCOMPARE(editor.field("p0")->text(), QString("3e+07"));
    QCOMPARE(editor.field("reset_fraction")->text(), QString("2"));
    QCOMPARE(editor.resetCombo()->currentIndex(), 0);
    QVERIFY(!editor.field("reset_fraction")->isEnabled());  // no threshold without the error rule
    QCOMPARE(spy.count(), 0);
  }

  void validEditEmitsOnce() {
    ControlSettingsEditor editor;
    QSignalSpy spy(&editor, &ControlSettingsEditor::settingsEdited);
    type(editor, "lambda", "0.98");
    QCOMPARE(spy.count(), 1);
    const auto s = spy.at(0).at(0).value<ControllerSettingsView>();
    QCOMPARE(s.lambda, 0.98);
    QCOMPARE(editor.settings().lambda, 0.98);
    type(editor, "lambda", "0.98");  // the same value again: nothing to recompute
    QCOMPARE(spy.count(), 1);
    type(editor, "p0", "1e+05");  // unchanged display text
    QCOMPARE(spy.count(), 1);
    type(editor, "reset_fraction", "10");
    QCOMPARE(spy.count(), 2);
    QCOMPARE(editor.settings().reset_fraction, 0.1);
    QCOMPARE(editor.errorText(), QString());
  }

  void invalidEditRefusedInPlace() {
    ControlSettingsEditor editor;
    QSignalSpy spy(&editor, &ControlSettingsEditor::settingsEdited);
    type(editor, "xi", "5");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(editor.settings().xi, 0.75);                // unchanged
    QCOMPARE(editor.field("xi")->text(), QString("5"));  // kept for correction
    QCOMPARE(editor.errorText(), QString("Model damping \u03be [\u2013] = 5: must be in [0.1, 2]"));
    QVERIFY(!editor.field("xi")->styleSheet().isEmpty());
    // Another valid field still goes through, with the last valid xi.
    type(editor, "force_reference_n", "1000");
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).value<ControllerSettingsView>().xi, 0.75);
    QVERIFY(!editor.errorText().isEmpty());
    type(editor, "xi", "1.5");  // corrected
    QCOMPARE(spy.count(), 2);
    QCOMPARE(editor.errorText(), QString());
    QVERIFY(editor.field("xi")->styleSheet().isEmpty());
    // setSettings clears the errors and shows the values.
    type(editor, "lambda", "2");
    editor.setSettings(ControllerSettingsView{});
    QCOMPARE(editor.errorText(), QString());
    QCOMPARE(editor.field("lambda")->text(), QString("1"));
  }

  void resetRuleEmits() {
    ControlSettingsEditor editor;
    QSignalSpy spy(&editor, &ControlSettingsEditor::settingsEdited);
    editor.resetCombo()->setCurrentIndex(2);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).value<ControllerSettingsView>().reset, 2);
    QVERIFY(!editor.field("reset_fraction")->isEnabled());
    editor.resetCombo()->setCurrentIndex(1);
    QCOMPARE(spy.count(), 2);
    QVERIFY(editor.field("reset_fraction")->isEnabled());
  }
};

MX_REGISTER_TEST(TestControlSettingsEditor)
#include "test_control_settings_editor.moc"

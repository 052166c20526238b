// The checked spin boxes: the wording of a refusal at the edges of a range, the note shown as the bad
// text is typed (kept in the box, the value unchanged), the note that stays when editing ends on it,
// and the next accepted keystroke that hides it.
#include <QLabel>

#include "checked_spin_box.h"
#include "input_feedback.h"
#include "test_registry.h"

using mx::widgets::CheckedDoubleSpinBox;
using mx::widgets::CheckedSpinBox;
using mx::widgets::inputNote;
using mx::widgets::SpinLimits;

Q_DECLARE_METATYPE(SpinLimits)

namespace {

const SpinLimits kTeeth{"Teeth", 1, 100, 0, {}};
const SpinLimits kStiffness{"Stiffness k [N/µm]", 0.001, 1e6, 4, {}};
const SpinLimits kKt{"K_t [N/mm²]", 0, 1e5, 2, "material's"};

// The note shown for `box`, "" when none is visible.
QString noteOf(const QWidget* box) {
  const QLabel* note = inputNote(box);
  return note && note->isVisible() ? note->text() : QString();
}

// A shown window with one box: stiffness 5.59 in [0.001, 1e6], 4 decimals.
struct StiffnessBox {
  QWidget window;
  CheckedDoubleSpinBox* box = new CheckedDoubleSpinBox(&window);
  StiffnessBox() {
    window.resize(500, 300);
    box->setGeometry(20, 20, 150, 24);
    box->setLocale(QLocale::c());
    box->setDecimals(4);
    box->setRange(0.001, 1e6);
    box->setValue(5.59);
    box->setFieldName("Stiffness k [N/µm]");
    window.show();
  }
};

}  // namespace

class TestCheckedSpinBox : public QObject {
  Q_OBJECT
 private slots:
  void refusal_data() {
    QTest::addColumn<SpinLimits>("limits");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("message");
    const QString teeth = "Teeth must be a whole number from 1 to 100; ";
    const QString stiffness = "Stiffness k [N/µm] must be between 0.001 and 1000000; ";
    QTest::newRow("letters") << kTeeth << "abc" << teeth + "\"abc\" is not a number.";
    QTest::newRow("minimum") << kTeeth << "1" << QString();
    QTest::newRow("maximum") << kTeeth << "100" << QString();
    QTest::newRow("below") << kTeeth << "0" << teeth + "\"0\" is below the minimum.";
    QTest::newRow("above") << kTeeth << "101" << teeth + "\"101\" is above the maximum.";
    QTest::newRow("fraction") << kTeeth << "2.5" << teeth + "\"2.5\" is not a whole number.";
    QTest::newRow("decimal point") << kTeeth << "2." << teeth + "\"2.\" is not a whole number.";
    QTest::newRow("empty") << kTeeth << "" << teeth + "nothing was entered.";
    QTest::newRow("negative") << kStiffness << "-5" << stiffness + "\"-5\" is below the minimum.";
    QTest::newRow("minus sign") << kStiffness << "-" << stiffness + "\"-\" is below the minimum.";
    QTest::newRow("just below") << kStiffness << "0.0009" << stiffness + "\"0.0009\" is below the minimum.";
    QTest::newRow("smallest") << kStiffness << "0.001" << QString();
    QTest::newRow("largest") << kStiffness << "1000000" << QString();
    QTest::newRow("just above") << kStiffness << "1000000.0001" << stiffness + "\"1000000.0001\" is above the maximum.";
    QTest::newRow("decimals") << kStiffness << "1.23456" << stiffness + "\"1.23456\" has more than 4 decimal(s).";
    QTest::newRow("long text") << kStiffness << "soft as butter, really soft"
                               << stiffness + "\"soft as butter, really …\" is not a number.";
    QTest::newRow("special") << kKt << "-5"
                             << "K_t [N/mm²] must be between 0.01 and 100000, or \"material's\"; \"-5\" is below the "
                                "minimum.";
  }
  void refusal() {
    QFETCH(SpinLimits, limits);
    QFETCH(QString, typed);
    QFETCH(QString, message);
    QCOMPARE(mx::widgets::spinRefusal(limits, typed, QLocale::c()), message);
  }

  // Typed text the box cannot take stays in it, with the note at once; the value does not change.
  void typingShowsTheNoteAtOnce_data() {
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("message");
    const QString stiffness = "Stiffness k [N/µm] must be between 0.001 and 1000000; ";
    QTest::newRow("negative") << "-5" << stiffness + "\"-5\" is below the minimum.";
    QTest::newRow("letters") << "abc" << stiffness + "\"abc\" is not a number.";
    QTest::newRow("too large") << "2000000" << stiffness + "\"2000000\" is above the maximum.";
  }
  void typingShowsTheNoteAtOnce() {
    QFETCH(QString, typed);
    QFETCH(QString, message);
    StiffnessBox s;
    QVERIFY(QTest::qWaitForWindowExposed(&s.window));
    s.box->selectAll();
    QTest::keyClicks(s.box, typed);
    QCOMPARE(noteOf(s.box), message);
    QCOMPARE(s.box->text(), typed);
    QCOMPARE(s.box->value(), 5.59);
    const QRect note = inputNote(s.box)->geometry();
    QCOMPARE(note.top(), s.box->geometry().bottom() + 1);
    QCOMPARE(note.left(), s.box->x());

    QTest::keyClick(s.box, Qt::Key_Return);  // editing ends: the value stays and the note says so
    QCOMPARE(s.box->value(), 5.59);
    QCOMPARE(s.box->text(), QString("5.5900"));
    QCOMPARE(noteOf(s.box), message + " The value stays 5.59.");
  }

  // A value only too small once editing ends ("0" may become "0.5") is answered then.
  void partialInputIsAnsweredWhenEditingEnds() {
    StiffnessBox s;
    QVERIFY(QTest::qWaitForWindowExposed(&s.window));
    s.box->selectAll();
    QTest::keyClick(s.box, Qt::Key_0);
    QCOMPARE(noteOf(s.box), QString());
    s.box->interpretText();
    QCOMPARE(s.box->value(), 5.59);
    QCOMPARE(noteOf(s.box), QString("Stiffness k [N/µm] must be between 0.001 and 1000000; \"0\" is below the minimum. "
                                    "The value stays 5.59."));
  }

  void anAcceptedKeystrokeHidesTheNote() {
    StiffnessBox s;
    QVERIFY(QTest::qWaitForWindowExposed(&s.window));
    s.box->selectAll();
    QTest::keyClicks(s.box, "-");
    QVERIFY(!noteOf(s.box).isEmpty());
    s.box->selectAll();
    QTest::keyClicks(s.box, "7");
    QCOMPARE(noteOf(s.box), QString());
    QTest::keyClick(s.box, Qt::Key_Return);
    QCOMPARE(s.box->value(), 7.0);
  }

  void integerBoxAndSuffix() {
    QWidget window;
    window.resize(400, 200);
    auto* teeth = new CheckedSpinBox(&window);
    teeth->setRange(1, 100);
    teeth->setValue(4);
    teeth->setFieldName("Teeth");
    auto* power = new CheckedDoubleSpinBox(&window);
    power->setSuffix(" kW");
    power->setFieldName("Spindle power");
    QCOMPARE(power->limits().field, QString("Spindle power [kW]"));  // the unit from the suffix
    power->setFieldName("Power [W]");
    QCOMPARE(power->limits().field, QString("Power [W]"));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    teeth->selectAll();
    QTest::keyClicks(teeth, "abc");
    QCOMPARE(noteOf(teeth), QString("Teeth must be a whole number from 1 to 100; \"abc\" is not a number."));
    QCOMPARE(teeth->value(), 4);
  }

  // The start of the special text is on its way to it: no note.
  void specialTextCanBeTyped() {
    QWidget window;
    auto* box = new CheckedDoubleSpinBox(&window);
    box->setRange(0, 1e5);
    box->setSpecialValueText("material's");
    box->setValue(600);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    box->selectAll();
    QTest::keyClicks(box, "mat");
    QCOMPARE(noteOf(box), QString());
  }
};

MX_REGISTER_TEST(TestCheckedSpinBox)
#include "test_checked_spin_box.moc"

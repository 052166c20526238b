// The import dialog: every tool of the file listed with its geometry in the display unit, all checked
// when they fit the project, none when a large library would not; OK only for a selection the project
// can hold (at most 100 tools), counting the project's own tools when appending.
#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QTableView>

#include "test_registry.h"
#include "tool_import_dialog.h"

using mx::app::ToolSpec;
using mx::widgets::DisplayUnits;
using mx::widgets::ToolImportDialog;

namespace {

std::vector<ToolSpec> tools(int count) {
  std::vector<ToolSpec> out;
  for (int i = 1; i <= count; ++i) {
    ToolSpec t;
    t.id = QString("T%1").arg(i);
    t.teeth = 3;
    t.diameter_mm = 12.7;
    t.flute_length_mm = 25.4;
    t.type = "flat end mill";
    out.push_back(t);
  }
  return out;
}

bool okEnabled(const ToolImportDialog& d) {
  return d.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->isEnabled();
}

QString cell(const ToolImportDialog& d, int row, int column) {
  const QAbstractItemModel* m = d.findChild<QTableView*>()->model();
  return m->index(row, column).data().toString();
}

}  // namespace

class TestToolImportDialog : public QObject {
  Q_OBJECT
 private slots:
  void listsTheToolsInTheDisplayUnit() {
    DisplayUnits inch;
    inch.setLength(DisplayUnits::Length::Inch);
    ToolImportDialog d("lib.tools", tools(2), {"Drill 5: a drill is not a milling cutter"}, 0, &inch);
    QCOMPARE(cell(d, 0, 0), QString("T1"));
    QCOMPARE(cell(d, 0, 1), QString("flat end mill"));
    QCOMPARE(cell(d, 0, 2), QString("0.5000"));  // 12.7 mm
    QCOMPARE(cell(d, 0, 4), QString("1.0000"));  // 25.4 mm
    QCOMPARE(cell(d, 0, 5), QString("–"));       // no stickout given
    QCOMPARE(d.findChild<QTableView*>()->model()->headerData(2, Qt::Horizontal).toString(), QString("D [in]"));
    QCOMPARE(d.selectedIds(), QStringList({"T1", "T2"}));
    QVERIFY(d.replace());  // an empty project can only be replaced
    QVERIFY(okEnabled(d));
  }

  void selectionWithinTheLimit_data() {
    QTest::addColumn<int>("fileTools");
    QTest::addColumn<int>("projectTools");
    QTest::addColumn<int>("checked");
    QTest::addColumn<bool>("replace");
    QTest::addColumn<bool>("ok");
    QTest::newRow("100 into empty") << 100 << 0 << 100 << true << true;
    QTest::newRow("98 appended to 2") << 98 << 2 << 98 << false << true;
    QTest::newRow("99 appended to 2") << 99 << 2 << 99 << false << false;
    QTest::newRow("99 replacing 2") << 99 << 2 << 99 << true << true;
    QTest::newRow("none checked") << 10 << 2 << 0 << false << false;
    QTest::newRow("5000, 3 checked") << 5000 << 2 << 3 << false << true;
  }
  void selectionWithinTheLimit() {
    QFETCH(int, fileTools);
    QFETCH(int, projectTools);
    QFETCH(int, checked);
    QFETCH(bool, replace);
    QFETCH(bool, ok);
    ToolImportDialog d("lib.json", tools(fileTools), {}, projectTools, nullptr);
    d.setAllChecked(false);
    for (int i = 1; i <= checked; ++i) d.setChecked(QString("T%1").arg(i), true);
    for (QRadioButton* b : d.findChildren<QRadioButton*>())
      if (b->text().startsWith(replace ? "Replace" : "Add")) b->setChecked(true);
    QCOMPARE(d.replace(), replace);
    QCOMPARE(d.selectedIds().size(), checked);
    QCOMPARE(okEnabled(d), ok);
  }

  // A library larger than the project can hold opens with nothing checked.
  void largeLibraryOpensUnchecked() {
    ToolImportDialog d("big.tools", tools(150), {}, 0, nullptr);
    QVERIFY(d.selectedIds().isEmpty());
    QVERIFY(!okEnabled(d));
  }
};

MX_REGISTER_TEST(TestToolImportDialog)
#include "test_tool_import_dialog.moc"

// Shop units in the main window: Edit > Preferences... opens the units page; accepting the Inch preset
// turns the readout, the status bar and the ranking to in, SFM, IPM, hp, lbf and in³/min at once, a new
// window starts in them (QSettings, here in a temporary folder), Cancel changes nothing, and the saved
// project file is the same whatever the units.
#include <QAction>
#include <QFile>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <cmath>
#include <numbers>

#include "main_window.h"
#include "ranking_table.h"
#include "ranking_table_model.h"
#include "shop_units_dialog.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"

using namespace mx;
using widgets::Quantity;
using widgets::ShopUnits;

namespace {

bool openShowAndRead(gui::MainWindow& window, const QString& path) {
  window.setQuiet(true);
  window.resize(1400, 900);
  window.show();
  QSignalSpy shown(test::lobesOf(window), &gui::LobesFeature::lobesShown);
  return window.openProject(path) && shown.wait(20000) && test::waitForReadout(window);
}

QAction* menuActionByTitle(const gui::MainWindow& window, const QString& menu, const QString& text) {
  for (QAction* top : window.menuBar()->actions())
    if (top->text() == menu && top->menu())
      for (QAction* a : top->menu()->actions())
        if (a->text() == text) return a;
  return nullptr;
}

// "3.682 hp" -> 3.682, and the unit after the number.
std::pair<double, QString> shown(const QString& text) {
  return {text.section(' ', 0, 0).toDouble(), text.section(' ', 1)};
}

QByteArray readFile(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
}  // namespace

class TestShopUnitsInWindow : public QObject {
  Q_OBJECT
 private slots:
  // The units are remembered in a settings file of this test's own temporary folder.
  void initTestCase() {
    QVERIFY(settings_dir_.isValid());
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-shop-units-test");
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings_dir_.path());
    QVERIFY(QSettings().fileName().startsWith(settings_dir_.path()));
  }
  void cleanupTestCase() {
    QSettings().remove("units");
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope,
                       QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation));
  }

  void inchPresetThroughPreferences() {
    gui::MainWindow window;
    QVERIFY(openShowAndRead(window, mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QCOMPARE(window.units()->shop(), ShopUnits::metric());
    widgets::OperatingPointReadout* readout = test::lobesOf(window)->readout();
    QCOMPARE(shown(readout->text("power")).second, QString("W"));

    QAction* preferences = menuActionByTitle(window, "&Edit", "&Preferences...");
    QVERIFY(preferences);
    preferences->trigger();
    auto* dialog = window.findChild<widgets::ShopUnitsDialog*>("preferencesDialog");
    QVERIFY(dialog && dialog->isVisible());
    dialog->inchButton()->click();
    QCOMPARE(window.units()->shop(), ShopUnits::metric());  // nothing applies before OK
    dialog->accept();
    QCOMPARE(window.units()->shop(), ShopUnits::inch());

    // The readout converts at once, with the unit beside each number.
    const widgets::PointReadout& r = readout->readout();
    double diameter_mm = 0.0;
    for (const app::ToolSpec& t : window.project()->tools)
      if (t.id == r.tool_id) diameter_mm = t.diameter_mm;
    QVERIFY(diameter_mm > 0.0);
    const struct {
      const char* field;
      double expected;
      const char* unit;
      double tolerance;
    } rows[] = {
        {"power", r.peak_power_w / 745.699872, "hp", 5e-4},
        {"force", r.peak_force_n / 4.4482216152605, "lbf", 0.05},
        {"depth", r.depth_mm / 25.4, "in", 5e-6},
        {"feed", r.feed_mm_per_tooth / 25.4, "in/tooth", 5e-6},
        {"surface_speed", std::numbers::pi * diameter_mm * 1e-3 * r.speed_rpm / 0.3048, "SFM", 0.5},
        {"feed_rate", r.feed_rate_mm_min / 25.4, "IPM", 5e-3},
        {"mrr", r.mrr_mm3_per_s * 0.06 / 16.387064, "in\u00b3/min", 5e-4},
    };
    for (const auto& row : rows) {
      const auto [value, unit] = shown(readout->text(row.field));
      QCOMPARE(unit, QString::fromUtf8(row.unit));
      QVERIFY2(std::abs(value - row.expected) <= row.tolerance,
               qPrintable(QString("%1: '%2', expected %3").arg(row.field, readout->text(row.field)).arg(row.expected)));
    }
    QVERIFY(r.peak_power_w > 0.0 && r.feed_rate_mm_min > 0.0);

    // The status bar and the ranking follow.
    QString status;
    for (const QLabel* label : window.statusBar()->findChildren<QLabel*>())
      if (label->text().startsWith("Point:")) status = label->text();
    QVERIFY2(status.contains(" in, s_t = ") && status.contains(" in/tooth"), qPrintable(status));
    auto* ranking = window.findChild<widgets::RankingTable*>();
    QVERIFY(ranking);
    using Model = widgets::RankingTableModel;
    QCOMPARE(ranking->model()->headerData(Model::Power, Qt::Horizontal).toString(), QString("P [hp]"));
    QCOMPARE(ranking->model()->headerData(Model::Mrr, Qt::Horizontal).toString(), QString("MRR [in\u00b3/min]"));

    // Remembered: a new window starts in the same units.
    {
      gui::MainWindow second;
      QCOMPARE(second.units()->shop(), ShopUnits::inch());
    }
    QCOMPARE(QSettings().value("units/power").toString(), QString("hp"));

    // Cancel changes nothing.
    widgets::ShopUnitsDialog* again = window.openPreferences();
    QCOMPARE(again->shopUnits(), ShopUnits::inch());
    again->metricButton()->click();
    again->reject();
    QCOMPARE(window.units()->shop(), ShopUnits::inch());
    test::engineOf(window)->cancelAll();
  }

  // The project file stays SI and shop-metric: saved in inch units it is byte for byte the metric one.
  void theProjectFileDoesNotFollowTheUnits() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    gui::MainWindow window;
    QVERIFY(openShowAndRead(window, mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    window.units()->setShop(ShopUnits::metric());
    QVERIFY(window.saveProject(dir.filePath("metric.mxproj")));
    window.units()->setShop(ShopUnits::inch());
    QVERIFY(window.saveProject(dir.filePath("inch.mxproj")));
    QCOMPARE(readFile(dir.filePath("inch.mxproj")), readFile(dir.filePath("metric.mxproj")));
    test::engineOf(window)->cancelAll();
  }

 private:
  QTemporaryDir settings_dir_;
};

MX_REGISTER_TEST(TestShopUnitsInWindow)
#include "test_shop_units.moc"

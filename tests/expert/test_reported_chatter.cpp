// The region a chatter report marks (+-2 % in speed, the reported depth and deeper), its edges, the
// report's validation, and which report holds a point.
#include "core/invalid_input.h"
#include "expert/reported_chatter.h"
#include "test_registry.h"

using namespace mx;

Q_DECLARE_METATYPE(std::size_t)

namespace {
ChatterReport reportAt(double speed_rpm, double depth_mm, std::size_t tool = 0) {
  ChatterReport r;
  r.tool = tool;
  r.speed_rev_per_s = speed_rpm / 60.0;
  r.depth_m = depth_mm * 1e-3;
  return r;
}

ExpertPoint pointAt(double speed_rpm, double depth_mm) {
  ExpertPoint q;
  q.speed_rev_per_s = speed_rpm / 60.0;
  q.depth_m = depth_mm * 1e-3;
  return q;
}
}  // namespace

class TestReportedChatter : public QObject {
  Q_OBJECT
 private slots:
  void regionBounds() {
    const ChatterRegion r = chatterRegionOf(reportAt(5000.0, 0.4));
    QCOMPARE_LE(std::abs(r.speed_from_rev_per_s * 60.0 - 4900.0), 1e-9);
    QCOMPARE_LE(std::abs(r.speed_to_rev_per_s * 60.0 - 5100.0), 1e-9);
    QCOMPARE_LE(std::abs(r.depth_from_m - 0.4e-3), 1e-15);
  }

  void contains_data() {
    QTest::addColumn<double>("speed_rpm");
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<bool>("inside");
    QTest::newRow("the report itself") << 5000.0 << 0.4 << true;
    QTest::newRow("deeper") << 5000.0 << 3.0 << true;
    QTest::newRow("shallower") << 5000.0 << 0.3999 << false;
    QTest::newRow("lower edge of the band") << 4900.0 << 0.5 << true;
    QTest::newRow("upper edge of the band") << 5100.0 << 0.5 << true;
    QTest::newRow("below the band") << 4899.0 << 0.5 << false;
    QTest::newRow("above the band") << 5101.0 << 0.5 << false;
  }
  void contains() {
    QFETCH(double, speed_rpm);
    QFETCH(double, depth_mm);
    QFETCH(bool, inside);
    const ChatterRegion r = chatterRegionOf(reportAt(5000.0, 0.4));
    QCOMPARE(r.contains(speed_rpm / 60.0, depth_mm * 1e-3), inside);
  }

  // Only the reports of the point's tool count; the first one that holds it is named.
  void reportHoldingPicksTheTool() {
    const std::vector<ChatterReport> reports{reportAt(3000.0, 1.0, 1), reportAt(5800.0, 0.5, 0),
                                             reportAt(5800.0, 0.2, 0)};
    QCOMPARE(reportHolding(reports, 0, pointAt(5800.0, 0.6)), std::optional<std::size_t>(1));
    QCOMPARE(reportHolding(reports, 0, pointAt(5800.0, 0.3)), std::optional<std::size_t>(2));
    QCOMPARE(reportHolding(reports, 0, pointAt(3000.0, 2.0)), std::nullopt);
    QCOMPARE(reportHolding(reports, 1, pointAt(3000.0, 2.0)), std::optional<std::size_t>(0));
    QCOMPARE(reportHolding({}, 0, pointAt(5800.0, 0.6)), std::nullopt);
  }

  void validation_data() {
    QTest::addColumn<std::size_t>("tool");
    QTest::addColumn<double>("speed_rpm");
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<double>("freq_hz");  // < 0: none
    QTest::addColumn<QString>("error");   // empty: valid
    QTest::newRow("valid") << std::size_t(1) << 5000.0 << 0.4 << 620.0 << QString();
    QTest::newRow("no frequency") << std::size_t(0) << 5000.0 << 0.4 << -1.0 << QString();
    QTest::newRow("tool out of range") << std::size_t(2) << 5000.0 << 0.4 << -1.0 << QString("tool index 2");
    QTest::newRow("zero speed") << std::size_t(0) << 0.0 << 0.4 << -1.0 << QString("speed = 0");
    QTest::newRow("nan depth") << std::size_t(0) << 5000.0 << double(NAN) << -1.0 << QString("depth = nan");
    QTest::newRow("negative depth") << std::size_t(0) << 5000.0 << -0.1 << -1.0 << QString("depth = -0.0001");
    QTest::newRow("zero frequency") << std::size_t(0) << 5000.0 << 0.4 << 0.0 << QString("frequency = 0");
  }
  void validation() {
    QFETCH(std::size_t, tool);
    QFETCH(double, speed_rpm);
    QFETCH(double, depth_mm);
    QFETCH(double, freq_hz);
    QFETCH(QString, error);
    ChatterReport r = reportAt(speed_rpm, depth_mm, tool);
    if (freq_hz >= 0.0) r.frequency_hz = freq_hz;
    try {
      validateChatterReport(r, 2, "reported chatter #1");
      QVERIFY2(error.isEmpty(), "accepted a bad report");
    } catch (const InvalidInput& e) {
      const QString what = QString::fromStdString(e.what());
      QVERIFY2(!error.isEmpty() && what.contains(error) && what.startsWith("reported chatter #1"), e.what());
    }
  }
};

MX_REGISTER_TEST(TestReportedChatter)
#include "test_reported_chatter.moc"

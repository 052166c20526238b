// The tool picture: the tooth marks at their pitch angles (clockwise from the top), the pitch labels
// halfway between teeth, runout as exaggerated radial offsets, and one offscreen rendering.
#include <QImage>
#include <cmath>
#include <numbers>

#include "support/test_constants.h"
#include "test_registry.h"
#include "tool_picture_widget.h"

using mx::MillingSetup;
using mx::app::ToolSpec;
using mx::widgets::runoutScalePxPerM;
using mx::widgets::ToolPictureWidget;
using mx::widgets::toothMarks;

namespace {

using mx::test::kDeg;

ToolSpec tool(int teeth, std::optional<std::vector<double>> pitch_deg, std::optional<std::vector<double>> runout_um) {
  ToolSpec t;
  t.id = "V4";
  t.teeth = teeth;
  t.diameter_mm = 16.0;
  t.helix_deg = 30.0;
  t.pitch_deg = std::move(pitch_deg);
  t.runout_um = std::move(runout_um);
  return t;
}

// The point at `radius` and `angle_deg` clockwise from the top of (100, 100), y down.
QPointF at(double radius, double angle_deg) {
  return {100.0 + radius * std::sin(angle_deg * kDeg), 100.0 - radius * std::cos(angle_deg * kDeg)};
}

bool near(QPointF a, QPointF b) {
  return std::abs(a.x() - b.x()) < 1e-9 && std::abs(a.y() - b.y()) < 1e-9;
}

}  // namespace

class TestToolPictureWidget : public QObject {
  Q_OBJECT
 private slots:
  // The diameter in the caption follows the display unit.
  void captionDiameterInTheDisplayUnit() {
    ToolPictureWidget picture;
    picture.setTool(tool(3, std::nullopt, std::nullopt));
    const MillingSetup& cutter = *picture.cutter();
    QCOMPARE(mx::widgets::toolCaption(cutter, 1.0, nullptr).front(), QString("V4: 3 teeth, D = 16 mm"));
    mx::widgets::DisplayUnits inch;
    inch.setShop(mx::widgets::ShopUnits::inch());
    QCOMPARE(mx::widgets::toolCaption(cutter, 1.0, &inch).front(), QString("V4: 3 teeth, D = 0.6299 in"));
  }

  void teethSitAtTheirPitchAngles_data() {
    QTest::addColumn<int>("teeth");
    QTest::addColumn<QVector<double>>("pitch");     // empty: uniform
    QTest::addColumn<QVector<double>>("expected");  // tooth angles [deg]
    QTest::newRow("uniform 3") << 3 << QVector<double>{} << QVector<double>{0, 120, 240};
    QTest::newRow("variable 4") << 4 << QVector<double>{70, 110, 70, 110} << QVector<double>{0, 70, 180, 250};
    QTest::newRow("variable 3") << 3 << QVector<double>{100, 130, 130} << QVector<double>{0, 100, 230};
    QTest::newRow("one tooth") << 1 << QVector<double>{} << QVector<double>{0};
  }
  void teethSitAtTheirPitchAngles() {
    QFETCH(int, teeth);
    QFETCH(QVector<double>, pitch);
    QFETCH(QVector<double>, expected);
    ToolPictureWidget picture;
    picture.setTool(
        tool(teeth, pitch.isEmpty() ? std::nullopt : std::optional(std::vector<double>(pitch.begin(), pitch.end())),
             std::nullopt));
    const MillingSetup& cutter = *picture.cutter();
    const auto marks = toothMarks(cutter, QPointF(100, 100), 50.0, 0.0);
    QCOMPARE(int(marks.size()), teeth);
    for (int j = 0; j < teeth; ++j) {
      const double next = j + 1 < teeth ? expected[j + 1] : 360.0;
      QVERIFY(std::abs(marks[std::size_t(j)].angle_rad - expected[j] * kDeg) < 1e-12);
      QVERIFY(std::abs(marks[std::size_t(j)].pitch_deg - (next - expected[j])) < 1e-9);
      QVERIFY2(near(marks[std::size_t(j)].edge, at(50.0, expected[j])), qPrintable(QString::number(j)));
      QVERIFY(near(marks[std::size_t(j)].pitch_label, at(0.62 * 50.0, 0.5 * (expected[j] + next))));
    }
  }

  // The largest |runout| is drawn as the given pixels; the others in proportion, outwards when positive.
  void runoutIsExaggeratedRadially() {
    ToolPictureWidget picture;
    picture.setTool(tool(4, std::vector<double>{70, 110, 70, 110}, std::vector<double>{0, 8, 0, -4}));
    const MillingSetup& cutter = *picture.cutter();
    const double scale = runoutScalePxPerM(cutter, 6.0);
    QCOMPARE(scale, 6.0 / 8e-6);
    const auto marks = toothMarks(cutter, QPointF(100, 100), 50.0, scale);
    QVERIFY(near(marks[0].edge, at(50.0, 0)));
    QVERIFY(near(marks[1].edge, at(56.0, 70)));
    QVERIFY(near(marks[3].edge, at(47.0, 250)));
    ToolPictureWidget none;
    none.setTool(tool(2, std::nullopt, std::nullopt));
    QCOMPARE(runoutScalePxPerM(*none.cutter(), 6.0), 0.0);
  }

  void rendersOffscreen() {
    ToolPictureWidget picture;
    picture.resize(picture.sizeHint());
    const QImage empty = picture.grab().toImage();
    picture.setTool(tool(4, std::vector<double>{70, 110, 70, 110}, std::vector<double>{0, 8, 0, -5}));
    const QImage image = picture.grab().toImage();
    QCOMPARE(image.size(), picture.sizeHint());
    QVERIFY(image != empty);
    int teeth_pixels = 0;  // the tooth marks are drawn in red
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const QColor c = image.pixelColor(x, y);
        if (c.red() > 150 && c.green() < 110 && c.blue() < 80) ++teeth_pixels;
      }
    QVERIFY2(teeth_pixels > 100, qPrintable(QString::number(teeth_pixels)));
    picture.clear();
    QVERIFY(!picture.cutter());
  }
};

MX_REGISTER_TEST(TestToolPictureWidget)
#include "test_tool_picture_widget.moc"

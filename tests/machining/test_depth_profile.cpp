// Depth of cut per block: from Z levels against the stock top, or from a project profile.
#include <cmath>

#include "core/invalid_input.h"
#include "gcode/gcode_reader.h"
#include "machining/depth_profile.h"
#include "test_registry.h"

using namespace mx;

class TestDepthProfile : public QObject {
  Q_OBJECT
 private slots:
  void fromStockTop() {
    const auto run =
        GcodeInterpreter().run(GcodeReader::readFile(std::string(MX_TEST_DATA_DIR) + "/gcode/pocket_mm.nc"));
    const auto d = DepthProfile::fromStockTop(0.0).blockDepths(run);
    const double expected[] = {0, 0, 0, 0, 0, 2e-3, 2e-3, 2e-3, 2e-3, 2e-3, 2e-3, 0, 2e-3, 1e-3, 0, 0, 0, 0};
    QCOMPARE(d.size(), std::size(expected));
    for (std::size_t i = 0; i < d.size(); ++i)
      QVERIFY2(std::abs(d[i] - expected[i]) < 1e-15, qPrintable(QString::number(i)));
    // a higher stock top (Z +0.5 mm) deepens every cut by 0.5 mm
    const auto d2 = DepthProfile::fromStockTop(0.5e-3).blockDepths(run);
    QVERIFY(std::abs(d2[13] - 1.5e-3) < 1e-15);
  }
  void fromProjectSegments() {
    // The 2006 paper's workpiece: 2, 3, 5, 3 mm over 5.87, 5.87, 5.87, 7.55 mm of feed path.
    const auto profile =
        DepthProfile::fromSegments({{5.87e-3, 2e-3}, {5.87e-3, 3e-3}, {5.87e-3, 5e-3}, {7.55e-3, 3e-3}});
    const auto run = GcodeInterpreter().run(
        GcodeReader::parse("G0 X-10\nG1 X0 F100\nX5.87\nX11.74\nX17.61\nX25.16\nX30\nG1 X0\nG0 X100\n"));
    // path: 10 mm before the part, then the four segments, then 4.84 mm beyond and 30 mm back
    const auto d = profile.blockDepths(run);
    QVERIFY(std::abs(d[1] - 3e-3) < 1e-15);  // path 0..10 mm spans segments 1 and 2: the larger depth
    QVERIFY(std::abs(d[2] - 5e-3) < 1e-15);  // 10..15.87 mm spans segments 2 and 3
    QVERIFY(std::abs(d[3] - 5e-3) < 1e-15);  // 15.87..21.74 mm: segments 3 and 4
    QVERIFY(std::abs(d[4] - 3e-3) < 1e-15);  // 21.74..27.61 mm: segment 4, then past the part
    QCOMPARE(d[5], 0.0);                     // 27.61..35.16 mm: past the part
    QCOMPARE(d[0], 0.0);
    QCOMPARE(d[8], 0.0);
    const auto exact = GcodeInterpreter().run(GcodeReader::parse("G1 X5.87 F100\nX11.74\nX17.61\nX25.16\nX30\n"));
    const auto e = profile.blockDepths(exact);
    const double expected[] = {2e-3, 3e-3, 5e-3, 3e-3, 0.0};
    for (std::size_t i = 0; i < 5; ++i) QVERIFY2(std::abs(e[i] - expected[i]) < 1e-15, qPrintable(QString::number(i)));
  }
  void invalidProfile() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, DepthProfile::fromSegments({{0.0, 1e-3}}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, DepthProfile::fromSegments({{1e-3, -1e-3}}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, DepthProfile::fromStockTop(std::nan("")));
  }
};

MX_REGISTER_TEST(TestDepthProfile)
#include "test_depth_profile.moc"

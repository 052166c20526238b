// Modal state of a G-code program: units, abs/inc, motion mode, F, S, position, arc lengths.
#include <cmath>
#include <numbers>

#include "gcode/gcode_interpreter.h"
#include "gcode/gcode_reader.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::kPi;
GcodeRun runFile(const char* name) {
  return GcodeInterpreter().run(GcodeReader::readFile(std::string(MX_TEST_DATA_DIR) + "/gcode/" + name));
}
GcodeRun runText(const char* text) {
  return GcodeInterpreter().run(GcodeReader::parse(text));
}
bool near(double a, double b, double tol) {
  return std::abs(a - b) <= tol;
}
}  // namespace

class TestGcodeInterpreter : public QObject {
  Q_OBJECT
 private slots:
  void pocketProgram() {
    const auto r = runFile("pocket_mm.nc");
    QCOMPARE(r.motions.size(), std::size_t(18));
    QVERIFY(r.warnings.empty());
    const auto& plunge = r.motions[5];  // N40 G1 Z-2. F150
    QCOMPARE(plunge.kind, MotionKind::Linear);
    QVERIFY(near(plunge.length_m, 7e-3, 1e-15));
    QVERIFY(near(plunge.feed_m_per_s, 150e-3 / 60.0, 1e-15));
    QVERIFY(plunge.feed_word);
    QVERIFY(near(plunge.speed_rev_per_s, 25.0, 1e-12));
    QVERIFY(near(r.motions[6].length_m, 40e-3, 1e-15));
    const auto& y = r.motions[7];  // N60 Y20. (modal G1, F600)
    QCOMPARE(y.kind, MotionKind::Linear);
    QVERIFY(!y.feed_word);
    QVERIFY(near(y.feed_m_per_s, 10e-3, 1e-15));
    const auto& cw = r.motions[8];  // quarter circle, clockwise, R20
    QCOMPARE(cw.kind, MotionKind::ArcCw);
    QVERIFY(near(cw.length_m, 20e-3 * kPi / 2.0, 1e-12));
    const auto& ccw = r.motions[9];  // three quarters, counter-clockwise, R20
    QCOMPARE(ccw.kind, MotionKind::ArcCcw);
    QVERIFY(near(ccw.length_m, 20e-3 * 1.5 * kPi, 1e-12));
    QVERIFY(near(ccw.end_m[0], 80e-3, 1e-15));
    QCOMPARE(r.motions[11].kind, MotionKind::Dwell);
    QCOMPARE(r.motions[11].dwell_s, 0.5);
    QVERIFY(near(r.motions[12].end_m[2], -1e-3, 1e-15));
    QCOMPARE(r.motions[12].kind, MotionKind::Linear);  // G1 still modal after G4
    QCOMPARE(r.motions[14].kind, MotionKind::Rapid);
    QCOMPARE(r.motions[15].kind, MotionKind::None);  // M5
  }
  void fullAndHelicalCircle() {
    const auto r = runText("G21 G90 G17\nG1 X0 Y0 Z0 F100\nG2 X0 Y0 I10 J0\nG3 X20 Y0 Z-3 I10\n");
    QVERIFY(near(r.motions[2].length_m, 2.0 * kPi * 10e-3, 1e-12));
    // half circle from (0,0) to (20,0) about (10,0), 3 mm down: helix
    QVERIFY(near(r.motions[3].length_m, std::hypot(kPi * 10e-3, 3e-3), 1e-12));
    QVERIFY(r.warnings.empty());
  }
  void incrementalMode() {
    const auto r = runText("G91 G1 X10 Y5 F100\nX10\nG90 X0\n");
    QVERIFY(near(r.motions[1].end_m[0], 20e-3, 1e-15));
    QVERIFY(near(r.motions[1].end_m[1], 5e-3, 1e-15));
    QVERIFY(r.motions[1].incremental);
    QVERIFY(near(r.motions[2].end_m[0], 0.0, 1e-15));
    QVERIFY(near(r.motions[2].length_m, 20e-3, 1e-15));
  }
  void inchProgram() {
    const auto r = runFile("inch.nc");
    QVERIFY(r.warnings.empty());
    const auto& plunge = r.motions[3];  // G1 Z-0.05 F10.
    QVERIFY(plunge.inch);
    QVERIFY(near(plunge.feed_m_per_s, 10.0 * 0.0254 / 60.0, 1e-15));
    QVERIFY(near(plunge.length_m, 0.25 * 0.0254, 1e-15));
    QVERIFY(near(r.motions[4].end_m[0], 2.0 * 0.0254, 1e-15));
    // G2 from (2,0) to (3,1) about (2,1): 270 degrees clockwise, R 1 in
    QCOMPARE(r.motions[5].kind, MotionKind::ArcCw);
    QVERIFY(near(r.motions[5].length_m, 1.5 * kPi * 0.0254, 1e-12));
    QVERIFY(near(r.motions[5].feed_m_per_s, 30.0 * 0.0254 / 60.0, 1e-15));
  }
  void unitChangeKeepsFeed() {
    const auto r = runText("G21 G1 X1 F254\nG20 X1\nG1 X2 F10\n");
    QVERIFY(near(r.motions[1].feed_m_per_s, 254e-3 / 60.0, 1e-15));  // not rescaled by G20
    QVERIFY(near(r.motions[1].end_m[0], 0.0254, 1e-15));
    QVERIFY(near(r.motions[2].feed_m_per_s, 10.0 * 0.0254 / 60.0, 1e-15));
  }
  void missingFeed() {
    const auto r = runFile("missing_f.nc");
    QVERIFY(r.motions[2].feed_missing);
    QVERIFY(r.motions[3].feed_missing);
    QVERIFY(!r.motions[4].feed_missing);
    QVERIFY(!r.motions[5].feed_missing);
    QVERIFY(near(r.motions[5].feed_m_per_s, 500e-3 / 60.0, 1e-15));  // modal F
    QCOMPARE(r.warnings.size(), std::size_t(2));
    QCOMPARE(r.warnings[0].line, 3);
    QCOMPARE(r.warnings[1].line, 4);
  }
  void arcRadiusMismatchAndNoMode() {
    const auto r = runText("X5\nG2 X10 Y0 I4 J0 F100\n");
    QCOMPARE(r.motions[0].kind, MotionKind::Rapid);
    QCOMPARE(r.warnings.size(), std::size_t(2));
    QCOMPARE(r.warnings[0].line, 1);
    QCOMPARE(r.warnings[1].line, 2);
    QVERIFY(r.warnings[1].message.find("radius") != std::string::npos);
  }
  void startPositionSetting() {
    GcodeInterpreterSettings s;
    s.start_m = {0.0, 0.0, 0.05};
    const auto r = GcodeInterpreter(s).run(GcodeReader::parse("G1 Z0 F100\n"));
    QVERIFY(near(r.motions[0].length_m, 0.05, 1e-15));
  }
};

MX_REGISTER_TEST(TestGcodeInterpreter)
#include "test_gcode_interpreter.moc"

// Heidenhain interpretation: the Klartext pocket has the ISO pocket's feed moves (same lengths, feeds
// and speed), arcs about CC, by radius and tangential have their analytic lengths, FMAX is a rapid for
// its block only, F AUTO is the TOOL CALL's feed, and INCH programs scale lengths and feeds.
#include <cmath>
#include <numbers>

#include "gcode/gcode_interpreter.h"
#include "gcode/gcode_reader.h"
#include "support/gcode_samples.h"
#include "test_registry.h"

using namespace mx;

namespace {
GcodeRun runOf(const std::string& text) {
  return GcodeInterpreter().run(GcodeReader::parse(text, GcodeDialect::Heidenhain));
}
std::vector<const GcodeMotion*> feedMoves(const GcodeRun& run) {
  std::vector<const GcodeMotion*> out;
  for (const GcodeMotion& m : run.motions)
    if (m.isFeedMove()) out.push_back(&m);
  return out;
}
}  // namespace

class TestHeidenhainInterpreter : public QObject {
  Q_OBJECT
 private slots:
  // Independent readings of one part: the ISO program (I, J centres) and the Klartext one (CC + C,
  // CR with R-) give the same feed moves.
  void samePocketAsIso() {
    const GcodeRun iso = GcodeInterpreter().run(GcodeReader::parse(test::gcodeSample("pocket_mm.nc")));
    const GcodeRun klartext = GcodeInterpreter().run(GcodeReader::parse(test::gcodeSample("programs/pocket_mm.h")));
    QVERIFY(klartext.warnings.empty());
    const auto a = feedMoves(iso), b = feedMoves(klartext);
    QCOMPARE(b.size(), a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      QVERIFY2(std::abs(a[i]->length_m - b[i]->length_m) < 1e-12, qPrintable(QString("feed move %1").arg(i)));
      QCOMPARE(b[i]->kind, a[i]->kind);
      QVERIFY(std::abs(a[i]->feed_m_per_s - b[i]->feed_m_per_s) < 1e-15);
      QVERIFY(std::abs(a[i]->speed_rev_per_s - b[i]->speed_rev_per_s) < 1e-15);
      for (std::size_t axis = 0; axis < 3; ++axis) QVERIFY(std::abs(a[i]->end_m[axis] - b[i]->end_m[axis]) < 1e-15);
    }
  }
  void arcLengths_data() {
    QTest::addColumn<QString>("program");
    QTest::addColumn<double>("length_mm");
    QTest::addColumn<int>("kind");
    const double pi = std::numbers::pi;
    QTest::newRow("C quarter, clockwise") << "L X+0 Y+0 F100\nCC X+10 Y+0\nC X+10 Y+10 DR-\n"
                                          << 5.0 * pi << int(MotionKind::ArcCw);
    QTest::newRow("C full circle") << "L X+0 Y+0 F100\nCC X+10 Y+0\nC DR+\n" << 20.0 * pi << int(MotionKind::ArcCcw);
    QTest::newRow("CC incremental") << "L X+5 Y+0 F100\nCC IX+5\nC X+15 Y+0 DR+\n"
                                    << 5.0 * pi << int(MotionKind::ArcCcw);
    QTest::newRow("CR R+ quarter") << "L X+0 Y+0 F100\nCR X+20 Y+20 R+20 DR-\n" << 10.0 * pi << int(MotionKind::ArcCw);
    QTest::newRow("CR R- three quarters") << "L X+0 Y+0 F100\nCR X+20 Y+20 R-20 DR-\n"
                                          << 30.0 * pi << int(MotionKind::ArcCw);
    QTest::newRow("CT after a line along X") << "L X+0 Y+0 F100\nL X+10\nCT X+20 Y+10\n"
                                             << 5.0 * pi << int(MotionKind::ArcCcw);
    QTest::newRow("helix") << "L X+0 Y+0 Z+0 F100\nCC X+10 Y+0\nC X+0 Y+0 Z-5 DR+\n"
                           << std::hypot(20.0 * pi, 5.0) << int(MotionKind::ArcCcw);
  }
  void arcLengths() {
    QFETCH(QString, program);
    QFETCH(double, length_mm);
    QFETCH(int, kind);
    const GcodeRun run = runOf(program.toStdString());
    const GcodeMotion& last = run.motions.back();
    QCOMPARE(int(last.kind), kind);
    QVERIFY2(std::abs(last.length_m * 1e3 - length_mm) < 1e-9,
             qPrintable(QString::number(last.length_m * 1e3, 'g', 12)));
  }
  // FMAX is a rapid for its block; the next L without F runs at the F before it. F AUTO is the TOOL
  // CALL's F.
  void rapidAndAutoFeeds() {
    const GcodeRun run = runOf("TOOL CALL 1 Z S2000 F450\nL X+0 F300\nL X+10 FMAX\nL X+20\nL X+30 F AUTO\nL X+40\n");
    QCOMPARE(run.motions[2].kind, MotionKind::Rapid);
    QVERIFY(std::abs(run.motions[3].feed_m_per_s - 300e-3 / 60.0) < 1e-15);
    QVERIFY(std::abs(run.motions[4].feed_m_per_s - 450e-3 / 60.0) < 1e-15);
    QVERIFY(std::abs(run.motions[5].feed_m_per_s - 450e-3 / 60.0) < 1e-15);
    QVERIFY(std::abs(run.motions[1].speed_rev_per_s - 2000.0 / 60.0) < 1e-12);
    QVERIFY(run.motions[0].speed_word && !run.motions[1].speed_word);
  }
  // The numbers after an M word are its own ("M103 F20"): never an axis or a feed of the block.
  void mWordParametersAreNotAxes() {
    const GcodeRun run = runOf("L X+0 Y+0 F100\nL M3 Y+5\nL X+10 M103 F20\n");
    QCOMPARE(run.motions[1].kind, MotionKind::None);
    QCOMPARE(run.motions[1].end_m[1], 0.0);
    QVERIFY(std::abs(run.motions[2].feed_m_per_s - 100e-3 / 60.0) < 1e-15);
  }
  void inchProgram() {
    const GcodeRun run = runOf("BEGIN PGM P INCH\nL X+0 Y+0 F10\nL X+2\nEND PGM P INCH\n");
    QVERIFY(run.motions[2].inch);
    QVERIFY(std::abs(run.motions[2].length_m - 2 * 0.0254) < 1e-15);
    QVERIFY(std::abs(run.motions[2].feed_m_per_s - 10 * 0.0254 / 60.0) < 1e-15);
  }
  void missingFeedAndCentreWarned() {
    const GcodeRun run = runOf("L X+10 Y+0\nC X+0 Y+10 DR+\n");
    QVERIFY(run.motions[0].feed_missing);
    QCOMPARE(run.warnings.size(), std::size_t(3));  // two moves without F, C without CC
  }
};

MX_REGISTER_TEST(TestHeidenhainInterpreter)
#include "test_heidenhain_interpreter.moc"

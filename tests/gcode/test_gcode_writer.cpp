// G-code writer: byte-exact output without edits, F/S replace or insert, comments, header.
#include <fstream>
#include <limits>
#include <sstream>

#include "core/invalid_input.h"
#include "gcode/gcode_reader.h"
#include "gcode/gcode_writer.h"
#include "support/gcode_samples.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::gcodeSample;
std::string edited(const std::string& line, const GcodeBlockEdit& e) {
  const auto p = GcodeReader::parse(line);
  return GcodeWriter::applyEdit(p.blocks.at(0), e);
}
GcodeBlockEdit feedEdit(double f) {
  GcodeBlockEdit e;
  e.feed = f;
  return e;
}
}  // namespace

class TestGcodeWriter : public QObject {
  Q_OBJECT
 private slots:
  void noEditsIsByteIdentical_data() {
    QTest::addColumn<QString>("file");
    for (const char* f : mx::test::kGcodeSamples) QTest::newRow(f) << QString(f);
  }
  void noEditsIsByteIdentical() {
    QFETCH(QString, file);
    const std::string text = gcodeSample(file.toStdString());
    const auto p = GcodeReader::parse(text);
    QCOMPARE(GcodeWriter::write(p, {}), text);
    QCOMPARE(GcodeWriter::write(p, std::vector<GcodeBlockEdit>(p.blocks.size())), text);
  }
  void headerAfterTapeMarker() {
    const std::string text = gcodeSample("pocket_mm.nc");
    const auto p = GcodeReader::parse(text);
    const GcodeHeader h{"demo (1)", "model-based", "2024-05-01"};
    const std::string out = GcodeWriter::write(p, {}, &h);
    const std::string header = GcodeWriter::headerText(h, "\n");
    std::string expected = "%\n";
    expected += header;
    expected += text.substr(2);
    QCOMPARE(out, expected);
    QVERIFY(header.find("(project: demo [1])\n") != std::string::npos);
    QVERIFY(header.find("(controller: model-based)\n") != std::string::npos);
    QVERIFY(header.find("(date: 2024-05-01)\n") != std::string::npos);
  }
  void headerUsesProgramLineEnd() {
    const std::string text = gcodeSample("crlf.nc");
    const GcodeHeader h{"p", "c", "d"};
    const std::string out = GcodeWriter::write(GcodeReader::parse(text), {}, &h);
    std::string expected = GcodeWriter::headerText(h, "\r\n");
    expected += text;
    QCOMPARE(out, expected);
    QCOMPARE(GcodeWriter::write(GcodeReader::parse(""), {}, &h), GcodeWriter::headerText(h, "\n"));
  }
  void replaceFeed() {
    QCOMPARE(edited("N50 G1 X40. F600", feedEdit(450)), std::string("N50 G1 X40. F450"));
    QCOMPARE(edited("g1x10f200.5y3", feedEdit(12.25)), std::string("g1x10f12.2y3"));  // case kept, 1 decimal
  }
  // A replaced number must not run into a stray '.' or digit after it.
  void replacedWordStaysApartFromStrayNumber() {
    GcodeBlockEdit s;
    s.speed_rpm = 60668;
    const std::string line = edited("G1 S30..2 F200", s);
    QCOMPARE(line, std::string("G1 S60668 .2 F200"));
    QCOMPARE(GcodeReader::parse(line).blocks.at(0).find('S')->value, 60668.0);
    const std::string dotted = edited("G1 S.1.5", s);
    QCOMPARE(dotted, std::string("G1 S60668 .5"));
    QCOMPARE(GcodeReader::parse(dotted).blocks.at(0).find('S')->value, 60668.0);
  }
  void insertFeedBeforeComments() {
    QCOMPARE(edited("G1 X10 ;cut", feedEdit(100)), std::string("G1 X10 F100 ;cut"));
    QCOMPARE(edited("G1 X10 (a) Y2 (b)", feedEdit(100)), std::string("G1 X10 (a) Y2 F100 (b)"));
    QCOMPARE(edited("X10", feedEdit(99.94)), std::string("X10 F99.9"));
  }
  void speedAndComment() {
    GcodeBlockEdit e;
    e.feed = 300;
    e.speed_rpm = 2134.4;
    e.comment = "force (limit)";
    QCOMPARE(edited("G1 X1 S1500 F200 ; x", e), std::string("G1 X1 S2134 F300 ; x (force [limit])"));
    GcodeBlockEdit s;
    s.speed_rpm = 1800;
    QCOMPARE(edited("G1 X1", s), std::string("G1 X1 S1800"));
    GcodeBlockEdit fs;
    fs.feed = 10;
    fs.speed_rpm = 20;
    QCOMPARE(edited("G1 X1", fs), std::string("G1 X1 F10 S20"));
  }
  void editsKeepLineEnds() {
    const auto p = GcodeReader::parse("G1 X1 F100\r\nG1 X2");
    std::vector<GcodeBlockEdit> e(2);
    e[0].feed = 50;
    e[1].feed = 60;
    e[1].comment = std::string(1, 'r');
    QCOMPARE(GcodeWriter::write(p, e), std::string("G1 X1 F50\r\nG1 X2 F60 (r)"));
  }
  void formatNumber() {
    QCOMPARE(GcodeWriter::formatNumber(450.0, 1), std::string("450"));
    QCOMPARE(GcodeWriter::formatNumber(12.345, 1), std::string("12.3"));
    QCOMPARE(GcodeWriter::formatNumber(-0.0001, 2), std::string("0"));
    QCOMPARE(GcodeWriter::formatNumber(0.5, 3), std::string("0.5"));
    QCOMPARE(GcodeWriter::formatNumber(1234567.0, 0), std::string("1234567"));
  }
  void wrongEditCount() {
    const auto p = GcodeReader::parse("G1 X1\nG1 X2\n");
    QVERIFY_THROWS_EXCEPTION(InvalidInput, GcodeWriter::write(p, std::vector<GcodeBlockEdit>(1)));
  }
  // An infinite F or S is a controller's failure: refused with the line, never written.
  void infiniteWordsAreNotWritten() {
    const auto p = GcodeReader::parse("G1 X1 F100\n");
    GcodeBlockEdit feed = feedEdit(std::numeric_limits<double>::infinity());
    try {
      GcodeWriter::applyEdit(p.blocks.at(0), feed);
      QFAIL("expected InvalidInput");
    } catch (const InvalidInput& e) {
      QCOMPARE(std::string(e.what()), std::string("gcode edit of line 1: F = inf: only a finite value is written"));
    }
    GcodeBlockEdit speed;
    speed.speed_rpm = -std::numeric_limits<double>::infinity();
    QVERIFY_THROWS_EXCEPTION(InvalidInput, GcodeWriter::applyEdit(p.blocks.at(0), speed));
    QCOMPARE(GcodeWriter::applyEdit(p.blocks.at(0), GcodeBlockEdit{}), std::string("G1 X1 F100"));  // NaN: untouched
  }
};

MX_REGISTER_TEST(TestGcodeWriter)
#include "test_gcode_writer.moc"

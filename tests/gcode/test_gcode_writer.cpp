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
    for (const char* f : mx::test::kDialectSamples) QTest::newRow(f) << QString(f);
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
  // Each dialect keeps its own words and comment style: only the number of F / S changes, or a word is
  // inserted where the dialect takes one.
  void dialectEdits_data() {
    QTest::addColumn<QString>("dialect");
    QTest::addColumn<QString>("line");
    QTest::addColumn<double>("feed");
    QTest::addColumn<double>("speed");
    QTest::addColumn<QString>("comment");
    QTest::addColumn<QString>("expected");
    const double keep = std::numeric_limits<double>::quiet_NaN();
    QTest::newRow("Heidenhain F") << "heidenhain"
                                  << "8 L X+40 F600 M8" << 450.0 << keep << ""
                                  << "8 L X+40 F450 M8";
    QTest::newRow("Heidenhain F inserted before M") << "heidenhain"
                                                    << "9 L Y+20 R0 M8" << 450.0 << keep << ""
                                                    << "9 L Y+20 R0 F450 M8";
    QTest::newRow("Heidenhain F AUTO") << "heidenhain"
                                       << "8 L X+40 F AUTO" << 450.0 << keep << ""
                                       << "8 L X+40 F450";
    QTest::newRow("Heidenhain TOOL CALL S") << "heidenhain"
                                            << "4 TOOL CALL 1 Z S1500 F600" << keep << 2400.0 << ""
                                            << "4 TOOL CALL 1 Z S2400 F600";
    QTest::newRow("Heidenhain TOOL CALL S inserted") << "heidenhain"
                                                     << "4 TOOL CALL 1 Z F600" << keep << 2400.0 << ""
                                                     << "4 TOOL CALL 1 Z S2400 F600";
    QTest::newRow("Heidenhain comment") << "heidenhain"
                                        << "8 L X+40 F600" << 450.0 << keep << "MX: force (limit)"
                                        << "8 L X+40 F450 ; MX: force (limit)";
    QTest::newRow("Heidenhain comment joins the block's own") << "heidenhain"
                                                              << "7 L Z-2 F150 ; plunge" << keep << keep << "MX: kept"
                                                              << "7 L Z-2 F150 ; plunge MX: kept";
    QTest::newRow("Heidenhain S kept apart from a quoted tool name")
        << "heidenhain"
        << "1 TOOL CALL \"MILL_D10\"F2000" << keep << 2400.0 << ""
        << "1 TOOL CALL \"MILL_D10\" S2400 F2000";
    QTest::newRow("Heidenhain F kept apart before M") << "heidenhain"
                                                      << "2 L \"X\"M3" << 450.0 << keep << ""
                                                      << "2 L \"X\" F450 M3";
    QTest::newRow("Sinumerik spindle address") << "sinumerik"
                                               << "N20 G0 Z5 S1=1500 M3" << keep << 2400.0 << ""
                                               << "N20 G0 Z5 S1=2400 M3";
    QTest::newRow("Sinumerik S kept apart from a following name") << "sinumerik"
                                                                  << "N20 S1.5e308=800" << keep << 2400.0 << ""
                                                                  << "N20 S2400 e308=800";
    QTest::newRow("Sinumerik comment") << "sinumerik"
                                       << "N50 G1 X40 F600" << 450.0 << keep << "MX: a (b)"
                                       << "N50 G1 X40 F450 ; MX: a (b)";
    QTest::newRow("LinuxCNC comment") << "linuxcnc"
                                      << "N50 G1 X40 F600" << 450.0 << keep << "MX: a (b)"
                                      << "N50 G1 X40 F450 (MX: a [b])";
  }
  void dialectEdits() {
    QFETCH(QString, dialect);
    QFETCH(QString, line);
    QFETCH(double, feed);
    QFETCH(double, speed);
    QFETCH(QString, comment);
    QFETCH(QString, expected);
    const GcodeDialect d = *dialectFromName(dialect.toStdString());
    const GcodeProgram p = GcodeReader::parse(line.toStdString() + "\n", d);
    GcodeBlockEdit e;
    e.feed = feed;
    e.speed_rpm = speed;
    e.comment = comment.toStdString();
    QCOMPARE(QString::fromStdString(GcodeWriter::applyEdit(p.blocks.at(0), e, d)), expected);
  }
  void dialectRefusesWordsItDoesNotTake() {
    const GcodeProgram p = GcodeReader::parse("7 L Z-2 F150\n5 L Z+5 FMAX\n", GcodeDialect::Heidenhain);
    GcodeBlockEdit speed;
    speed.speed_rpm = 2000;
    QString error;
    try {
      GcodeWriter::applyEdit(p.blocks[0], speed, GcodeDialect::Heidenhain);
    } catch (const InvalidInput& e) {
      error = e.what();
    }
    QCOMPARE(error, QString("gcode edit of line 1: a Heidenhain Klartext L block takes no S word"));
    QVERIFY_THROWS_EXCEPTION(InvalidInput,
                             GcodeWriter::applyEdit(p.blocks[1], feedEdit(100), GcodeDialect::Heidenhain));
  }
  // Sinumerik reads its "%_N_" and ";$PATH" lines first: the header follows them, as ';' comments.
  void sinumerikHeader() {
    const std::string text = gcodeSample("programs/pocket_mm.mpf");
    const GcodeHeader h{"demo", "model-based", "2024-05-01"};
    const std::string out = GcodeWriter::write(GcodeReader::parse(text), {}, &h);
    const std::size_t after_path = text.find('\n', text.find(";$PATH")) + 1;
    QCOMPARE(out, text.substr(0, after_path) + GcodeWriter::headerText(h, "\n", true) + text.substr(after_path));
    QVERIFY(out.find("; project: demo\n") != std::string::npos);
  }
  // Heidenhain numbers its blocks: the header rides on BEGIN PGM, and no line is added.
  void heidenhainHeader() {
    const std::string text = gcodeSample("programs/pocket_mm.h");
    const GcodeHeader h{"demo", "model-based", "2024-05-01"};
    const GcodeProgram in = GcodeReader::parse(text);
    const GcodeProgram out = GcodeReader::parse(GcodeWriter::write(in, {}, &h));
    QCOMPARE(out.blocks.size(), in.blocks.size());
    QCOMPARE(out.blocks[0].text,
             std::string("0 BEGIN PGM POCKET MM ; MillExpert optimised part program, project: demo, "
                         "controller: model-based, date: 2024-05-01"));
    for (std::size_t i = 1; i < in.blocks.size(); ++i) QCOMPARE(out.blocks[i].text, in.blocks[i].text);
  }
  // A comment that would take a block past the reader's 4096 bytes is cut: the program reads again.
  void commentCutAtTheLineLimit() {
    const std::string line = "0 BEGIN PGM " + std::string(4070, 'A') + " MM";
    const GcodeHeader h{"a project with a long name", "model-based", "2024-05-01"};
    const GcodeProgram p = GcodeReader::parse(line + "\n", GcodeDialect::Heidenhain);
    const std::string out = GcodeWriter::write(p, {}, &h);
    QVERIFY(out.size() > 4080 && out.size() <= 4096 + 1);
    QCOMPARE(GcodeReader::parse(out, GcodeDialect::Heidenhain).blocks.size(), std::size_t(1));
  }
  void replaceFeed() {
    QCOMPARE(edited("N50 G1 X40. F600", feedEdit(450)), std::string("N50 G1 X40. F450"));
    QCOMPARE(edited("g1x10f200.5y3", feedEdit(12.25)), std::string("g1x10f12.2y3"));  // case kept, 1 decimal
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

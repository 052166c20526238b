// The ISO-family lexer's dialect constructs: Sinumerik spindle addresses, arc radii, cycle calls,
// assignments and system variables; LinuxCNC parameters, o-words and M52; expression values; and the
// text each dialect cannot split into words.
#include "core/invalid_input.h"
#include "gcode/gcode_interpreter.h"
#include "gcode/gcode_reader.h"
#include "support/gcode_samples.h"
#include "test_registry.h"

using namespace mx;

namespace {
GcodeProgram read(const std::string& text, GcodeDialect d) {
  return GcodeReader::parse(text, d);
}
using mx::test::wordText;
}  // namespace

class TestIsoLexer : public QObject {
  Q_OBJECT
 private slots:
  void samplesRead_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("warnings");
    QTest::newRow("Sinumerik") << "programs/pocket_mm.mpf" << 0;
    QTest::newRow("LinuxCNC") << "programs/pocket_mm.ngc" << 0;
  }
  void samplesRead() {
    QFETCH(QString, file);
    QFETCH(int, warnings);
    const std::string text = test::gcodeSample(file.toStdString());
    const GcodeProgram p = GcodeReader::parse(text);
    QCOMPARE(int(p.warnings.size()), warnings);
    QCOMPARE(p.text(), text);
  }
  void sinumerikSpindleAddressAndRadius() {
    const GcodeProgram p = read("N20 G0 Z5 S1=1500 M3\nN70 G2 X60 Y40 CR=20\n", GcodeDialect::Sinumerik);
    const GcodeBlock& s = p.blocks[0];
    QCOMPARE(wordText(s, s.speedWord()), std::string("S1=1500"));
    QCOMPARE(s.speedWord()->value_at, std::size_t(3));
    QCOMPARE(s.find('S')->value, 1500.0);
    QCOMPARE(p.blocks[1].findAddress("CR")->value, 20.0);
    QVERIFY(p.warnings.empty());
  }
  // Sinumerik's G4 F is the dwell in seconds: no feed word, the modal F stays.
  void sinumerikDwell() {
    const GcodeProgram p = read("G1 X1 F600\nG4 F0.5\nG1 X2\n", GcodeDialect::Sinumerik);
    QCOMPARE(p.blocks[1].feedWord(), nullptr);
    QCOMPARE(p.blocks[1].feed_insert_at, std::string::npos);
    const GcodeRun run = GcodeInterpreter().run(p);
    QCOMPARE(run.motions[1].kind, MotionKind::Dwell);
    QCOMPARE(run.motions[1].dwell_s, 0.5);
    QVERIFY(std::abs(run.motions[2].feed_m_per_s - 600e-3 / 60.0) < 1e-15);
  }
  // G70 gives lengths in inch but leaves F in mm/min; G700 both.
  void sinumerikInch() {
    const GcodeRun g70 = GcodeInterpreter().run(read("G70 G1 X1 F100\n", GcodeDialect::Sinumerik));
    QVERIFY(std::abs(g70.motions[0].length_m - 0.0254) < 1e-15);
    QVERIFY(std::abs(g70.motions[0].feed_m_per_s - 0.1 / 60.0) < 1e-15);
    const GcodeRun g700 = GcodeInterpreter().run(read("G700 G1 X1 F100\n", GcodeDialect::Sinumerik));
    QVERIFY(std::abs(g700.motions[0].feed_m_per_s - 100 * 0.0254 / 60.0) < 1e-15);
  }
  void warnings_data() {
    QTest::addColumn<QString>("dialect");
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("Sinumerik: other call") << "sinumerik"
                                           << "N10 POCKET3(5,0,1)"
                                           << "POCKET3(5,0,1)"
                                           << "call: kept verbatim, not interpreted";
    QTest::newRow("Sinumerik: R parameter") << "sinumerik"
                                            << "R1=5 G1 X1"
                                            << "R1=5"
                                            << "assignment: kept verbatim";
    QTest::newRow("Sinumerik: incremental expression") << "sinumerik"
                                                       << "G1 X=IC(5) F100"
                                                       << "X=IC(5)"
                                                       << "value is an expression: kept verbatim, not evaluated";
    QTest::newRow("Sinumerik: system variable") << "sinumerik"
                                                << "$P_UIFR[1]=0"
                                                << "$P_UIFR[1]=0"
                                                << "system variable: kept verbatim, not evaluated";
    QTest::newRow("Sinumerik: second spindle") << "sinumerik"
                                               << "S2=500"
                                               << "S2=500"
                                               << "assignment: kept verbatim";
    QTest::newRow("LinuxCNC: o-word") << "linuxcnc"
                                      << "o100 call [2] [3]"
                                      << "o100 call [2] [3]"
                                      << "o-word (subroutine or flow control): kept verbatim, not interpreted";
    QTest::newRow("LinuxCNC: expression value") << "linuxcnc"
                                                << "G1 X[#<x>*2] F100"
                                                << "X[#<x>*2]"
                                                << "value is an expression: kept verbatim, not evaluated";
    QTest::newRow("LinuxCNC: parameter value") << "linuxcnc"
                                               << "G1 Z#<depth> F100"
                                               << "Z#<depth>"
                                               << "value is an expression: kept verbatim, not evaluated";
    QTest::newRow("ISO: macro variable") << "iso"
                                         << "#100=2.5"
                                         << "#100=2.5"
                                         << "parameter (macro variable): kept verbatim, not evaluated";
  }
  void warnings() {
    QFETCH(QString, dialect);
    QFETCH(QString, line);
    QFETCH(QString, text);
    QFETCH(QString, message);
    const GcodeProgram p = read(line.toStdString() + "\n", *dialectFromName(dialect.toStdString()));
    QCOMPARE(p.warnings.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(p.warnings[0].text), text);
    QCOMPARE(QString::fromStdString(p.warnings[0].message), message);
  }
  void knownConstructs_data() {
    QTest::addColumn<QString>("dialect");
    QTest::addColumn<QString>("line");
    QTest::newRow("Sinumerik cycle") << "sinumerik"
                                     << "CYCLE832(0.01,_ORI_ROUGH,0.1)";
    QTest::newRow("Sinumerik message") << "sinumerik"
                                       << "MSG(\"roughing (pass 1)\")";
    QTest::newRow("Sinumerik G64") << "sinumerik"
                                   << "G64 G1 X1 F100";
    QTest::newRow("Sinumerik header") << "sinumerik"
                                      << "%_N_POCKET_MPF";
    QTest::newRow("LinuxCNC assignment") << "linuxcnc"
                                         << "#<depth> = [#<d> + 1.5]";
    QTest::newRow("LinuxCNC M52") << "linuxcnc"
                                  << "M52 P1";
    QTest::newRow("LinuxCNC G64 P") << "linuxcnc"
                                    << "G64 P0.01";
    QTest::newRow("block delete") << "iso"
                                  << "/G1 X1 F100";
  }
  void knownConstructs() {
    QFETCH(QString, dialect);
    QFETCH(QString, line);
    const GcodeProgram p = read(line.toStdString() + "\n", *dialectFromName(dialect.toStdString()));
    QVERIFY2(p.warnings.empty(), p.warnings.empty() ? "" : p.warnings[0].message.c_str());
  }
  // A word before a parenthesis stays a word on Sinumerik ("S78591(note)": S78591 and a comment), and a
  // LinuxCNC o-word line takes no inserted F or S.
  void wordsBesideConstructs() {
    const GcodeProgram sin = read("G1 X1 F214821.2S78591(note)\n", GcodeDialect::Sinumerik);
    QCOMPARE(sin.blocks[0].speedWord()->value, 78591.0);
    QCOMPARE(sin.blocks[0].comments.size(), std::size_t(1));
    const GcodeProgram o = read("o100 sub\n", GcodeDialect::LinuxCnc);
    QCOMPARE(o.blocks[0].feed_insert_at, std::string::npos);
    QCOMPARE(o.blocks[0].speed_insert_at, std::string::npos);
  }
  void refused_data() {
    QTest::addColumn<QString>("dialect");
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("message");
    QTest::newRow("ISO: dollar") << "iso"
                                 << "G1 $X1"
                                 << "line 1, column 4: $X1: cannot be split into ISO / Fanuc words (a letter with a "
                                    "number, or a comment)";
    QTest::newRow("Sinumerik: unclosed call") << "sinumerik"
                                              << "CYCLE81(1,2"
                                              << "line 1, column 1: CYCLE81(1,2: cannot be split into Siemens "
                                                 "Sinumerik words (a letter with a number, or a comment)";
    QTest::newRow("LinuxCNC: unclosed bracket") << "linuxcnc"
                                                << "G1 X[1+2 F100"
                                                << "line 1, column 4: X[1+2 F100: cannot be split into LinuxCNC words "
                                                   "(a letter with a number, or a comment)";
    QTest::newRow("LinuxCNC: empty assignment") << "linuxcnc"
                                                << "#<depth> ="
                                                << "line 1, column 1: #<depth> =: cannot be split into LinuxCNC words "
                                                   "(a letter with a number, or a comment)";
    QTest::newRow("LinuxCNC: unclosed bracket value") << "linuxcnc"
                                                      << "#1 = [#1"
                                                      << "line 1, column 1: #1 = [#1: cannot be split into LinuxCNC "
                                                         "words (a letter with a number, or a comment)";
    QTest::newRow("Sinumerik: empty assignment") << "sinumerik"
                                                 << "N10 R1="
                                                 << "line 1, column 5: R1=: cannot be split into Siemens Sinumerik "
                                                    "words (a letter with a number, or a comment)";
    QTest::newRow("Sinumerik: unclosed call in a value")
        << "sinumerik"
        << "$P_UIFR[1]=CTRANS(X,2.5"
        << "line 1, column 1: $P_UIFR[1]=CTRANS(X,2.5: cannot be split into Siemens Sinumerik words (a letter "
           "with a number, or a comment)";
    QTest::newRow("Sinumerik: arc radius past its range")
        << "sinumerik"
        << "G2 X60 Y10 CR=2000000"
        << "line 1, column 12: CR=2000000 = 2e+06: must be in [-1e+06, 1e+06] (coordinate)";
    QTest::newRow("LinuxCNC: bare hash") << "linuxcnc"
                                         << "G1 # X1"
                                         << "line 1, column 4: #: cannot be split into LinuxCNC words (a letter with "
                                            "a number, or a comment)";
  }
  void refused() {
    QFETCH(QString, dialect);
    QFETCH(QString, line);
    QFETCH(QString, message);
    QString error;
    try {
      read(line.toStdString() + "\n", *dialectFromName(dialect.toStdString()));
    } catch (const InvalidInput& e) {
      error = QString::fromStdString(e.what());
    }
    QCOMPARE(error, message);
  }
};

MX_REGISTER_TEST(TestIsoLexer)
#include "test_iso_lexer.moc"

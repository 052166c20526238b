// Dialect detection: each dialect's markers, ISO by default, markers inside comments ignored, and the
// programs that cannot be attributed (two dialects, no G-code) refused with the line that shows it.
#include "core/invalid_input.h"
#include "gcode/gcode_dialect.h"
#include "support/gcode_samples.h"
#include "test_registry.h"

using namespace mx;

class TestGcodeDialect : public QObject {
  Q_OBJECT
 private slots:
  void detected_data() {
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("dialect");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("evidence");
    QTest::newRow("plain ISO") << "G21 G90\nG1 X10 F100\n"
                               << "iso" << 0 << "";
    QTest::newRow("ISO program number") << "O1234\nG0 X0\n"
                                        << "iso" << 0 << "";
    QTest::newRow("empty") << ""
                           << "iso" << 0 << "";
    QTest::newRow("comments only") << "(nothing)\n; still nothing\n"
                                   << "iso" << 0 << "";
    QTest::newRow("BEGIN PGM") << "0 BEGIN PGM P1 MM\n1 L X+10 F100\n"
                               << "heidenhain" << 1 << "BEGIN PGM";
    QTest::newRow("TOOL CALL without BEGIN PGM") << "; part\n3 TOOL CALL 1 Z S2000\n"
                                                 << "heidenhain" << 2 << "TOOL CALL";
    QTest::newRow("numbered L block") << "7 L X+0 Y+0 RL F300\n"
                                      << "heidenhain" << 1 << "block number + L";
    QTest::newRow("Sinumerik header") << "%_N_PART_MPF\nG1 X1 F1\n"
                                      << "sinumerik" << 1 << "%_N_";
    QTest::newRow("CYCLE call") << "G0 X0\nCYCLE832(0.01,1,1)\n"
                                << "sinumerik" << 2 << "CYCLE832(";
    QTest::newRow("spindle address") << "G0 X0 S1=2000 M3\n"
                                     << "sinumerik" << 1 << "S1=";
    QTest::newRow("arc radius") << "G2 X10 Y0 CR=5\n"
                                << "sinumerik" << 1 << "CR=";
    QTest::newRow("named parameter") << "#<depth> = 2\nG1 Z-#<depth>\n"
                                     << "linuxcnc" << 1 << "#<";
    QTest::newRow("adaptive feed input") << "G0 X0\nM52 P1\n"
                                         << "linuxcnc" << 2 << "M52";
    QTest::newRow("o-word") << "o100 sub\nG1 X1 F1\no100 endsub\n"
                            << "linuxcnc" << 1 << "o-word SUB";
    QTest::newRow("MSG comment") << "(MSG, change the tool)\nG0 X0\n"
                                 << "linuxcnc" << 1 << "(MSG,";
    QTest::newRow("lower-case LinuxCNC") << "g0 x0\nm52 p1\n"
                                         << "linuxcnc" << 2 << "M52";
    QTest::newRow("markers in comments do not count") << "(BEGIN PGM in a comment)\nG1 X1 ; CYCLE81(1)\n"
                                                      << "iso" << 0 << "";
  }
  void detected() {
    QFETCH(QString, program);
    QFETCH(QString, dialect);
    QFETCH(int, line);
    QFETCH(QString, evidence);
    const DialectDetection d = detectDialect(program.toStdString());
    QCOMPARE(QString::fromStdString(std::string(dialectName(d.dialect))), dialect);
    QCOMPARE(d.line, line);
    QCOMPARE(QString::fromStdString(d.evidence), evidence);
  }
  void samples_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("dialect");
    QTest::newRow("ISO") << "pocket_mm.nc"
                         << "iso";
    QTest::newRow("Heidenhain") << "programs/pocket_mm.h"
                                << "heidenhain";
    QTest::newRow("Sinumerik") << "programs/pocket_mm.mpf"
                               << "sinumerik";
    QTest::newRow("LinuxCNC") << "programs/pocket_mm.ngc"
                              << "linuxcnc";
  }
  void samples() {
    QFETCH(QString, file);
    QFETCH(QString, dialect);
    const DialectDetection d = detectDialect(test::gcodeSample(file.toStdString()));
    QCOMPARE(QString::fromStdString(std::string(dialectName(d.dialect))), dialect);
  }
  void refused_data() {
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("message");
    QTest::newRow("Heidenhain and Sinumerik")
        << "0 BEGIN PGM A MM\n1 L X+1 F100\nCYCLE81(2,0,1)\n"
        << "line 3: CYCLE81(2,0,1): Siemens Sinumerik syntax (CYCLE81() in a program that line 1 marks as "
           "Heidenhain Klartext (BEGIN PGM): the dialect cannot be detected; name it (iso, heidenhain, sinumerik, "
           "linuxcnc)";
    QTest::newRow("LinuxCNC and Sinumerik") << "#<x> = 1\nG0 X0 S1=100\n"
                                            << "line 2: G0 X0 S1=100: Siemens Sinumerik syntax (S1=) in a program that "
                                               "line 1 marks as LinuxCNC (#<): the dialect cannot be detected; name it "
                                               "(iso, heidenhain, sinumerik, linuxcnc)";
    QTest::newRow("prose") << "\n\nThis is a letter.\nG1 X1\n"
                           << "line 3: This is a letter.: not a block of a known dialect (iso, heidenhain, sinumerik, "
                              "linuxcnc): the dialect cannot be detected; name it if the program is one of them";
  }
  void refused() {
    QFETCH(QString, program);
    QFETCH(QString, message);
    QString error;
    try {
      detectDialect(program.toStdString());
    } catch (const InvalidInput& e) {
      error = QString::fromStdString(e.what());
    }
    QCOMPARE(error, message);
  }
  void names() {
    for (const GcodeDialect d :
         {GcodeDialect::Iso, GcodeDialect::Heidenhain, GcodeDialect::Sinumerik, GcodeDialect::LinuxCnc})
      QCOMPARE(dialectFromName(dialectName(d)), std::optional<GcodeDialect>(d));
    QCOMPARE(dialectFromName("fanuc"), std::optional<GcodeDialect>());
    QCOMPARE(dialectNames(), std::string("iso, heidenhain, sinumerik, linuxcnc"));
  }
};

MX_REGISTER_TEST(TestGcodeDialect)
#include "test_gcode_dialect.moc"

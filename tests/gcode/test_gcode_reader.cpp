// G-code reader: blocks, words, comments, warnings with line/column/text, byte-exact reassembly.
#include <fstream>
#include <sstream>

#include "core/invalid_input.h"
#include "gcode/gcode_reader.h"
#include "support/gcode_samples.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::gcodeSample;
}  // namespace

class TestGcodeReader : public QObject {
  Q_OBJECT
 private slots:
  void reassemblesEveryFileByteForByte_data() {
    QTest::addColumn<QString>("file");
    for (const char* f : mx::test::kGcodeSamples) QTest::newRow(f) << QString(f);
  }
  void reassemblesEveryFileByteForByte() {
    QFETCH(QString, file);
    const std::string text = gcodeSample(file.toStdString());
    const auto p = GcodeReader::readFile(std::string(MX_TEST_DATA_DIR) + "/gcode/" + file.toStdString());
    QCOMPARE(p.text(), text);
    QCOMPARE(
        static_cast<qsizetype>(p.blocks.size()),
        static_cast<qsizetype>(std::count(text.begin(), text.end(), '\n') + (!text.empty() && text.back() != '\n')));
  }
  void emptyFile() {
    const auto p = GcodeReader::parse("");
    QVERIFY(p.blocks.empty());
    QVERIFY(p.warnings.empty());
    QCOMPARE(p.text(), std::string());
  }
  void wordsOfABlock() {
    const auto p = GcodeReader::parse("N20 G0 Z5. S1500 M3\n");
    QCOMPARE(p.blocks.size(), std::size_t(1));
    const auto& b = p.blocks[0];
    QCOMPARE(b.words.size(), std::size_t(5));
    QCOMPARE(b.words[2].letter, 'Z');
    QCOMPARE(b.words[2].value, 5.0);
    QCOMPARE(b.words[3].value, 1500.0);
    QCOMPARE(b.words[3].column, std::size_t(12));
    QCOMPARE(b.words[3].length, std::size_t(5));
    QVERIFY(b.words[4].known);  // M3: a common M word
    QCOMPARE(b.words[4].letter, 'M');
    QVERIFY(p.warnings.empty());
    QCOMPARE(b.words_end, b.text.size());
  }
  // The M words every mill controller shares are known (no warning), several in one block too; others
  // stay unknown and are warned about. All are written back verbatim.
  void commonMWords_data() {
    QTest::addColumn<QString>("block");
    QTest::addColumn<int>("warnings");
    for (const char* m : {"M0", "M1", "M2", "M3", "M4", "M5", "M6", "M7", "M8", "M9", "M30", "m3", "M03"})
      QTest::newRow(m) << QString("G0 Z5 %1").arg(m) << 0;
    QTest::newRow("spindle and coolant in one block") << "S1200 M3 M8" << 0;
    QTest::newRow("M98 (subprogram call)") << "M98 P100" << 1;
    QTest::newRow("M99") << "M99" << 1;
    QTest::newRow("M3.5") << "M3.5" << 1;
    QTest::newRow("M without a number") << "G0 Z5 M" << 1;
  }
  void commonMWords() {
    QFETCH(QString, block);
    QFETCH(int, warnings);
    const std::string text = block.toStdString() + "\n";
    const auto p = GcodeReader::parse(text);
    QCOMPARE(static_cast<int>(p.warnings.size()), warnings);
    QCOMPARE(p.text(), text);
  }
  void compactLowerCaseAndSignedNumbers() {
    const auto p = GcodeReader::parse("g1x10.5y-.5z+2.f200");
    const auto& w = p.blocks[0].words;
    QCOMPARE(w.size(), std::size_t(5));
    QCOMPARE(w[0].letter, 'G');
    QCOMPARE(w[1].value, 10.5);
    QCOMPARE(w[2].value, -0.5);
    QCOMPARE(w[3].value, 2.0);
    QCOMPARE(w[4].letter, 'F');
    QCOMPARE(w[4].value, 200.0);
    QCOMPARE(w[4].column, std::size_t(16));
    QVERIFY(p.blocks[0].hasG(1));
    QCOMPARE(p.blocks[0].eol, std::string());
    QCOMPARE(p.warnings.size(), std::size_t(1));  // no line end
    QCOMPARE(p.warnings[0].column, std::size_t(0));
  }
  void comments() {
    const auto p = GcodeReader::parse("G1 (a) X10 ; tail (x)\n(only)\nG0 (unclosed\n");
    QCOMPARE(p.blocks[0].comments.size(), std::size_t(2));
    QCOMPARE(p.blocks[0].comments[0].text, std::string("a"));
    QCOMPARE(p.blocks[0].comments[1].text, std::string(" tail (x)"));
    QCOMPARE(p.blocks[0].comments[1].column, std::size_t(12));
    QCOMPARE(p.blocks[0].words_end, std::size_t(10));
    QCOMPARE(p.blocks[1].words.size(), std::size_t(0));
    QCOMPARE(p.blocks[2].comments[0].text, std::string("unclosed"));
    QCOMPARE(p.warnings.size(), std::size_t(1));
    QCOMPARE(p.warnings[0].line, 3);
    QCOMPARE(p.warnings[0].column, std::size_t(4));
    QCOMPARE(p.warnings[0].text, std::string("(unclosed"));
  }
  void unknownWordsAndLines() {
    const auto p = GcodeReader::readFile(std::string(MX_TEST_DATA_DIR) + "/gcode/unknown_words.nc");
    struct W {
      int line;
      std::size_t column;
      const char* text;
    };
    // M6 (line 2) and M3 (line 3) are common M words: known, not warned about.
    const W expected[] = {{1, 9, "G54"}, {2, 1, "T1"},  {4, 13, "G40"}, {5, 1, "#100=2.5"}, {6, 4, "X[#100*2]"},
                          {7, 8, "R5"},  {7, 11, "Q2"}, {8, 1, "G18"},  {9, 1, "garbage"},  {9, 9, "line"}};
    QCOMPARE(p.warnings.size(), std::size(expected));
    for (std::size_t i = 0; i < std::size(expected); ++i) {
      QCOMPARE(p.warnings[i].line, expected[i].line);
      QCOMPARE(p.warnings[i].column, expected[i].column);
      QCOMPARE(p.warnings[i].text, std::string(expected[i].text));
      const auto& line = p.blocks[static_cast<std::size_t>(expected[i].line - 1)].text;
      QCOMPARE(line.substr(p.warnings[i].column - 1, p.warnings[i].text.size()), p.warnings[i].text);
    }
    // the known words around the unknown ones are still read
    QCOMPARE(p.blocks[5].find('F')->value, 400.0);
    QCOMPARE(p.blocks[9].find('Y')->value, 10.0);
  }
  void crlfLineEnds() {
    const auto p = GcodeReader::readFile(std::string(MX_TEST_DATA_DIR) + "/gcode/crlf.nc");
    QCOMPARE(p.blocks.size(), std::size_t(6));
    for (const auto& b : p.blocks) {
      QCOMPARE(b.eol, std::string("\r\n"));
      QVERIFY(b.text.find('\r') == std::string::npos);
    }
    QVERIFY(p.warnings.empty());
    QCOMPARE(p.lineEnd(), std::string("\r\n"));
    QCOMPARE(p.blocks[3].find('F')->value, 800.0);
  }
  void truncatedLastLine() {
    const auto p = GcodeReader::readFile(std::string(MX_TEST_DATA_DIR) + "/gcode/truncated.nc");
    QCOMPARE(p.blocks.size(), std::size_t(5));
    QCOMPARE(p.blocks.back().eol, std::string());
    QCOMPARE(p.blocks.back().text, std::string("G1 Y15"));
    QCOMPARE(p.blocks.back().find('Y')->value, 15.0);
    QCOMPARE(p.warnings.size(), std::size_t(1));
    QCOMPARE(p.warnings[0].line, 5);
  }
  void nonAsciiCommentsKept() {
    const auto p = GcodeReader::readFile(std::string(MX_TEST_DATA_DIR) + "/gcode/utf8_comments.nc");
    QVERIFY(p.warnings.empty());
    QCOMPARE(p.blocks[0].comments[0].text, std::string("Tasche fr\xC3\xA4sen \xE2\x80\x93 Werkst\xC3\xBC"
                                                       "ck \xC3\x98 80 mm, Spannung pr\xC3\xBC"
                                                       "fen"));
    QCOMPARE(p.blocks[4].comments[0].text, std::string("\xE5\x88\x87\xE5\x89\x8A cutting"));
    QCOMPARE(p.blocks[4].find('F')->value, 700.0);
  }
  void repeatedWordWarned() {
    const auto p = GcodeReader::parse("G1 X1 X2\n");
    QCOMPARE(p.warnings.size(), std::size_t(1));
    QCOMPARE(p.warnings[0].column, std::size_t(7));
    QCOMPARE(p.blocks[0].find('X')->value, 1.0);
  }
  void unreadableFile() { QVERIFY_THROWS_EXCEPTION(InvalidInput, GcodeReader::readFile("/nonexistent/x.nc")); }

  // Words past their letter's range, non-finite words and over-long lines refuse the program with the
  // line, the column and the range; the values at the limits are read.
  void refusedWords_data() {
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("message");
    QTest::newRow("S at the limit") << "G1 X1 F100 S100000\n" << QString();
    QTest::newRow("S 1e10") << "G1 X1 F100\nS10000000000 G1 X2\n"
                            << "line 2, column 1: S10000000000 = 1e+10: must be in [0, 100000] rpm (spindle speed)";
    QTest::newRow("S negative") << "S-1\n"
                                << "line 1, column 1: S-1 = -1: must be in [0, 100000] rpm (spindle speed)";
    QTest::newRow("F 1e7") << "G1 X1 F10000000\n"
                           << "line 1, column 7: F10000000 = 1e+07: must be in [0, 1e+06] per minute (feed)";
    QTest::newRow("X beyond a kilometre") << "G0 X-2000000\n"
                                          << "line 1, column 4: X-2000000 = -2e+06: must be in [-1e+06, 1e+06] "
                                             "(coordinate)";
    QTest::newRow("P a week") << "G4 P604800\n"
                              << "line 1, column 4: P604800 = 604800: must be in [0, 100000] s (dwell)";
    QTest::newRow("F nan") << "G1 X1 Fnan\n"
                           << "line 1, column 7: Fnan: a word's value must be a finite number";
    QTest::newRow("S -Infinity") << "S-Infinity\n"
                                 << "line 1, column 1: S-Infinity: a word's value must be a finite number";
    QTest::newRow("unknown letter with nan is kept") << "G1 X1 Qnan\n" << QString();
    QTest::newRow("stray number after a word")
        << "G1 S30..2 F200\n"
        << "line 1, column 8: .2: cannot be split into ISO / Fanuc words (a letter with a number, or a comment)";
    QTest::newRow("stray characters") << "G1 X1\n@@ garbage line\n"
                                      << "line 2, column 1: @@: cannot be split into ISO / Fanuc words (a letter "
                                         "with a number, or a comment)";
    QTest::newRow("not G-code at all") << "{\"name\": 1}\n"
                                       << "line 1: {\"name\": 1}: not a block of a known dialect (iso, heidenhain, "
                                          "sinumerik, linuxcnc): the dialect cannot be detected; name it if the "
                                          "program is one of them";
    QTest::newRow("line at the limit") << QString("(") + QString(4094, 'x') + ")\n" << QString();
    QTest::newRow("line past the limit") << QString("(") + QString(4095, 'x') + ")\n"
                                         << "line 1: 4097 characters: a block has at most 4096";
  }
  void refusedWords() {
    QFETCH(QString, program);
    QFETCH(QString, message);
    QString error;
    try {
      GcodeReader::parse(program.toStdString());
    } catch (const InvalidInput& e) {
      error = QString::fromStdString(e.what());
    }
    QCOMPARE(error, message);
  }
};

MX_REGISTER_TEST(TestGcodeReader)
#include "test_gcode_reader.moc"

// Heidenhain Klartext blocks: keywords, words with signs and incremental axes, the editable F and S
// words and where new ones go, structure comments, warnings for what is not interpreted, and the text
// that cannot be split into words.
#include "core/invalid_input.h"
#include "gcode/gcode_reader.h"
#include "support/gcode_samples.h"
#include "test_registry.h"

using namespace mx;

namespace {
GcodeBlock block(const std::string& line) {
  return GcodeReader::parse(line + "\n", GcodeDialect::Heidenhain).blocks.at(0);
}
using mx::test::wordText;
}  // namespace

class TestHeidenhainLexer : public QObject {
  Q_OBJECT
 private slots:
  void sampleReadsWithoutWarnings() {
    const std::string text = test::gcodeSample("programs/pocket_mm.h");
    const GcodeProgram p = GcodeReader::parse(text);
    QCOMPARE(p.dialect.dialect, GcodeDialect::Heidenhain);
    QVERIFY2(p.warnings.empty(), p.warnings.empty() ? "" : p.warnings[0].message.c_str());
    QCOMPARE(p.text(), text);
    const char* keywords[] = {"BEGIN PGM", "",  "BLK", "BLK", "TOOL CALL", "L", "L", "L", "L", "L",
                              "CC",        "C", "CR",  "L",   "*",         "L", "L", "L", "M", "END PGM"};
    QCOMPARE(p.blocks.size(), std::size(keywords));
    for (std::size_t i = 0; i < p.blocks.size(); ++i) QCOMPARE(p.blocks[i].keyword, std::string(keywords[i]));
  }
  void signedAndIncrementalWords() {
    const GcodeBlock b = block("12 L IX-5.5 Y+10 Z-2 RL F250 M3");
    QCOMPARE(b.findAddress("IX")->value, -5.5);
    QCOMPARE(b.findAddress("Y")->value, 10.0);
    QCOMPARE(b.findAddress("Z")->value, -2.0);
    QCOMPARE(wordText(b, b.feedWord()), std::string("F250"));
    QCOMPARE(b.feedWord()->value_at, std::size_t(1));
    const GcodeBlock arc = block("13 CR X+80 Y+20 R-20 DR+");
    QCOMPARE(arc.findAddress("R")->value, -20.0);
    QCOMPARE(arc.findAddress("DR")->value, 1.0);
  }
  // F goes before the M words of a motion block; a rapid (FMAX) and CC take none; F after an M word
  // is the M word's own parameter (M103 F20).
  void feedWordsAndInsertion() {
    const GcodeBlock l = block("9 L Y+20 R0 M8");
    QCOMPARE(l.feedWord(), nullptr);
    QCOMPARE(l.text.substr(0, l.feed_insert_at), std::string("9 L Y+20 R0"));
    QCOMPARE(block("5 L Z+5 R0 FMAX M3").feed_insert_at, std::string::npos);
    QCOMPARE(block("10 CC X+60 Y+20").feed_insert_at, std::string::npos);
    const GcodeBlock m103 = block("17 L X+20 Y+20 RL F500 M103 F20");
    QCOMPARE(wordText(m103, m103.feedWord()), std::string("F500"));
    QVERIFY(!m103.words.back().known);  // F20 is M103's factor, not a feed of the block
    const GcodeBlock automatic = block("8 L X+40 F AUTO");
    QCOMPARE(wordText(automatic, automatic.feedWord()), std::string("F AUTO"));
    QCOMPARE(automatic.feedWord()->has_value, false);
  }
  // TOOL CALL: S is the speed word; a new S goes after the tool axis; other blocks take no S.
  void toolCallSpeed() {
    const GcodeBlock with = block("4 TOOL CALL 1 Z S1500 F600");
    QCOMPARE(wordText(with, with.speedWord()), std::string("S1500"));
    const GcodeBlock without = block("4 TOOL CALL \"MILL D10 Z3\" Z F600 DL+0.1");
    QCOMPARE(without.speedWord(), nullptr);
    QCOMPARE(without.text.substr(0, without.speed_insert_at), std::string("4 TOOL CALL \"MILL D10 Z3\" Z"));
    QCOMPARE(block("7 L Z-2 F150").speed_insert_at, std::string::npos);
  }
  void commentsAndBlockSkip() {
    const GcodeBlock structure = block("14 * - step up: 1 mm");
    QCOMPARE(structure.keyword, std::string("*"));
    QCOMPARE(structure.comments.at(0).text, std::string(" - step up: 1 mm"));
    const GcodeBlock skipped = block("15 / L Z-1 F100 ; optional pass");
    QCOMPARE(skipped.keyword, std::string("L"));
    QCOMPARE(skipped.comments.at(0).text, std::string(" optional pass"));
    QCOMPARE(wordText(skipped, skipped.feedWord()), std::string("F100"));
  }
  void warnings_data() {
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown word in L") << "7 L X+1 Q5 F100"
                                       << "Q5"
                                       << "unknown word: kept verbatim";
    QTest::newRow("malformed number") << "7 L X+1.2.3 F100"
                                      << "X+1.2.3"
                                      << "unknown word: kept verbatim";
    QTest::newRow("polar move") << "8 LP PR+10 PA+30"
                                << "LP PR+10 PA+30"
                                << "block not interpreted (its motion is not modelled): kept verbatim";
    QTest::newRow("cycle call") << "9 CYCL CALL M3"
                                << "CYCL CALL M3"
                                << "block not interpreted (its motion is not modelled): kept verbatim";
    QTest::newRow("unknown keyword") << "10 FOO X+1"
                                     << "FOO X+1"
                                     << "unknown block: kept verbatim";
  }
  void warnings() {
    QFETCH(QString, line);
    QFETCH(QString, text);
    QFETCH(QString, message);
    const GcodeProgram p = GcodeReader::parse(line.toStdString() + "\n", GcodeDialect::Heidenhain);
    QCOMPARE(p.warnings.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(p.warnings[0].text), text);
    QCOMPARE(QString::fromStdString(p.warnings[0].message), message);
  }
  void silentBlocks() {
    for (const char* line : {"2 BLK FORM 0.1 Z X+0 Y+0 Z-20", "3 CYCL DEF 200 DRILLING", "4 Q200=2 ;SET-UP CLEARANCE",
                             "5 FN 0: Q1 = +5", "6 LBL 1", "7 M30", "8 STOP", ""})
      QVERIFY2(GcodeReader::parse(std::string(line) + "\n", GcodeDialect::Heidenhain).warnings.empty(), line);
  }
  void refused_data() {
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("message");
    QTest::newRow("stray character") << "7 L X+1 @ F100"
                                     << "line 1, column 9: @: cannot be split into Heidenhain Klartext words";
    QTest::newRow("block number run into a word") << "12L X+1"
                                                  << "line 1, column 1: 12L: cannot be split into Heidenhain "
                                                     "Klartext words";
    QTest::newRow("unclosed tool name") << "4 TOOL CALL \"MILL Z S100"
                                        << "line 1, column 13: \"MILL Z S100: cannot be split into Heidenhain "
                                           "Klartext words";
    QTest::newRow("feed past its range") << "7 L X+1 F2000000"
                                         << "line 1, column 9: F2000000 = 2e+06: must be in [0, 1e+06] per minute "
                                            "(feed)";
  }
  void refused() {
    QFETCH(QString, line);
    QFETCH(QString, message);
    QString error;
    try {
      GcodeReader::parse(line.toStdString() + "\n", GcodeDialect::Heidenhain);
    } catch (const InvalidInput& e) {
      error = QString::fromStdString(e.what());
    }
    QCOMPARE(error, message);
  }
};

MX_REGISTER_TEST(TestHeidenhainLexer)
#include "test_heidenhain_lexer.moc"

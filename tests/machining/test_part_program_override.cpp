// Part-program overrides: round trip, F/S-only differences (checked block by block), modal feed,
// missing F, truncated line, non-ASCII comments, CRLF, empty file, inch programs, CSV.
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/invalid_input.h"
#include "gcode/gcode_reader.h"
#include "machining/part_program_override.h"
#include "support/gcode_samples.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::gcodeSample;
const GcodeHeader kHeader{"tests", "model-based (Landers & Ulsoy)", "2024-05-01"};

ModelBasedForceController landers(double f_ref) {
  ModelBasedForceSettings s;
  s.reference_force_N = f_ref;
  return ModelBasedForceController(s);
}
// Keeps the programmed feed (or 100 mm/min where none).
FeedDecision identity(const CutState& s) {
  return {s.programmed_feed_m_per_s == s.programmed_feed_m_per_s ? s.programmed_feed_m_per_s : 100e-3 / 60.0, 0.0,
          "id"};
}

// The block without comments, F and S words, and whitespace: what must not change.
std::string skeleton(const GcodeBlock& b) {
  std::string t = b.text;
  struct Span {
    std::size_t pos, len;
  };
  std::vector<Span> cut;
  for (const auto& c : b.comments) cut.push_back({c.column - 1, c.length});
  for (const auto& w : b.words)
    if (w.known && (w.letter == 'F' || w.letter == 'S')) cut.push_back({w.column - 1, w.length});
  std::sort(cut.begin(), cut.end(), [](const Span& a, const Span& c) { return a.pos > c.pos; });
  for (const auto& s : cut) t.erase(s.pos, s.len);
  std::string out;
  for (char c : t)
    if (c != ' ' && c != '\t') out += c;
  return out + "|" + b.eol;
}

// Checks that output = header + input with only F/S words and comments changed; returns the number of
// blocks that differ.
int checkOnlyFeedSpeedComments(const std::string& input, const std::string& output) {
  const auto in = GcodeReader::parse(input);
  const auto out = GcodeReader::parse(output);
  const std::size_t header_lines = 4 + ((!in.blocks.empty() && in.blocks[0].text == "%") ? 1 : 0);
  if (out.blocks.size() != in.blocks.size() + 4) return -1;
  int differing = 0;
  std::size_t k = 0;
  for (std::size_t i = 0; i < out.blocks.size(); ++i) {
    const bool is_header = (header_lines == 5) ? (i >= 1 && i <= 4) : (i < 4);
    if (is_header) {
      if (!out.blocks[i].words.empty() || out.blocks[i].comments.size() != 1) return -1;
      continue;
    }
    const auto& a = in.blocks[k++];
    const auto& b = out.blocks[i];
    if (skeleton(a) != skeleton(b)) return -1;
    if (a.text != b.text) ++differing;
  }
  return differing;
}

// The block without comments, its editable F and S words, and blanks (any dialect).
std::string dialectSkeleton(const GcodeBlock& b) {
  struct Span {
    std::size_t pos, len;
  };
  std::vector<Span> cut;
  for (const auto& c : b.comments) cut.push_back({c.column - 1, c.length});
  for (const GcodeWord* w : {b.feedWord(), b.speedWord()})
    if (w) cut.push_back({w->column - 1, w->length});
  std::sort(cut.begin(), cut.end(), [](const Span& a, const Span& c) { return a.pos > c.pos; });
  std::string t = b.text;
  for (const auto& span : cut) t.erase(span.pos, span.len);
  std::string out;
  for (char c : t)
    if (c != ' ' && c != '\t') out += c;
  return out + "|" + b.eol;
}

// The new F of every feed move of the pocket, overridden at 400 N in its dialect.
std::vector<double> overriddenFeeds(const std::string& file, std::string* output = nullptr) {
  const std::string text = gcodeSample(file);
  const auto r = PartProgramOverrider(modelBasedFeedController(landers(400.0)), PartProgramOverrideSettings{})
                     .run(std::string_view(text));
  const std::string out = r.writeProgram(kHeader);
  if (output) *output = out;
  const GcodeProgram back = GcodeReader::parse(out);
  const GcodeRun run = GcodeInterpreter().run(back);
  std::vector<double> feeds;
  for (const GcodeMotion& m : run.motions)
    if (m.isFeedMove()) feeds.push_back(m.feed_m_per_s);
  return feeds;
}

PartProgramOverrideSettings stockTopZero() {
  PartProgramOverrideSettings s;
  s.stock_top_z_m = 0.0;
  return s;
}
}  // namespace

class TestPartProgramOverride : public QObject {
  Q_OBJECT
 private slots:
  void roundTripWithoutChanges_data() {
    QTest::addColumn<QString>("file");
    for (const char* f :
         {"pocket_mm.nc", "crlf.nc", "inch.nc", "unknown_words.nc", "truncated.nc", "utf8_comments.nc", "empty.nc"})
      QTest::newRow(f) << QString(f);
  }
  void roundTripWithoutChanges() {
    QFETCH(QString, file);
    const std::string text = gcodeSample(file.toStdString());
    const auto r = PartProgramOverrider(identity, stockTopZero()).run(std::string_view(text));
    QCOMPARE(r.changed_blocks, std::size_t(0));
    const std::string out = r.writeProgram(kHeader);
    std::string header = GcodeWriter::headerText(kHeader, r.program.lineEnd());
    std::string expected = text;
    const std::size_t at = (text.rfind("%\n", 0) == 0) ? 2 : 0;
    expected.insert(at, header);
    QCOMPARE(out, expected);
    QCOMPARE(checkOnlyFeedSpeedComments(text, out), 0);
  }
  void modelBasedChangesOnlyFeedSpeedAndComments_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("changed");
    QTest::newRow("pocket_mm.nc") << "pocket_mm.nc" << 2;  // N50 F600 -> force limit, N120 (1 mm) -> drive max
    QTest::newRow("crlf.nc") << "crlf.nc" << 1;            // plunges keep their feed
    QTest::newRow("utf8_comments.nc") << "utf8_comments.nc" << 1;
    QTest::newRow("truncated.nc") << "truncated.nc" << 1;
    QTest::newRow("unknown_words.nc") << "unknown_words.nc" << 1;
    QTest::newRow("missing_f.nc") << "missing_f.nc" << 2;  // the F-less plunge, and F500
  }
  void modelBasedChangesOnlyFeedSpeedAndComments() {
    QFETCH(QString, file);
    QFETCH(int, changed);
    const std::string text = gcodeSample(file.toStdString());
    const auto controller = landers(400.0);
    const auto r =
        PartProgramOverrider(modelBasedFeedController(controller), stockTopZero()).run(std::string_view(text));
    const std::string out = r.writeProgram(kHeader);
    const int differing = checkOnlyFeedSpeedComments(text, out);
    QCOMPARE(differing, static_cast<int>(r.changed_blocks));
    QCOMPARE(differing, changed);
    // The output, read back, runs every feed move at the row's new feed; the cutting ones at 400 N
    // (or at a feed maximum); plunges keep their feed (predicted force NaN).
    const auto rerun = GcodeInterpreter().run(GcodeReader::parse(out));
    std::size_t k = 0;
    for (const auto& m : rerun.motions) {
      if (!m.isFeedMove()) continue;
      QVERIFY(k < r.rows.size());
      const auto& row = r.rows[k++];
      QVERIFY(std::abs(m.feed_m_per_s - row.new_feed_m_per_s) < 1e-12);
      if (row.depth_m > 0.0 && !std::isnan(row.predicted_force_N)) {  // cutting, not a kept plunge
        const double n = row.speed_rev_per_s;
        const double force = controller.force(row.depth_m, m.feed_m_per_s / (4.0 * n));
        const bool at_max = m.feed_m_per_s >= 36e-3 * (1 - 1e-3) || m.feed_m_per_s / (4.0 * n) >= 0.6e-3 * (1 - 1e-3);
        QVERIFY2(at_max || std::abs(force - 400.0) < 0.5,
                 qPrintable(QString("line %1: %2 N").arg(row.line).arg(force)));
      }
    }
    QCOMPARE(k, r.rows.size());
    // every changed block says why
    for (const auto& edit : r.edits)
      if (!edit.empty()) QVERIFY(edit.comment.rfind("MX: ", 0) == 0);
  }
  void modalFeedRestoredAfterChangedBlock() {
    // Block 2 cuts 2 mm (feed changed), block 4 inherits F in the input but is an air move: the
    // programmed 900 mm/min must be written back, or it would run at block 2's feed.
    const std::string text = "G21 G90 S1500\nG1 X10 Z-2 F900\nG0 Z1\nG1 X20\nG1 X30\n";
    const auto r =
        PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero()).run(std::string_view(text));
    QVERIFY(r.edits[1].feed == r.edits[1].feed);
    QVERIFY(std::abs(r.edits[1].feed - 900.0) > 1.0);
    QCOMPARE(r.edits[3].feed, 900.0);
    QVERIFY(r.edits[3].comment.find("restore programmed feed (air move)") != std::string::npos);
    QVERIFY(r.edits[4].empty());  // modal 900 again
    const auto rerun = GcodeInterpreter().run(GcodeReader::parse(r.writeProgram(kHeader)));
    QVERIFY(std::abs(rerun.motions[4 + 1].feed_m_per_s - r.edits[1].feed * 1e-3 / 60.0) < 1e-15);
    QVERIFY(std::abs(rerun.motions[4 + 3].feed_m_per_s - 900e-3 / 60.0) < 1e-15);
    QVERIFY(std::abs(rerun.motions[4 + 4].feed_m_per_s - 900e-3 / 60.0) < 1e-15);
  }
  void plungeKeepsFeedUnlessTold() {
    const std::string text = "G21 G90 S1500\nG1 Z-2 F100\n";
    auto s = stockTopZero();
    const auto keep = PartProgramOverrider(modelBasedFeedController(landers(400.0)), s).run(std::string_view(text));
    QVERIFY(keep.edits[1].empty());
    s.keep_plunge_feed = false;
    const auto change = PartProgramOverrider(modelBasedFeedController(landers(400.0)), s).run(std::string_view(text));
    QCOMPARE(change.edits[1].feed, 1059.5);  // (400/(760*2^0.65))^(1/0.63) mm * 4 * 1500 rpm
  }
  void missingFeedGetsControllerFeed() {
    const std::string text = gcodeSample("missing_f.nc");
    const auto r =
        PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero()).run(std::string_view(text));
    QCOMPARE(r.rows.size(), std::size_t(4));
    QVERIFY(std::isnan(r.rows[0].original_feed_m_per_s));
    QVERIFY(r.rows[0].reason.rfind("missing F", 0) == 0);
    QVERIFY(r.edits[2].feed > 0.0);
    const auto out = GcodeReader::parse(r.writeProgram(kHeader));
    QVERIFY(GcodeInterpreter().run(out).warnings.empty());  // no feed move without F any more
    bool warned = false;
    for (const auto& w : r.warnings)
      warned = warned || (w.line == 3 && w.message.find("without F") != std::string::npos);
    QVERIFY(warned);
  }
  void truncatedLastLineStaysTruncated() {
    const auto r = PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero())
                       .run(std::string_view(gcodeSample("truncated.nc")));
    const std::string out = r.writeProgram(kHeader);
    QVERIFY(out.size() > 6 && out.compare(out.size() - 7, 7, "\nG1 Y15") == 0);  // unchanged, no line end added
    // and when the truncated line itself changes
    const auto r2 = PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero())
                        .run(std::string_view("S1500\nG1 X30 Z-2 F900\nG0 Z1\nG1 Y15"));
    const std::string out2 = r2.writeProgram(kHeader);
    QCOMPARE(out2.substr(out2.rfind('\n') + 1),
             std::string("G1 Y15 F900 (MX: F 900 mm/min, restore programmed feed [air move])"));
  }
  void nonAsciiCommentsAndCrlfPreserved() {
    const std::string utf8 = gcodeSample("utf8_comments.nc");
    const std::string out = PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero())
                                .run(std::string_view(utf8))
                                .writeProgram(kHeader);
    QVERIFY(out.find("(Tasche fr\xC3\xA4sen \xE2\x80\x93 Werkst\xC3\xBC"
                     "ck \xC3\x98 80 mm, Spannung pr\xC3\xBC"
                     "fen)\n") != std::string::npos);
    QVERIFY(out.find("(\xE5\x88\x87\xE5\x89\x8A cutting)") != std::string::npos);
    QVERIFY(out.find("; Schnittgeschwindigkeit \xE2\x89\x88 80 m/min") != std::string::npos);
    const std::string crlf = gcodeSample("crlf.nc");
    const std::string out2 = PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero())
                                 .run(std::string_view(crlf))
                                 .writeProgram(kHeader);
    QCOMPARE(std::count(out2.begin(), out2.end(), '\n'), std::count(out2.begin(), out2.end(), '\r'));
    QCOMPARE(std::count(out2.begin(), out2.end(), '\n'), std::ptrdiff_t(10));
  }
  void emptyProgram() {
    const auto r =
        PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero()).run(std::string_view(""));
    QVERIFY(r.rows.empty());
    QCOMPARE(r.writeProgram(kHeader), GcodeWriter::headerText(kHeader, "\n"));
    QCOMPARE(r.csv(), FeedOverrideTable::header());
  }
  void inchProgram() {
    const auto controller = landers(400.0);
    const auto r = PartProgramOverrider(modelBasedFeedController(controller), stockTopZero())
                       .run(std::string_view(gcodeSample("inch.nc")));
    // G1 X2.0 F30. cuts 0.05 in = 1.27 mm deep at 3000 rpm
    const auto& row = r.rows[1];
    QVERIFY(std::abs(row.depth_m - 1.27e-3) < 1e-15);
    const double v = controller.feed(1.27e-3, 50.0).feed_rate_m_per_s;
    const double in_per_min = std::round(v * 60.0 / 0.0254 * 100.0) / 100.0;
    QVERIFY(std::abs(r.edits[4].feed - in_per_min) < 1e-9);  // written in in/min, 2 decimals
    QVERIFY(std::abs(row.new_feed_m_per_s - in_per_min * 0.0254 / 60.0) < 1e-15);
    QVERIFY(std::abs(row.original_feed_m_per_s - 30.0 * 0.0254 / 60.0) < 1e-15);
    QVERIFY(r.edits[4].comment.find("in/min") != std::string::npos);
    const std::string out = r.writeProgram(kHeader);
    QVERIFY(out.find("G1 X2.0 F" + GcodeWriter::formatNumber(in_per_min, 2) + " (MX: ") != std::string::npos);
    // CSV in mm/min
    QVERIFY(r.csv().find(",762,") != std::string::npos);  // 30 in/min original
  }
  void speedOverride() {
    auto s = stockTopZero();
    s.speed_rev_per_s = 2134.0 / 60.0;
    const std::string text = gcodeSample("pocket_mm.nc");
    const auto r = PartProgramOverrider(modelBasedFeedController(landers(400.0)), s).run(std::string_view(text));
    QCOMPARE(r.edits[3].speed_rpm, 2134.0);  // N20 G0 Z5. S1500 M3
    for (const auto& row : r.rows) QVERIFY(std::abs(row.speed_rev_per_s * 60.0 - 2134.0) < 1e-9);
    const std::string out = r.writeProgram(kHeader);
    QVERIFY(out.find("N20 G0 Z5. S2134 M3 (MX: S 2134 rpm from the expert system)") != std::string::npos);
    QVERIFY(checkOnlyFeedSpeedComments(text, out) > 0);
  }
  void noSpindleSpeed() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput,
                             PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero())
                                 .run(std::string_view("G1 X10 Z-1 F100\n")));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, PartProgramOverrider(BlockFeedController{}, stockTopZero()));
  }
  // A feed move in the air with no F anywhere before it: no controller sets its feed, so the program is
  // refused with the line instead of a non-finite feed.
  void missingFeedAboveTheStock() {
    try {
      PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero())
          .run(std::string_view("G21 G90 S1200\nG0 Z5\nG1 X10\n"));
      QFAIL("expected InvalidInput");
    } catch (const InvalidInput& e) {
      QCOMPARE(std::string(e.what()), std::string("part program line 3: a feed move with no F word before it, above "
                                                  "the stock where no controller sets the feed: add an F word to this "
                                                  "line or an earlier one"));
    }
  }
  // The pocket in every dialect: read back in its own dialect, the output has the same blocks in the
  // same order, only F / S words and comments changed (header lines aside), and its feed moves run at
  // the feeds of the ISO program's override.
  void dialectRoundTrip_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("header_lines");
    QTest::newRow("Heidenhain") << "programs/pocket_mm.h" << 0;
    QTest::newRow("Sinumerik") << "programs/pocket_mm.mpf" << 4;
    QTest::newRow("LinuxCNC") << "programs/pocket_mm.ngc" << 4;
  }
  void dialectRoundTrip() {
    QFETCH(QString, file);
    QFETCH(int, header_lines);
    std::string out;
    const std::vector<double> feeds = overriddenFeeds(file.toStdString(), &out);
    const std::vector<double> iso = overriddenFeeds("pocket_mm.nc");
    QCOMPARE(feeds.size(), iso.size());
    for (std::size_t i = 0; i < iso.size(); ++i) QVERIFY(std::abs(feeds[i] - iso[i]) < 1e-12);
    const GcodeProgram in = GcodeReader::parse(gcodeSample(file.toStdString()));
    const GcodeProgram back = GcodeReader::parse(out);
    QCOMPARE(back.dialect.dialect, in.dialect.dialect);
    QCOMPARE(back.blocks.size(), in.blocks.size() + std::size_t(header_lines));
    std::size_t k = 0, changed = 0;
    int headers = 0;
    for (const GcodeBlock& b : back.blocks) {
      if (k < in.blocks.size() && dialectSkeleton(b) == dialectSkeleton(in.blocks[k])) {
        if (b.text != in.blocks[k++].text) ++changed;
        continue;
      }
      QVERIFY2(b.words.empty() && b.comments.size() == 1, b.text.c_str());  // an inserted header line
      ++headers;
    }
    QCOMPARE(headers, header_lines);
    QCOMPARE(k, in.blocks.size());
    QVERIFY(changed >= 2);
  }
  // Heidenhain keeps S in the TOOL CALL: the expert system's speed changes it, and a TOOL CALL without
  // S gets one; a feed move with no TOOL CALL before it cannot.
  void heidenhainSpeedGoesToTheToolCall() {
    PartProgramOverrideSettings s;
    s.speed_rev_per_s = 2134.0 / 60.0;
    const auto r = PartProgramOverrider(identity, s).run(std::string_view(gcodeSample("programs/pocket_mm.h")));
    QCOMPARE(r.edits[4].speed_rpm, 2134.0);  // 4 TOOL CALL 1 Z S1500 F600
    for (std::size_t i = 0; i < r.edits.size(); ++i)
      if (i != 4) QVERIFY(std::isnan(r.edits[i].speed_rpm));
    const auto inserted =
        PartProgramOverrider(identity, s).run(std::string_view("TOOL CALL 1 Z F600\nL Z-1 F100\nL X+10\n"));
    const std::string first = inserted.writeProgram(kHeader).substr(0, inserted.writeProgram(kHeader).find('\n'));
    QVERIFY2(first.rfind("TOOL CALL 1 Z S2134 F600 ; MillExpert optimised part program", 0) == 0, first.c_str());
    QVERIFY(first.find("MX: S 2134 rpm from the expert system") != std::string::npos);
    QVERIFY_THROWS_EXCEPTION(InvalidInput,
                             PartProgramOverrider(identity, s).run(std::string_view("BEGIN PGM A MM\nL Z-1 F100\n")));
  }
  // LinuxCNC's M52 P1 scales every F by the adaptive-feed input: the operator is told once.
  void linuxCncAdaptiveFeedInputWarned() {
    const auto r = PartProgramOverrider(modelBasedFeedController(landers(400.0)), PartProgramOverrideSettings{})
                       .run(std::string_view(gcodeSample("programs/pocket_mm.ngc")));
    int told = 0;
    for (const GcodeWarning& w : r.warnings)
      if (w.message.find("M52 P1 (line 7) is in effect") != std::string::npos) ++told;
    QCOMPARE(told, 1);
  }
  void csvTable() {
    const auto r = PartProgramOverrider(modelBasedFeedController(landers(400.0)), stockTopZero())
                       .run(std::string_view(gcodeSample("crlf.nc")));
    const std::string csv = r.csv();
    QCOMPARE(std::count(csv.begin(), csv.end(), '\n'), std::ptrdiff_t(1 + 3));
    QVERIFY(csv.find("\n3,3,200,") != std::string::npos);
    QVERIFY(csv.find(",400\n") != std::string::npos);  // predicted force of a force-limited block
  }
};

MX_REGISTER_TEST(TestPartProgramOverride)
#include "test_part_program_override.moc"

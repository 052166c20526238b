// Line reading over bytes with binary blocks: line ends, trailing blanks, skips and put-back.
#include "frf/text_lines.h"
#include "test_registry.h"

using namespace mx;

class TestTextLines : public QObject {
  Q_OBJECT
 private slots:
  void lineEndsAndTrailingBlanks() {
    TextLines lines("a  \r\nb\t\n\n  c");
    TextLine l;
    QVERIFY(lines.next(l));
    QCOMPARE(l.text, std::string_view("a"));
    QCOMPARE(l.number, 1);
    QVERIFY(lines.next(l));
    QCOMPARE(l.text, std::string_view("b"));
    QVERIFY(lines.nextNonBlank(l));  // skips the empty line 3
    QCOMPARE(l.text, std::string_view("  c"));
    QCOMPARE(l.number, 4);
    QVERIFY(!lines.next(l));
    QCOMPARE(lines.remaining(), std::size_t(0));
  }

  void skipCountsLineEnds() {
    TextLines lines("h\n\x01\n\n\x02tail\nlast");
    TextLine l;
    QVERIFY(lines.next(l));
    QCOMPARE(lines.position(), std::size_t(2));
    lines.skip(4);  // "\x01\n\n\x02"
    QCOMPARE(lines.lineNumber(), 3);
    QVERIFY(lines.next(l));
    QCOMPARE(l.text, std::string_view("tail"));
    QCOMPARE(l.number, 4);
    lines.skip(100);  // at most what is left
    QCOMPARE(lines.remaining(), std::size_t(0));
  }

  void putBackReturnsTheSameLine() {
    TextLines lines("one\ntwo\n");
    TextLine l;
    lines.next(l);
    lines.next(l);
    lines.putBack();
    QCOMPARE(lines.lineNumber(), 1);
    QVERIFY(lines.next(l));
    QCOMPARE(l.text, std::string_view("two"));
    QCOMPARE(l.number, 2);
  }

  void delimiter_data() {
    QTest::addColumn<QString>("line");
    QTest::addColumn<bool>("delimiter");
    QTest::newRow("I6") << "    -1" << true;
    QTest::newRow("flush") << "-1" << true;
    QTest::newRow("tab") << "\t-1" << true;
    QTest::newRow("-10") << "   -10" << false;
    QTest::newRow("58") << "    58" << false;
    QTest::newRow("value") << "  -1.0" << false;
  }
  void delimiter() {
    QFETCH(QString, line);
    QFETCH(bool, delimiter);
    QCOMPARE(isUffDelimiter(line.toStdString()), delimiter);
  }
};

MX_REGISTER_TEST(TestTextLines)
#include "test_text_lines.moc"

// Values echoed in messages (document/shortened_text.h): whole up to 80 characters, else the first 80,
// a mark and the length; a surrogate pair is never cut; formatValue shortens JSON values the same way.
#include <QJsonArray>

#include "document/project_rules.h"
#include "document/shortened_text.h"
#include "test_registry.h"

using namespace mx::app;

namespace {
const QChar kMark(0x2026);
}

class TestShortenedText : public QObject {
  Q_OBJECT
 private slots:
  void shortenedAndQuoted_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("shortened");
    QTest::addColumn<QString>("quoted");
    QTest::newRow("empty") << QString() << QString() << "''";
    QTest::newRow("80 characters") << QString(80, 'a') << QString(80, 'a') << "'" + QString(80, 'a') + "'";
    QTest::newRow("81 characters") << QString(81, 'a') << QString(80, 'a') + kMark + " (81 characters)"
                                   << "'" + QString(80, 'a') + kMark + "' (81 characters)";
    QTest::newRow("10 MB") << QString(10485760, 'a') << QString(80, 'a') + kMark + " (10485760 characters)"
                           << "'" + QString(80, 'a') + kMark + "' (10485760 characters)";
    // U+1F600 is a surrogate pair; the 80th UTF-16 unit would be its first half.
    const QString smiles = QString(79, 'b') + QString(40, QChar(0xD83D)).replace(QChar(0xD83D), "\U0001F600");
    QTest::newRow("surrogate pair at the cut")
        << smiles << QString(79, 'b') + kMark + QString(" (%1 characters)").arg(smiles.size())
        << "'" + QString(79, 'b') + kMark + QString("' (%1 characters)").arg(smiles.size());
  }
  void shortenedAndQuoted() {
    QFETCH(QString, text);
    QFETCH(QString, shortened);
    QFETCH(QString, quoted);
    QCOMPARE(mx::app::shortened(text), shortened);
    QCOMPARE(mx::app::quoted(text), quoted);
  }

  void doubleQuotes() {
    QCOMPARE(quoted(QString(90, 'c'), u'"'), "\"" + QString(80, 'c') + kMark + "\" (90 characters)");
  }

  void formatValueShortens_data() {
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("expected");
    QTest::newRow("short string") << QJsonValue("up") << "\"up\"";
    QTest::newRow("long string") << QJsonValue(QString(1000, 'x'))
                                 << "\"" + QString(80, 'x') + kMark + "\" (1000 characters)";
    QTest::newRow("escaped") << QJsonValue(QString(100, '\n'))
                             << "\"" + QString(80, '\\').replace("\\", "\\n") + kMark + "\" (100 characters)";
    QJsonArray numbers;
    for (int i = 0; i < 100; ++i) numbers.append(1000 + i);
    const QString array = "[1000,1001,1002,1003,1004,1005,1006,1007,1008,1009,1010,1011,1012,1013,1014,1015,";
    QTest::newRow("long array") << QJsonValue(numbers) << array.left(80) + kMark + " (501 characters)";
    QTest::newRow("number") << QJsonValue(150.0) << "150";
  }
  void formatValueShortens() {
    QFETCH(QJsonValue, value);
    QFETCH(QString, expected);
    QCOMPARE(formatValue(value), expected);
  }
};

MX_REGISTER_TEST(TestShortenedText)
#include "test_shortened_text.moc"

// Reading outside files (core/input_file.h through document/input_files.h): a regular file up to its
// limit is read whole; over the limit, or a device, FIFO or directory, is refused before a byte is
// read, with the size and the limit named; loadProject refuses the same, naming the file.
#include <QElapsedTimer>
#include <QTemporaryDir>

#include "core/invalid_input.h"
#include "document/input_files.h"
#include "document/project.h"
#include "support/hostile_files.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::app;

namespace {
constexpr InputFileLimit kSmall{1 * kMegabyte, "a test file"};
}

class TestInputFiles : public QObject {
  Q_OBJECT
 private slots:
  void refused_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("expected");
    QTest::newRow("/dev/zero") << "/dev/zero"
                               << "a character device, not a regular file: a test file must be a regular file";
    QTest::newRow("/dev/null") << "/dev/null"
                               << "a character device, not a regular file: a test file must be a regular file";
    QTest::newRow("FIFO") << "fifo"
                          << "a FIFO, not a regular file: a test file must be a regular file";
    QTest::newRow("folder") << "folder"
                            << "a directory, not a regular file: a test file must be a regular file";
    QTest::newRow("1 MB + 1 byte") << "bytes:1048577"
                                   << "1.0 MB (1048577 bytes) is over the 1 MB limit of a test file";
    QTest::newRow("missing") << "missing"
                             << "cannot be read (expected a readable file)";
  }
  void refused() {
    QFETCH(QString, kind);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString path = kind == "missing" ? dir.filePath("absent") : test::hostileInput(dir, kind);
    QVERIFY(!path.isEmpty());
    QElapsedTimer clock;
    clock.start();
    try {
      readBoundedFile(path, kSmall);
      QFAIL("read");
    } catch (const InvalidInput& e) {
      QCOMPARE(QString::fromStdString(e.what()), expected);
    }
    QVERIFY(clock.elapsed() < 2000);
  }

  void atTheLimitIsRead() {
    QTemporaryDir dir;
    const QString path = test::hostileInput(dir, "bytes:1048576");
    const QByteArray bytes = readBoundedFile(path, kSmall);
    QCOMPARE(bytes.size(), 1048576);
    QCOMPARE(bytes.count('\0'), 1048576);
  }

  void projectLimitIsNamed() {
    QCOMPARE(kProjectFileLimit.max_bytes, 64 * kMegabyte);
    QTemporaryDir dir;
    const QString path = test::hostileInput(dir, QString("bytes:%1").arg(80 * test::kMB));
    try {
      loadProject(path);
      QFAIL("loaded");
    } catch (const ProjectError& e) {
      QCOMPARE(QString::fromStdString(e.what()),
               path + ": 80.0 MB (83886080 bytes) is over the 64 MB limit of a project file");
    }
  }
};

MX_REGISTER_TEST(TestInputFiles)
#include "test_input_files.moc"

// The FRF reader's error: its message names the file, the line or block byte, and what was expected.
#include "frf/frf_file_error.h"
#include "test_registry.h"

using namespace mx;

class TestFrfFileError : public QObject {
  Q_OBJECT
 private slots:
  void atLine() {
    const FrfFileError e("a.unv", 12, "expected a number");
    QCOMPARE(std::string(e.what()), std::string("a.unv: line 12: expected a number"));
    QCOMPARE(e.source(), std::string("a.unv"));
    QCOMPARE(e.line(), 12);
    QVERIFY(!e.blockOffset());
  }
  void wholeFile() {
    const FrfFileError e("/x/a.csv", 0, "cannot be read");
    QCOMPARE(std::string(e.what()), std::string("/x/a.csv: cannot be read"));
  }
  void inBinaryBlock() {
    const FrfFileError e("b.uff", 2, 40, "expected a finite value");
    QCOMPARE(std::string(e.what()),
             std::string("b.uff: binary block of the dataset at line 2, byte 40: expected a finite value"));
    QCOMPARE(e.blockOffset().value_or(0), std::size_t(40));
    const std::runtime_error& base = e;  // one type, catchable as a runtime error
    QVERIFY(std::string(base.what()).starts_with("b.uff"));
  }
};

MX_REGISTER_TEST(TestFrfFileError)
#include "test_frf_file_error.moc"

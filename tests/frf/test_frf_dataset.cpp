// Names of the FRF quantities and directions (used in messages and by the CLI).
#include "frf/frf_dataset.h"
#include "test_registry.h"

using namespace mx;

class TestFrfDataset : public QObject {
  Q_OBJECT
 private slots:
  void names() {
    QCOMPARE(frfQuantityName(FrfQuantity::Receptance), std::string_view("receptance"));
    QCOMPARE(frfQuantityName(FrfQuantity::Mobility), std::string_view("mobility"));
    QCOMPARE(frfQuantityName(FrfQuantity::Accelerance), std::string_view("accelerance"));
    QCOMPARE(frfDirectionName(FrfDirection::X), std::string_view("x"));
    QCOMPARE(frfDirectionName(FrfDirection::Y), std::string_view("y"));
    QCOMPARE(frfDirectionName(FrfDirection::Z), std::string_view("z"));
  }
};

MX_REGISTER_TEST(TestFrfDataset)
#include "test_frf_dataset.moc"

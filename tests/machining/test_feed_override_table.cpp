// Feed-override CSV: columns, units (mm/min whatever the program units), quoting, empty cells.
#include <limits>

#include "machining/feed_override_table.h"
#include "test_registry.h"

using namespace mx;

class TestFeedOverrideTable : public QObject {
  Q_OBJECT
 private slots:
  void rows() {
    FeedOverrideRow a;
    a.block = 6;
    a.line = 6;
    a.original_feed_m_per_s = 600e-3 / 60.0;
    a.new_feed_m_per_s = 452.5e-3 / 60.0;
    a.speed_rev_per_s = 25.0;
    a.predicted_force_N = 1199.996;
    a.reason = "force limit, \"SMC I\"";
    FeedOverrideRow b;
    b.block = 3;
    b.line = 3;
    b.new_feed_m_per_s = 30.0 * 0.0254 / 60.0;  // 30 in/min
    const std::string csv = FeedOverrideTable::csv({a, b});
    QCOMPARE(csv, std::string("block,line,original_F_mm_min,new_F_mm_min,S_rpm,reason,predicted_force_N\n"
                              "6,6,600,452.5,1500,\"force limit, \"\"SMC I\"\"\",1200\n"
                              "3,3,,762,,,\n"));
  }
  void emptyTable() { QCOMPARE(FeedOverrideTable::csv({}), FeedOverrideTable::header()); }
};

MX_REGISTER_TEST(TestFeedOverrideTable)
#include "test_feed_override_table.moc"

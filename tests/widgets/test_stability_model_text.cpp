// The stability chart's model label and the ZOA/SDM advice for a tool.
#include <numbers>

#include "stability_model_text.h"
#include "support/test_constants.h"
#include "test_registry.h"

using mx::MillingSetup;
using mx::StabilityMethod;

namespace {

using mx::test::kDeg;

MillingSetup setup(int teeth, double helix_deg, const std::vector<double>& pitch_deg, double immersion) {
  MillingSetup s;
  s.teeth = teeth;
  s.diameter_m = 0.016;
  s.helix_rad = helix_deg * kDeg;
  for (double p : pitch_deg) s.pitch_rad.push_back(p * kDeg);
  s.radial_depth_m = immersion * s.diameter_m;
  s.immersion = mx::Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, mx::MillingDirection::Up);
  return s;
}

}  // namespace

Q_DECLARE_METATYPE(MillingSetup)
Q_DECLARE_METATYPE(StabilityMethod)

class TestStabilityModelText : public QObject {
  Q_OBJECT
 private slots:
  void modelLabel_data() {
    QTest::addColumn<StabilityMethod>("method");
    QTest::addColumn<MillingSetup>("tool");
    QTest::addColumn<QString>("label");
    const auto sdm = StabilityMethod::SemiDiscretization, zoa = StabilityMethod::ZeroOrder;
    QTest::newRow("SDM variable helix") << sdm << setup(4, 30, {70, 110, 70, 110}, 0.5)
                                        << "SDM, 4 teeth, variable pitch, 30\u00b0 helix";
    QTest::newRow("ZOA uniform") << zoa << setup(3, 0, {}, 1.0) << "ZOA, 3 teeth, uniform pitch";
    QTest::newRow("equal list is uniform") << zoa << setup(2, 0, {180, 180}, 1.0) << "ZOA, 2 teeth, uniform pitch";
    QTest::newRow("one tooth, left helix")
        << sdm << setup(1, -12.5, {}, 1.0) << "SDM, 1 tooth, uniform pitch, -12.5\u00b0 helix";
  }
  void modelLabel() {
    QFETCH(StabilityMethod, method);
    QFETCH(MillingSetup, tool);
    QFETCH(QString, label);
    QCOMPARE(mx::widgets::modelLabel(method, tool), label);
  }

  void methodAdvice_data() {
    QTest::addColumn<StabilityMethod>("method");
    QTest::addColumn<MillingSetup>("tool");
    QTest::addColumn<QString>("advice");
    const auto sdm = StabilityMethod::SemiDiscretization, zoa = StabilityMethod::ZeroOrder;
    const QString tail = "; SDM models pitch, helix and process damping";
    QTest::newRow("ZOA fits") << zoa << setup(3, 0, {}, 1.0) << QString();
    QTest::newRow("ZOA at 4 teeth, a/D = 0.5") << zoa << setup(4, 0, {}, 0.5) << QString();  // always a tooth in cut
    QTest::newRow("ZOA variable pitch") << zoa << setup(4, 0, {70, 110, 70, 110}, 1.0)
                                        << "ZOA: approximate for this tool (variable pitch)" + tail;
    QTest::newRow("ZOA helix") << zoa << setup(3, 30, {}, 1.0)
                               << "ZOA: approximate for this tool (30\u00b0 helix)" + tail;
    QTest::newRow("ZOA intermittent") << zoa << setup(3, 0, {}, 0.5)
                                      << "ZOA: approximate for this tool (intermittent cut: a/D = 0.5 < 0.75)" + tail;
    QTest::newRow("ZOA all three") << zoa << setup(4, 30, {85, 95, 85, 95}, 0.05)
                                   << "ZOA: approximate for this tool (variable pitch, 30\u00b0 helix)" + tail;
    MillingSetup damped = setup(3, 0, {}, 1.0);
    damped.process_damping_n_per_m = 1e5;
    QTest::newRow("ZOA process damping")
        << zoa << damped << "ZOA: approximate for this tool (process damping C_i = 1e+05 N/m left out)" + tail;
    QTest::newRow("SDM process damping") << sdm << damped << QString();
    QTest::newRow("SDM variable helix") << sdm << setup(4, 30, {70, 110, 70, 110}, 0.05) << QString();
  }
  void methodAdvice() {
    QFETCH(StabilityMethod, method);
    QFETCH(MillingSetup, tool);
    QFETCH(QString, advice);
    QCOMPARE(mx::widgets::methodAdvice(method, tool), advice);
  }
};

MX_REGISTER_TEST(TestStabilityModelText)
#include "test_stability_model_text.moc"

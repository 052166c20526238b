// The check of every JSON output: a non-finite number anywhere, or a null outside the documented
// "no value" keys, is a failed computation that names its JSON path; everything else passes.
#include <limits>

#include "services/json_output.h"
#include "services/service_errors.h"
#include "test_registry.h"

using namespace mx::app;

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The error message of checkJsonOutput, or "" when it passes.
QString checkMessage(const QJsonObject& object) {
  try {
    checkJsonOutput(object);
  } catch (const ComputationError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace

class TestJsonOutput : public QObject {
  Q_OBJECT

 private slots:
  void outputs_data() {
    QTest::addColumn<QJsonObject>("object");
    QTest::addColumn<QString>("message");
    QTest::newRow("finite numbers") << QJsonObject{{"a", 1.5}, {"b", QJsonArray{0.0, -1e300}}} << QString();
    QTest::newRow("nan at the top") << QJsonObject{{"peak_power_W", kNan}}
                                    << "peak_power_W = nan: the computation gave no finite value";
    QTest::newRow("inf deep in an array")
        << QJsonObject{{"ranking", QJsonArray{QJsonObject{{"C", 1.0}}, QJsonObject{{"C", kInf}}}}}
        << "ranking[1].C = inf: the computation gave no finite value";
    QTest::newRow("-inf in a nested object")
        << QJsonObject{{"q", QJsonObject{{"mrr", -kInf}}}} << "q.mrr = -inf: the computation gave no finite value";
    QTest::newRow("undocumented null") << QJsonObject{{"peak_power_W", QJsonValue()}}
                                       << "peak_power_W = null: the computation gave no value";
    QTest::newRow("documented null") << QJsonObject{{"blim_mm", QJsonValue()}, {"q_star_star", QJsonValue()}}
                                     << QString();
    QTest::newRow("nulls in a documented array")
        << QJsonObject{{"blim_mm", QJsonArray{1.0, QJsonValue(), 2.0}}} << QString();
    QTest::newRow("null member of a documented object")
        << QJsonObject{{"points", QJsonArray{QJsonObject{{"min_cost", QJsonObject{{"R1", QJsonValue()}}}}}}}
        << QString();
    QTest::newRow("nan stays an error under a documented key")
        << QJsonObject{{"blim_mm", QJsonArray{1.0, kNan}}} << "blim_mm[1] = nan: the computation gave no finite value";
  }
  void outputs() {
    QFETCH(QJsonObject, object);
    QFETCH(QString, message);
    QCOMPARE(checkMessage(object), message);
  }

  void numberOrNullIsOnlyNullWhenNotFinite() {
    QCOMPARE(jsonNumberOrNull(2.5), QJsonValue(2.5));
    QVERIFY(jsonNumberOrNull(kNan).isNull());
    QVERIFY(jsonNumberOrNull(-kInf).isNull());
  }
};

MX_REGISTER_TEST(TestJsonOutput)
#include "test_json_output.moc"

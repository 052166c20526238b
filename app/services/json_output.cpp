#include "services/json_output.h"

#include <QJsonArray>

#include "services/service_errors.h"

namespace mx::app {
namespace {

void checkValue(const QJsonValue& value, const QString& path, bool nullAllowed);

void checkObject(const QJsonObject& object, const QString& path, bool nullAllowed) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    const QString child = path.isEmpty() ? it.key() : path + "." + it.key();
    checkValue(it.value(), child, nullAllowed || documentedNullKeys().contains(it.key()));
  }
}

void checkValue(const QJsonValue& value, const QString& path, bool nullAllowed) {
  if (value.isDouble() && !std::isfinite(value.toDouble()))
    throw ComputationError(
        QString("%1 = %2: the computation gave no finite value").arg(path, QString::number(value.toDouble())));
  if (value.isNull() && !nullAllowed)
    throw ComputationError(QString("%1 = null: the computation gave no value").arg(path));
  if (value.isObject()) checkObject(value.toObject(), path, nullAllowed);
  if (value.isArray()) {
    const QJsonArray array = value.toArray();
    for (qsizetype i = 0; i < array.size(); ++i)
      checkValue(array.at(i), QString("%1[%2]").arg(path).arg(i), nullAllowed);
  }
}

}  // namespace

const QSet<QString>& documentedNullKeys() {
  static const QSet<QString> keys{
      "blim_mm",                // lobes, point: no instability below --max-depth
      "chatter_frequency_Hz",   // lobes, simulate, pareto: no chatter
      "ROS",                    // point: outside the lobes' robustness measure
      "ros",                    // pareto: no speed security at the point
      "machine",                // history: the record names no machine
      "q_star_star",            // rank: Rule 5 found no better point
      "rule5",                  // rank: Rule 5 did not run
      "max_force_N",            // rank, point: the tool has no force limit
      "Jc",                     // control --sweep-beta: the run at that beta diverged
      "best_beta",              // control --sweep-beta: no stable beta
      "best_Jc",                //   ... and its cost
      "hi",                     // pareto: a requirement without an upper bound
      "gilbert_tool_life_min",  // pareto: no Gilbert optimum for the objective
      "min_cost",               // weights-sweep: a tool excluded by the rules
      "freq_Hz",                // a chatter report without a frequency
      "suggested_speed_rpm",    // pareto --feedback, simulate: no speed to suggest
      "k",                      //   ... and its lobe number
      "reselected",             // pareto --feedback: no re-selection
      "csv",                    // override: no --csv given
      "tool_table",             // override --afc: no --afc-tool given
      "chatter_time_s",         // supervise: no chatter detected
      "settling_s",             // supervise: a force transient that never settles
      "followed",               // pareto: message-only advice has no bound to follow
  };
  return keys;
}

void checkJsonOutput(const QJsonObject& object) {
  checkObject(object, QString(), false);
}

}  // namespace mx::app

#include "services/learning_record.h"

#include <QJsonArray>
#include <array>
#include <cmath>
#include <stdexcept>

#include "document/shortened_text.h"

namespace mx::app {

namespace {

constexpr std::array<std::pair<LearningSource, const char*>, 4> kSources{{
    {LearningSource::Operator, "operator"},
    {LearningSource::Automatic, "automatic"},
    {LearningSource::Rule, "rule"},
    {LearningSource::Feedback, "feedback"},
}};

void require(bool condition, const QString& message) {
  if (!condition) throw std::invalid_argument(message.toStdString());
}

bool positive(double value) {
  return std::isfinite(value) && value > 0.0;
}

}  // namespace

QString learningSourceName(LearningSource source) {
  for (const auto& [value, name] : kSources)
    if (value == source) return QString::fromLatin1(name);
  return QStringLiteral("operator");
}

LearningSource parseLearningSource(const QString& name) {
  for (const auto& [value, text] : kSources)
    if (name == QLatin1String(text)) return value;
  throw std::invalid_argument(
      QString("source %1: must be one of operator, automatic, rule, feedback").arg(quoted(name)).toStdString());
}

void validateLearningRecord(const LearningRecord& r) {
  require(!r.weights.empty(), "weights: at least one weight is required");
  double sum = 0.0;
  for (std::size_t i = 0; i < r.weights.size(); ++i) {
    require(std::isfinite(r.weights[i]) && r.weights[i] >= 0.0,
            QString("weights[%1] = %2: must be finite and >= 0").arg(i).arg(r.weights[i]));
    sum += r.weights[i];
  }
  require(std::abs(sum - 1.0) <= 1e-6, QString("weights: sum %1, must sum to 1").arg(sum, 0, 'g', 12));
  require(!r.tool.id.isEmpty(), "tool.id: must not be empty");
  require(positive(r.tool.diameter_mm), QString("tool.diameter_mm = %1: must be > 0").arg(r.tool.diameter_mm));
  require(r.tool.teeth >= 1, QString("tool.teeth = %1: must be >= 1").arg(r.tool.teeth));
  require(!r.material.isEmpty(), "material: must not be empty");
  require(!r.machine.name || !r.machine.name->isEmpty(), "machine.name: must not be empty when given");
  require(std::isfinite(r.machine.spindle_power_W) && r.machine.spindle_power_W >= 0.0,
          QString("machine.spindle_power_W = %1: must be >= 0").arg(r.machine.spindle_power_W));
  require(!r.machine.max_spindle_rpm || positive(*r.machine.max_spindle_rpm),
          "machine.max_spindle_rpm: must be > 0 when given");
  require(positive(r.q.speed_rpm), QString("q.speed_rpm = %1: must be > 0").arg(r.q.speed_rpm));
  require(positive(r.q.depth_mm), QString("q.depth_mm = %1: must be > 0").arg(r.q.depth_mm));
  require(positive(r.q.feed_mm_per_tooth), QString("q.feed_mm_per_tooth = %1: must be > 0").arg(r.q.feed_mm_per_tooth));
  for (auto it = r.objectives.begin(); it != r.objectives.end(); ++it)
    require(it.value().isDouble() || it.value().isNull(),
            QString("objectives.%1: must be a number or null").arg(it.key()));
}

QJsonObject learningEntryJson(const LearningRecord& r) {
  QJsonArray weights;
  for (double w : r.weights) weights.append(w);
  return {{"time", learningTimeText(r.time)},
          {"tool", r.tool.id},
          {"material", r.material},
          {"machine", r.machine.name ? QJsonValue(*r.machine.name) : QJsonValue(QJsonValue::Null)},
          {"weights", weights},
          {"q",
           QJsonObject{
               {"speed_rpm", r.q.speed_rpm}, {"depth_mm", r.q.depth_mm}, {"feed_mm_per_tooth", r.q.feed_mm_per_tooth}}},
          {"objectives", r.objectives},
          {"source", learningSourceName(r.source)}};
}

QString learningTimeText(const QDateTime& time) {
  return time.toUTC().toString(Qt::ISODateWithMs);
}

}  // namespace mx::app

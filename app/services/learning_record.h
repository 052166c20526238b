#pragma once
// One programmed point of the Rule 14 learning database (Rubio et al., Pareto expert system): the
// weights that produced it, the job (tool, material, machine), the chosen point q, every objective
// term and who chose it. Plain data; LearningDatabase stores and queries it.
#include <QDateTime>
#include <QJsonObject>
#include <QString>
#include <optional>
#include <vector>

namespace mx::app {

// Who programmed the point: the operator's weights (Rule 8), automatic weight modulation (Rules
// 11-13), an operator rule (Rule 18) or the chatter feedback loop (module VI).
enum class LearningSource { Operator, Automatic, Rule, Feedback };

QString learningSourceName(LearningSource source);  // "operator", "automatic", "rule", "feedback"
// Throws std::invalid_argument listing the allowed names for anything else.
LearningSource parseLearningSource(const QString& name);

struct LearningTool {
  QString id;
  double diameter_mm = 0.0;
  int teeth = 0;
};

struct LearningMachine {
  std::optional<QString> name;  // the project's machine.name: which machine of the shop wrote it
  double spindle_power_W = 0.0;
  std::optional<double> max_spindle_rpm;  // no limit when absent
};

struct LearningPoint {
  double speed_rpm = 0.0;
  double depth_mm = 0.0;
  double feed_mm_per_tooth = 0.0;
};

struct LearningRecord {
  qint64 id = 0;                // assigned by the database
  QString uid;                  // unique over every database; a new UUID when left empty at insertion
  QDateTime time;               // UTC; "now" when left invalid at insertion
  std::vector<double> weights;  // on the simplex (>= 0, sum 1)
  LearningTool tool;
  QString material;
  LearningMachine machine;
  LearningPoint q;
  // Objective terms, name -> number (or null), e.g. {"tol", "mrr_cm3_s", "surf", "ros", "eta",
  // "power_W"}. "mrr_cm3_s" also feeds the indexed MRR column.
  QJsonObject objectives;
  LearningSource source = LearningSource::Operator;
};

// Throws std::invalid_argument naming the first bad field (weights off the simplex, empty tool or
// material, non-positive diameter/teeth/speed/depth/feed, a non-numeric objective term).
void validateLearningRecord(const LearningRecord& record);

// The CLI `history` entry: {"time","tool","material","machine","weights","q","objectives","source"};
// "machine" is null when the record names none.
QJsonObject learningEntryJson(const LearningRecord& record);

// UTC ISO 8601 with milliseconds ("2024-05-01T08:30:00.125Z"): sorts lexicographically by time.
QString learningTimeText(const QDateTime& time);

}  // namespace mx::app

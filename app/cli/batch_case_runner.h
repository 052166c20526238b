#pragma once
// One batch case computed in this process by the single command's own code (cli_computations.h), so
// that a results line's "result" is exactly what `millexpert-cli COMPUTATION` prints for the case.
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>

#include "document/project.h"

namespace mx::app {

struct BatchCaseOutcome {
  std::optional<QJsonObject> result;  // the command's JSON; absent when it failed before printing
  std::optional<QJsonObject> error;   // {"exit_code", "message"}: what the command would exit with
};

class BatchCaseRunner {
 public:
  // Turns the manifest's options into the command's flags and parses them once; throws CliError(2)
  // naming an option the command does not have, one the batch sets itself, or a value it refuses.
  BatchCaseRunner(const QString& computation, const QJsonObject& options);
  // Never throws: a failure becomes the outcome's error.
  BatchCaseOutcome run(const Project& project, const QString& tool) const;
  const QStringList& flags() const { return flags_; }

 private:
  QJsonObject compute(const Project& project, const QString& tool, BatchCaseOutcome& outcome) const;
  QString computation_;
  QStringList flags_;
};

}  // namespace mx::app

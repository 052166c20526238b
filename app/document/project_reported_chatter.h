#pragma once
// expert.reported_chatter and expert.max_malfunction_iterations: the parser's, the validator's and the
// writer's part (internal to app/document).
#include <QJsonObject>

#include "document/json_reader.h"
#include "document/project.h"

namespace mx::app {

void readReportedChatter(const ObjectReader& expert, ExpertSpec& spec);
// Ranges, and every report's tool must be a tool of the project.
void validateReportedChatter(const ExpertSpec& spec, const std::vector<ToolSpec>& tools);
void putReportedChatter(QJsonObject& expert, const ExpertSpec& spec);

}  // namespace mx::app

#pragma once
// Chatter observed at the machine, from the project (expert.reported_chatter) or the command line
// (rank --chatter-at SPEED:DEPTH[:FREQ_HZ], rpm, mm, Hz), as evidence for Rule 6 of the 2006 expert
// system (expert/reported_chatter.h), and the words for a loop that stopped at its bound.
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <vector>

#include "document/project.h"
#include "expert/expert_session.h"

namespace mx::app {

// "5800:0.5" or "5800:0.5:640" for `tool`; InputError naming --chatter-at, the text and the form or range.
ChatterReportSpec parseChatterAt(const QString& text, const QString& tool);

// Engine form, tools by their index in `tool_ids`; ProjectError naming the report for an unknown tool.
std::vector<ChatterReport> engineChatterReports(const std::vector<ChatterReportSpec>& reports,
                                                const QStringList& tool_ids);

// {"tool", "speed_rpm", "depth_mm", "freq_Hz" (null when not given), "region": {"speed_from_rpm",
// "speed_to_rpm", "depth_from_mm"}, "holds_chosen_point"} for the result's chosen point.
QJsonObject reportedChatterJson(const ChatterReportSpec& report, const ExpertResult& result,
                                const QStringList& tool_ids);

// Why Rule 6 stopped at its bound with the chosen point still in a reported region (empty when it
// did not): the bound, the report, the point and the final weights.
QString unresolvedChatterMessage(const ExpertResult& result, const std::vector<ChatterReportSpec>& reports,
                                 const QStringList& tool_ids, int bound);

}  // namespace mx::app

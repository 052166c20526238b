#pragma once
// The JSON-building part of the single commands that `batch` runs in-process: each takes the parsed
// flags and a loaded project and returns exactly the object the command prints, so that a batch
// line's "result" and the single command's output cannot drift apart.
#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QJsonObject>
#include <QList>
#include <optional>
#include <vector>

#include "document/project.h"

namespace mx::app {

QList<QCommandLineOption> lobesOptions();
QJsonObject lobesJson(const QCommandLineParser& parser, const Project& project);

QList<QCommandLineOption> pointOptions();
// --method, checked: zoa or sdm (CliError(2) otherwise).
QString pointMethod(const QCommandLineParser& parser);
QJsonObject pointJson(const QCommandLineParser& parser, const Project& project);

QList<QCommandLineOption> rankOptions();
struct RankWeightFlags {
  std::optional<std::vector<double>> c;
  std::optional<std::vector<double>> cr;
};
// --c and --cr, checked on the simplex (CliError(2) otherwise).
RankWeightFlags readRankWeights(const QCommandLineParser& parser);
struct RankOutput {
  QJsonObject json;
  QString unresolved_chatter;  // non-empty: Rule 6 stopped with the point in a reported region (exit 1)
};
RankOutput rankJson(const QCommandLineParser& parser, const Project& project);

}  // namespace mx::app

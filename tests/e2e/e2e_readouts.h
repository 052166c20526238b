#pragma once
// Comparisons of what the window shows: the operating-point readout (the struct behind the panel and
// the panel's rounded text) against another window's or the CLI's numbers, and the ranking table's
// rows against `millexpert-cli rank`.
#include <QHash>
#include <QJsonObject>
#include <QString>
#include <QVector>

#include "e2e_report.h"
#include "point_readout.h"
#include "ranking_table.h"

namespace mx::e2e {

// The readout panel's fields (OperatingPointReadout::text keys).
inline const QStringList kReadoutFields = {"verdict",        "tool",  "speed",          "depth", "feed", "power", "mrr",
                                           "power_fraction", "force", "force_fraction", "blim",  "dns",  "ros"};

// Every field of two readouts of the same point; `prefix` names the checks.
void compareReadouts(Report& report, const QString& prefix, const widgets::PointReadout& actual,
                     const widgets::PointReadout& expected);

// The number at the start of a shown text ("576.8 W" -> 576.8) and half a unit of its last digit.
struct ShownNumber {
  double value = 0.0;
  double half_unit = 0.0;
  bool ok = false;
};
ShownNumber shownNumber(const QString& text);

// The readout of a point against `millexpert-cli point` (its JSON) on the same file and point.
void compareWithCliPoint(Report& report, const widgets::PointReadout& readout, const QHash<QString, QString>& shown,
                         const QJsonObject& cli);

// The ranking table's rows against the "ranking" of `millexpert-cli rank`.
void compareWithCliRanking(Report& report, const QString& prefix, const QVector<widgets::RankingRow>& rows,
                           const QString& selected, const QJsonObject& cli);

// Two ranking tables row by row (tool, C, q*).
void compareRankings(Report& report, const QString& prefix, const QVector<widgets::RankingRow>& actual,
                     const QVector<widgets::RankingRow>& expected);

}  // namespace mx::e2e

#pragma once
// The live tool ranking of the 2006 expert system (Rule 4): one row per tool with an admissible point,
// best first, with its minimum tool cost C (eq. 13), the three weighted terms, its cost-minimising
// point q* and the power / MRR / Delta N_s there, and (once simulated, Rule 5) C_t, C_f and
// C_resultant (NaN = unknown, shown as an em dash). The rows are shown in the order given (rank
// 1..n); the selected tool (Rule 4's choice) is bold with a check mark. A click on a row emits
// toolActivated(); the clicked row stays selected across setRanking() while its tool is listed.
// Lengths follow the DisplayUnits (mm or inch); an update of 20 rows costs well under 1 ms.
#include <QString>
#include <QStringList>
#include <QVector>
#include <QWidget>
#include <limits>

#include "display_units.h"

class QLabel;
class QTableView;

namespace mx {
struct Ranking;
struct RefinementCandidate;
}  // namespace mx

namespace mx::widgets {

class RankingTableModel;

struct RankingRow {
  static constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

  QString tool;             // tool id
  double min_cost = 0.0;    // C at q* (eq. 13)
  double power_term = 0.0;  // c1 P / P_av
  double mrr_term = 0.0;    // c2 MRR_max / MRR
  double dns_term = 0.0;    // c3 Delta N_s,max / Delta N_s
  double speed_rpm = 0.0;   // q*
  double depth_mm = 0.0;
  double feed_mm_per_tooth = 0.0;
  double power_w = 0.0;              // peak cutting power at q*
  double mrr_mm3_min = 0.0;          // MRR at q* [mm^3/min]
  double dns_rpm = 0.0;              // Delta N_s at q* [rpm]
  double time_cost = kUnknown;       // C_t at q** (eq. 18)
  double frequency_cost = kUnknown;  // C_f at q** (eq. 19)
  double resultant_cost = kUnknown;  // C_resultant at q** (eq. 20)
};

class RankingTable : public QWidget {
  Q_OBJECT
 public:
  explicit RankingTable(QWidget* parent = nullptr);

  // rows best first; selected_tool is marked (empty: none). Clears a stale mark.
  void setRanking(const QVector<RankingRow>& rows, const QString& selected_tool);
  // The shown ranking is of an earlier project: greyed, with the reason above it, until the next ranking.
  void setStale(const QString& reason);
  bool isStale() const;
  const QVector<RankingRow>& rows() const;
  QString selectedTool() const;
  QString currentTool() const { return current_; }  // the clicked row's tool ("" if none)
  void setUnits(DisplayUnits* units);

  // Rows of an engine ranking (best first), tool ids by tool index; q** columns unknown.
  static QVector<RankingRow> rowsFromRanking(const mx::Ranking& ranking, const QStringList& tool_ids);
  // Fills C_t, C_f and C_resultant of `tool`'s row from the chosen refinement candidate (q**).
  static void applyRefinement(QVector<RankingRow>& rows, const QString& tool, const mx::RefinementCandidate& chosen);

  QTableView* view() const { return view_; }
  RankingTableModel* model() const { return model_; }

 signals:
  void toolActivated(const QString& id);

 private:
  void onClicked(int row);
  void restoreCurrent();

  RankingTableModel* model_;
  QTableView* view_;
  QLabel* stale_;
  QString current_;
};

}  // namespace mx::widgets

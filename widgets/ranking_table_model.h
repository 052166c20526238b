#pragma once
// Table model of the RankingTable: one row per RankingRow, in the given (rank) order. Display text
// with units in the headers, the glossary's What's This on the q*, q** and ΔN_s columns, raw values
// under ValueRole, the selected tool bold with a check mark.
// setRanking() with the same tools in the same order only emits dataChanged; the same tools in another
// order are a layout change (persistent indexes follow their tool, so views keep their selection);
// a different set of tools resets the model.
#include <QAbstractTableModel>
#include <QIcon>
#include <QPointer>
#include <QVector>
#include <optional>

#include "display_units.h"
#include "glossary.h"
#include "ranking_table.h"

namespace mx::widgets {

class RankingTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column {
    Rank,
    Tool,
    MinCost,
    PowerTerm,
    MrrTerm,
    DnsTerm,
    Speed,
    Depth,
    Feed,
    Power,
    Mrr,
    Dns,
    TimeCost,
    FrequencyCost,
    ResultantCost,
    ColumnCount
  };
  static constexpr int ValueRole = Qt::UserRole + 1;     // the raw value (double; rank int; tool QString)
  static constexpr int SelectedRole = Qt::UserRole + 2;  // bool: the row of the selected tool

  explicit RankingTableModel(QObject* parent = nullptr);

  void setRanking(const QVector<RankingRow>& rows, const QString& selected_tool);
  const QVector<RankingRow>& rows() const { return rows_; }
  const QString& selectedTool() const { return selected_; }
  int rowOf(const QString& tool) const;  // -1 if absent
  void setUnits(DisplayUnits* units);

  int rowCount(const QModelIndex& parent = {}) const override { return parent.isValid() ? 0 : int(rows_.size()); }
  int columnCount(const QModelIndex& parent = {}) const override { return parent.isValid() ? 0 : ColumnCount; }
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;

 private:
  double value(const RankingRow& row, int column) const;  // in display units
  static std::optional<Quantity> quantity(int column);
  static std::optional<Term> columnTerm(int column);
  QString text(const RankingRow& row, int column) const;
  void unitsChanged();

  QVector<RankingRow> rows_;
  QString selected_;
  QPointer<DisplayUnits> units_;
  QIcon mark_;
};

}  // namespace mx::widgets

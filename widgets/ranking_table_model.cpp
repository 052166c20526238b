#include "ranking_table_model.h"

#include <QFont>
#include <QPainter>
#include <QPixmap>
#include <cmath>

namespace mx::widgets {

namespace {

constexpr const char* kDash = "\u2014";

// A green check mark, drawn once (no style or resource dependency).
QIcon checkMark() {
  QPixmap pixmap(16, 16);
  pixmap.fill(Qt::transparent);
  QPainter p(&pixmap);
  p.setRenderHint(QPainter::Antialiasing);
  p.setPen(QPen(QColor(30, 150, 30), 2.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  p.drawPolyline(QPolygonF({QPointF(3, 8.5), QPointF(6.5, 12), QPointF(13, 4)}));
  return QIcon(pixmap);
}

}  // namespace

RankingTableModel::RankingTableModel(QObject* parent) : QAbstractTableModel(parent), mark_(checkMark()) {}

int RankingTableModel::rowOf(const QString& tool) const {
  for (qsizetype i = 0; i < rows_.size(); ++i)
    if (rows_[i].tool == tool) return int(i);
  return -1;
}

void RankingTableModel::setRanking(const QVector<RankingRow>& rows, const QString& selected_tool) {
  bool sameTools = rows.size() == rows_.size();
  for (qsizetype i = 0; sameTools && i < rows.size(); ++i) sameTools = rows[i].tool == rows_[i].tool;
  if (sameTools) {
    rows_ = rows;
    selected_ = selected_tool;
    if (!rows_.isEmpty()) emit dataChanged(index(0, 0), index(int(rows_.size()) - 1, ColumnCount - 1));
    return;
  }
  // The same tools in a new order (a re-rank): a layout change that moves the persistent indexes, so
  // that views keep their selection and current row without a reset.
  QVector<int> newRow(rows_.size(), -1);
  bool permutation = rows.size() == rows_.size();
  for (qsizetype i = 0; permutation && i < rows_.size(); ++i) {
    for (qsizetype j = 0; j < rows.size(); ++j)
      if (rows[j].tool == rows_[i].tool) newRow[i] = int(j);
    permutation = newRow[i] >= 0;
  }
  if (permutation) {
    emit layoutAboutToBeChanged({}, QAbstractItemModel::VerticalSortHint);
    const QModelIndexList from = persistentIndexList();
    QModelIndexList to;
    to.reserve(from.size());
    for (const QModelIndex& index : from) to.push_back(this->index(newRow[index.row()], index.column()));
    rows_ = rows;
    selected_ = selected_tool;
    changePersistentIndexList(from, to);
    emit layoutChanged({}, QAbstractItemModel::VerticalSortHint);
    return;
  }
  beginResetModel();
  rows_ = rows;
  selected_ = selected_tool;
  endResetModel();
}

void RankingTableModel::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &RankingTableModel::unitsChanged);
}

void RankingTableModel::unitsChanged() {
  emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
  if (!rows_.isEmpty()) emit dataChanged(index(0, 0), index(int(rows_.size()) - 1, ColumnCount - 1));
}

double RankingTableModel::value(const RankingRow& r, int column) const {
  const ShopUnits& units = DisplayUnits::of(units_);
  switch (column) {
    case MinCost:
      return r.min_cost;
    case PowerTerm:
      return r.power_term;
    case MrrTerm:
      return r.mrr_term;
    case DnsTerm:
      return r.dns_term;
    case Speed:
      return r.speed_rpm;
    case Depth:
      return units.fromBase(Quantity::Length, r.depth_mm);
    case Feed:
      return units.fromBase(Quantity::ChipLoad, r.feed_mm_per_tooth);
    case Power:
      return units.fromBase(Quantity::Power, r.power_w);
    case Mrr:
      return units.fromBase(Quantity::RemovalRate, r.mrr_mm3_min / 1000.0);
    case Dns:
      return r.dns_rpm;
    case TimeCost:
      return r.time_cost;
    case FrequencyCost:
      return r.frequency_cost;
    case ResultantCost:
      return r.resultant_cost;
    default:
      return RankingRow::kUnknown;
  }
}

// The shop-unit quantity of a column, if it has one.
std::optional<Quantity> RankingTableModel::quantity(int column) {
  switch (column) {
    case Depth:
      return Quantity::Length;
    case Feed:
      return Quantity::ChipLoad;
    case Power:
      return Quantity::Power;
    case Mrr:
      return Quantity::RemovalRate;
    default:
      return std::nullopt;
  }
}

QString RankingTableModel::text(const RankingRow& r, int column) const {
  const double v = value(r, column);
  if (!std::isfinite(v)) return QString::fromUtf8(kDash);
  if (const std::optional<Quantity> q = quantity(column)) {
    const int decimals = DisplayUnits::of(units_).decimals(*q);
    return QString::number(v, 'f', *q == Quantity::RemovalRate ? ShopUnits::readableDecimals(v, decimals) : decimals);
  }
  if (column == Speed || column == Dns) return QString::number(v, 'f', 0);
  return QString::number(v, 'f', 4);
}

QVariant RankingTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rows_.size()) return {};
  const RankingRow& r = rows_[index.row()];
  const int column = index.column();
  const bool selected = !selected_.isEmpty() && r.tool == selected_;
  switch (role) {
    case Qt::DisplayRole:
      if (column == Rank) return index.row() + 1;
      if (column == Tool) return r.tool;
      return text(r, column);
    case ValueRole:
      if (column == Rank) return index.row() + 1;
      if (column == Tool) return r.tool;
      return value(r, column);
    case SelectedRole:
      return selected;
    case Qt::FontRole:
      if (selected) {
        QFont font;
        font.setBold(true);
        return font;
      }
      return {};
    case Qt::DecorationRole:
      return selected && column == Tool ? QVariant(mark_) : QVariant();
    case Qt::TextAlignmentRole:
      return QVariant::fromValue(column == Tool ? Qt::AlignLeft | Qt::AlignVCenter : Qt::AlignRight | Qt::AlignVCenter);
    case Qt::ToolTipRole:
      if (selected)
        return tr("%1: the selected tool (Rule 4: lowest minimum cost C). Click to show its lobes.").arg(r.tool);
      return tr("%1: rank %2. Click to show its lobes.").arg(r.tool).arg(index.row() + 1);
    default:
      return {};
  }
}

QVariant RankingTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal) return role == Qt::DisplayRole ? QVariant(section + 1) : QVariant();
  const ShopUnits& units = DisplayUnits::of(units_);
  const QString u = units.symbol(Quantity::Length);
  struct Header {
    QString title;
    QString tip;
  };
  auto header = [&]() -> Header {
    switch (section) {
      case Rank:
        return {tr("Rank"),
                tr("Rule 4: tools by increasing minimum cost C (ties: higher MRR, lower power, lower speed)")};
      case Tool:
        return {tr("Tool"), tr("Tool id; the check mark is the selected tool")};
      case MinCost:
        return {tr("min C [\u2013]"), tr("Minimum tool cost C over the admissible space (eq. 13); lower is better")};
      case PowerTerm:
        return {tr("c1\u00b7P/P_av [\u2013]"), tr("Power term of C at q*: c1 P / P_av")};
      case MrrTerm:
        return {tr("c2\u00b7MRR_max/MRR [\u2013]"), tr("MRR term of C at q*: c2 MRR_max / MRR")};
      case DnsTerm:
        return {tr("c3\u00b7\u0394N_s,max/\u0394N_s [\u2013]"),
                tr("Speed security term of C at q*: c3 \u0394N_s,max / \u0394N_s")};
      case Speed:
        return {tr("N* [rpm]"), tr("Spindle speed of q*, the tool's cost-minimising point")};
      case Depth:
        return {tr("b* [%1]").arg(u), tr("Axial depth of cut of q*")};
      case Feed:
        return {tr("s_t* [%1]").arg(units.symbol(Quantity::ChipLoad)), tr("Feed per tooth of q*")};
      case Power:
        return {tr("P [%1]").arg(units.symbol(Quantity::Power)), tr("Peak cutting power at q*")};
      case Mrr:
        return {tr("MRR [%1]").arg(units.symbol(Quantity::RemovalRate)), tr("Material removal rate at q*")};
      case Dns:
        return {tr("\u0394N_s [rpm]"), tr("Spindle speed security change at q*: distance in speed to the lobes")};
      case TimeCost:
        return {tr("C_t [\u2013]"), tr("Time-response cost at q** (eq. 18); \u2014 until simulated")};
      case FrequencyCost:
        return {tr("C_f [\u2013]"), tr("Spectrum cost at q** (eq. 19); \u2014 until simulated")};
      case ResultantCost:
        return {tr("C_resultant [\u2013]"), tr("Resultant cost at q** (eq. 20); \u2014 until simulated")};
      default:
        return {};
    }
  };
  if (role == Qt::DisplayRole) return header().title;
  if (role == Qt::ToolTipRole) return header().tip;
  if (role == Qt::WhatsThisRole) return columnTerm(section) ? glossaryText(*columnTerm(section)) : QVariant();
  return {};
}

// The glossary term a column shows (What's This, Shift+F1): q*'s coordinates, q**'s costs, ΔN_s.
std::optional<Term> RankingTableModel::columnTerm(int column) {
  switch (column) {
    case Speed:
    case Depth:
    case Feed:
      return Term::QStar;
    case DnsTerm:
    case Dns:
      return Term::DeltaNs;
    case TimeCost:
    case FrequencyCost:
    case ResultantCost:
      return Term::QStarStar;
    default:
      return std::nullopt;
  }
}

Qt::ItemFlags RankingTableModel::flags(const QModelIndex& index) const {
  return index.isValid() ? Qt::ItemIsEnabled | Qt::ItemIsSelectable : Qt::NoItemFlags;
}

}  // namespace mx::widgets

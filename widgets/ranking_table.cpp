#include "ranking_table.h"

#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QTableView>
#include <QVBoxLayout>

#include "expert/expert_session.h"
#include "glossary.h"
#include "model/milling_setup.h"
#include "ranking_table_model.h"

namespace mx::widgets {

RankingTable::RankingTable(QWidget* parent)
    : QWidget(parent), model_(new RankingTableModel(this)), view_(new QTableView(this)), stale_(new QLabel(this)) {
  view_->setObjectName("ranking_view");
  view_->setModel(model_);
  view_->setSortingEnabled(false);  // the order is the rank
  view_->setSelectionBehavior(QAbstractItemView::SelectRows);
  view_->setSelectionMode(QAbstractItemView::SingleSelection);
  view_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  view_->setAlternatingRowColors(true);
  view_->verticalHeader()->hide();
  view_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  view_->horizontalHeader()->setStretchLastSection(true);
  view_->setToolTip(tr("Tool ranking by minimum tool cost C (Rule 4), best first. Click a tool to show its lobes."));
  setToolTip(view_->toolTip());
  // What's This on the table as a whole; each header has its own (RankingTableModel, Qt::WhatsThisRole).
  view_->setWhatsThis(glossaryText(Term::QStar) + "\n\n" + glossaryText(Term::QStarStar));
  setWhatsThis(view_->whatsThis());
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  stale_->setObjectName("ranking_stale");
  stale_->setStyleSheet("color: #8a5a00;");
  stale_->hide();
  layout->addWidget(stale_);
  layout->addWidget(view_);
  connect(view_, &QTableView::clicked, this, [this](const QModelIndex& index) { onClicked(index.row()); });
  connect(view_, &QTableView::activated, this, [this](const QModelIndex& index) { onClicked(index.row()); });
  connect(model_, &QAbstractItemModel::modelReset, this, &RankingTable::restoreCurrent);
}

void RankingTable::setRanking(const QVector<RankingRow>& rows, const QString& selected_tool) {
  stale_->hide();
  view_->setEnabled(true);
  model_->setRanking(rows, selected_tool);
}

bool RankingTable::isStale() const {
  return !stale_->isHidden();
}

void RankingTable::setStale(const QString& reason) {
  stale_->setText(tr("Stale: %1").arg(reason));
  stale_->show();
  view_->setEnabled(false);
}

const QVector<RankingRow>& RankingTable::rows() const {
  return model_->rows();
}

QString RankingTable::selectedTool() const {
  return model_->selectedTool();
}

void RankingTable::setUnits(DisplayUnits* units) {
  model_->setUnits(units);
}

void RankingTable::onClicked(int row) {
  if (row < 0 || row >= model_->rows().size()) return;
  current_ = model_->rows()[row].tool;
  emit toolActivated(current_);
}

void RankingTable::restoreCurrent() {
  const int row = current_.isEmpty() ? -1 : model_->rowOf(current_);
  if (row < 0) {
    current_.clear();
    return;
  }
  const QModelIndex index = model_->index(row, 0);
  // select() only: setting the current index would scroll to it and force a relayout.
  view_->selectionModel()->select(index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
}

QVector<RankingRow> RankingTable::rowsFromRanking(const Ranking& ranking, const QStringList& tool_ids) {
  QVector<RankingRow> rows;
  rows.reserve(qsizetype(ranking.tools.size()));
  for (const ToolChoice& t : ranking.tools) {
    RankingRow r;
    const auto i = qsizetype(t.tool);
    r.tool = i < tool_ids.size() ? tool_ids[i] : QString("#%1").arg(i + 1);
    r.min_cost = t.min_cost;
    r.power_term = t.terms.power;
    r.mrr_term = t.terms.mrr;
    r.dns_term = t.terms.speed_security;
    r.speed_rpm = revPerSToRpm(t.q.speed_rev_per_s);
    r.depth_mm = t.q.depth_m * 1e3;
    r.feed_mm_per_tooth = t.q.feed_per_tooth_m * 1e3;
    r.power_w = t.q.power_w;
    r.mrr_mm3_min = t.q.mrr_m3_per_s * 1e9 * 60.0;
    r.dns_rpm = revPerSToRpm(t.q.speed_security);
    rows.push_back(r);
  }
  return rows;
}

void RankingTable::applyRefinement(QVector<RankingRow>& rows, const QString& tool, const RefinementCandidate& chosen) {
  for (RankingRow& r : rows) {
    if (r.tool != tool) continue;
    r.time_cost = chosen.time_cost;
    r.frequency_cost = chosen.frequency_cost;
    r.resultant_cost = chosen.resultant;
  }
}

}  // namespace mx::widgets

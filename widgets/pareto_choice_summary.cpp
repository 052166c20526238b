#include "pareto_choice_summary.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QStandardItemModel>
#include <QVBoxLayout>
#include <utility>

#include "section_heading.h"

namespace mx::widgets {

namespace {
void selectKey(QComboBox* combo, const QString& key) {
  const QSignalBlocker block(combo);
  const int i = combo->findData(key);
  if (i >= 0) combo->setCurrentIndex(i);
}
}  // namespace

ParetoChoiceSummaryPanel::ParetoChoiceSummaryPanel(QWidget* parent)
    : QWidget(parent),
      objective_(new QComboBox),
      normalisation_(new QComboBox),
      point_(new QLabel),
      binding_(new QLabel) {
  objective_->setObjectName("pareto_objective");
  objective_->addItem(tr("Weighted J (TOL, MRR, SURF, ROS)"), "weighted");
  objective_->addItem(tr("Minimum cost per part"), "min_cost");
  objective_->addItem(tr("Maximum rate (minimum time per part)"), "max_rate");
  objective_->setToolTip(
      tr("pareto.objective: the weighted sum of eq. 9, or Gilbert's machining economics with the Taylor "
         "tool life (needs pareto.economics)"));
  normalisation_->setObjectName("pareto_normalisation");
  normalisation_->addItem(tr("log (TOL, SURF)"), "log");
  normalisation_->addItem(tr("min-max (Rule 9 as printed)"), "minmax");
  normalisation_->addItem(tr("max only"), "max");
  normalisation_->setToolTip(
      tr("pareto.normalisation (Rule 9): log scores equal ratios of tool life and roughness equally "
         "anywhere in Q; min-max compresses most of Q near one end of those power laws"));
  point_->setObjectName("pareto_point_summary");
  point_->setWordWrap(true);
  point_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  binding_->setObjectName("pareto_binding");
  binding_->setWordWrap(true);
  binding_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* form = new QFormLayout;
  form->addRow(tr("Objective"), objective_);
  form->addRow(tr("Normalisation"), normalisation_);
  // The texts under their captions, at the dock's full width: as fields of the form, their wrapped
  // height came out short of the text (QFormLayout's height for width) and the last line was cut.
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(form);
  for (auto [caption, text] : {std::pair{tr("Selected q"), point_}, std::pair{tr("Binding at q"), binding_}}) {
    QLabel* heading = sectionHeading(caption);
    heading->setBuddy(text);
    layout->addWidget(heading);
    layout->addWidget(text);
  }
  connect(objective_, &QComboBox::activated, this,
          [this](int i) { emit objectiveChosen(objective_->itemData(i).toString()); });
  connect(normalisation_, &QComboBox::activated, this,
          [this](int i) { emit normalisationChosen(normalisation_->itemData(i).toString()); });
  setSummary(std::nullopt);
}

void ParetoChoiceSummaryPanel::setObjective(const QString& key) {
  selectKey(objective_, key);
}

void ParetoChoiceSummaryPanel::setNormalisation(const QString& key) {
  selectKey(normalisation_, key);
}

void ParetoChoiceSummaryPanel::setEconomicsAvailable(bool available) {
  auto* model = qobject_cast<QStandardItemModel*>(objective_->model());
  for (int i = 1; i < objective_->count(); ++i) {
    model->item(i)->setEnabled(available);
    model->item(i)->setToolTip(available ? QString() : tr("needs pareto.economics in the project"));
  }
}

void ParetoChoiceSummaryPanel::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, [this] { setSummary(summary_); });
}

void ParetoChoiceSummaryPanel::setSummary(const std::optional<ParetoChoiceSummary>& s) {
  summary_ = s;
  if (!s) {
    point_->setText(tr("\u2014"));
    binding_->setText(tr("\u2014"));
    return;
  }
  const ShopUnits& units = DisplayUnits::of(units_);
  QString text = tr("%1 rpm, depth %2, %3\nMRR %4, tool life %5 min, roughness %6 \u00b5m, ROS %7")
                     .arg(s->speed_rpm, 0, 'f', 0)
                     .arg(units.format(Quantity::Length, s->depth_mm))
                     .arg(units.format(Quantity::ChipLoad, s->feed_mm_per_tooth))
                     .arg(units.format(Quantity::RemovalRate, cm3PerMinFromCm3PerS(s->mrr_cm3_s)))
                     .arg(s->tol_min, 0, 'g', 4)
                     .arg(s->surf_um, 0, 'g', 4)
                     .arg(s->ros, 0, 'f', 3);
  if (s->cost_per_part && s->time_per_part_min)
    text += tr("\nCost per part %1, time per part %2 min")
                .arg(*s->cost_per_part, 0, 'f', 2)
                .arg(*s->time_per_part_min, 0, 'f', 2);
  point_->setText(text);
  binding_->setText(s->binding.isEmpty() ? tr("no limit: a further step of depth and feed stays inside Q")
                                         : QStringLiteral("\u2022 ") + s->binding.join(QStringLiteral("\n\u2022 ")));
}

}  // namespace mx::widgets

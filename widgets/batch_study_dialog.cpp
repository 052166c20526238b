#include "batch_study_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <array>
#include <optional>
#include <utility>

namespace mx::widgets {

namespace {

constexpr std::array<std::pair<const char*, const char*>, 4> kComputations{{
    {"lobes", "Stability lobes of each tool (best pocket)"},
    {"rank", "Expert ranking of the tools (selected tool and q*)"},
    {"pareto", "Pareto study of the tools (tool and q)"},
    {"point", "Operating point of each tool (verdict)"},
}};

constexpr std::array<std::pair<const char*, const char*>, 12> kColumnTitles{{
    {"project", "Project"},
    {"machine", "Machine"},
    {"material", "Material"},
    {"operation", "Operation"},
    {"case", "Case"},
    {"tool", "Tool"},
    {"speed_rpm", "Speed [rpm]"},
    {"depth_mm", "Depth [mm]"},
    {"feed_mm_per_tooth", "Feed [mm/tooth]"},
    {"blim_mm", "b_lim [mm]"},
    {"verdict", "Verdict"},
    {"error", "Error"},
}};

CheckedDoubleSpinBox* rpmBox(QWidget* parent, const QString& name, double minimum, double value) {
  auto* box = new CheckedDoubleSpinBox(parent);
  box->setObjectName(name);
  box->setRange(minimum, 200000.0);
  box->setDecimals(0);
  box->setSuffix(" rpm");
  box->setValue(value);
  return box;
}

// A section object of a summary cell ({"milling":"up","radial_immersion":0.5,...}) as a machinist reads
// it: "up milling, a_e/D 0.5, f_z max 0.15 mm"; other cells as they are.
QString cellText(const QString& column, const QString& text) {
  if (column != QLatin1String("operation") || !text.startsWith('{')) return text;
  const QJsonObject o = QJsonDocument::fromJson(text.toUtf8()).object();
  QStringList parts;
  if (o.contains("milling")) parts << BatchStudyDialog::tr("%1 milling").arg(o.value("milling").toString());
  if (o.contains("radial_immersion"))
    parts << BatchStudyDialog::tr("a_e/D %1").arg(o.value("radial_immersion").toDouble());
  if (o.contains("max_feed_per_tooth_mm"))
    parts << BatchStudyDialog::tr("f_z max %1 mm").arg(o.value("max_feed_per_tooth_mm").toDouble());
  return parts.isEmpty() ? text : parts.join(", ");
}

// Decimals a numeric column is shown with: speeds whole, depths to the µm, feeds to 0.1 µm.
int decimalsOf(const QString& column) {
  if (column == QLatin1String("speed_rpm") || column == QLatin1String("case")) return 0;
  if (column == QLatin1String("feed_mm_per_tooth")) return 4;
  return 3;
}

// A cell that sorts by its number when it holds one (text order would put 9050 after 12000).
class ResultItem : public QTableWidgetItem {
 public:
  ResultItem(const QString& column, const QString& text) : QTableWidgetItem(cellText(column, text)) {
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok) return;
    number_ = value;
    setText(QString::number(value, 'f', decimalsOf(column)));
    setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  }
  bool operator<(const QTableWidgetItem& other) const override {
    const auto* o = dynamic_cast<const ResultItem*>(&other);
    if (o && number_ && o->number_) return *number_ < *o->number_;
    return QTableWidgetItem::operator<(other);
  }

 private:
  std::optional<double> number_;
};

}  // namespace

BatchStudyDialog::BatchStudyDialog(QWidget* parent)
    : QDialog(parent),
      computation_(new QComboBox(this)),
      tools_(new QListWidget(this)),
      materials_(new QListWidget(this)),
      machines_(new QListWidget(this)),
      add_machines_(new QPushButton(tr("Add from project files..."), this)),
      save_(new QPushButton(tr("Save manifest..."), this)),
      run_(new QPushButton(tr("Run here"), this)),
      cancel_(new QPushButton(tr("Cancel run"), this)),
      open_(new QPushButton(tr("Open results..."), this)),
      progress_(new QProgressBar(this)),
      status_(new QLabel(this)),
      results_(new QTableWidget(this)) {
  setObjectName("batchStudyDialog");
  setWindowTitle(tr("Batch study"));
  save_->setObjectName("batchSave");
  run_->setObjectName("batchRun");
  cancel_->setObjectName("batchCancel");
  open_->setObjectName("batchOpen");
  progress_->setObjectName("batchProgress");
  progress_->setFormat(tr("%v of %m cases"));
  progress_->setRange(0, 1);
  progress_->setValue(0);
  status_->setObjectName("batchStatus");
  status_->setWordWrap(true);
  results_->setObjectName("batchResults");
  results_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  results_->setSortingEnabled(true);
  results_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  results_->verticalHeader()->setVisible(false);

  auto* actions = new QHBoxLayout;
  actions->addWidget(save_);
  actions->addWidget(run_);
  actions->addWidget(cancel_);
  actions->addStretch(1);
  actions->addWidget(open_);
  auto* close = new QDialogButtonBox(QDialogButtonBox::Close, this);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(buildForm());
  layout->addLayout(actions);
  layout->addWidget(progress_);
  layout->addWidget(status_);
  layout->addWidget(results_, 1);
  layout->addWidget(close);

  connect(save_, &QPushButton::clicked, this, [this] { emit saveRequested(settings()); });
  connect(run_, &QPushButton::clicked, this, [this] { emit runRequested(settings()); });
  connect(cancel_, &QPushButton::clicked, this, &BatchStudyDialog::cancelRequested);
  connect(open_, &QPushButton::clicked, this, &BatchStudyDialog::openResultsRequested);
  connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(computation_, &QComboBox::currentIndexChanged, this,
          [this] { speed_range_->setVisible(computation_->currentData().toString() == "lobes"); });
  connect(tools_, &QListWidget::itemChanged, this, &BatchStudyDialog::updateButtons);
  connect(materials_, &QListWidget::itemChanged, this, &BatchStudyDialog::updateButtons);
  connect(machines_, &QListWidget::itemChanged, this, &BatchStudyDialog::updateButtons);
  connect(add_machines_, &QPushButton::clicked, this, &BatchStudyDialog::addMachinesRequested);
  resize(1100, 760);
  updateButtons();
}

QWidget* BatchStudyDialog::buildForm() {
  auto* group =
      new QGroupBox(tr("Cases: each checked material x each checked machine x the project's operation"), this);
  for (const auto& [key, text] : kComputations) computation_->addItem(tr(text), QString::fromLatin1(key));
  computation_->setObjectName("batchComputation");
  tools_->setObjectName("batchTools");
  materials_->setObjectName("batchMaterials");
  jobs_ = new CheckedSpinBox(group);
  jobs_->setObjectName("batchJobs");
  jobs_->setFieldName(tr("Jobs [cases at once]"));
  jobs_->setRange(1, 1);
  auto* form = new QFormLayout(group);
  form->addRow(tr("Computation:"), computation_);
  form->addRow(tr("Tools (rank and Pareto: compared together):"), tools_);
  form->addRow(tr("Materials:"), materials_);
  form->addRow(tr("Machines:"), buildMachines());
  form->addRow(tr("Lobes:"), buildSpeedRange());
  form->addRow(tr("Jobs [cases at once]:"), jobs_);
  tools_->setMaximumHeight(110);
  materials_->setMaximumHeight(110);
  return group;
}

QWidget* BatchStudyDialog::buildMachines() {
  auto* box = new QWidget(this);
  machines_->setObjectName("batchMachines");
  machines_->setMaximumHeight(80);
  add_machines_->setObjectName("batchAddMachines");
  add_machines_->setToolTip(
      tr("Read the machine section of other project files (one per machine of the shop): each checked "
         "machine is a case, its spindle power, speed, torque and feed limits replacing the project's"));
  auto* row = new QHBoxLayout(box);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(machines_, 1);
  row->addWidget(add_machines_, 0, Qt::AlignTop);
  return box;
}

QWidget* BatchStudyDialog::buildSpeedRange() {
  speed_range_ = new QWidget(this);
  from_ = rpmBox(speed_range_, "batchFrom", 1.0, 4000.0);
  from_->setFieldName(tr("First speed [rpm]"));
  to_ = rpmBox(speed_range_, "batchTo", 1.0, 18000.0);
  to_->setFieldName(tr("Last speed [rpm]"));
  step_ = rpmBox(speed_range_, "batchStep", 1.0, 50.0);
  step_->setFieldName(tr("Speed step [rpm]"));
  method_ = new QComboBox(speed_range_);
  method_->setObjectName("batchMethod");
  method_->addItem(tr("ZOA (zeroth-order approximation)"), "zoa");
  method_->addItem(tr("Semi-discretization"), "sdm");
  auto* row = new QHBoxLayout(speed_range_);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(new QLabel(tr("speed from"), speed_range_));
  row->addWidget(from_);
  row->addWidget(new QLabel(tr("to"), speed_range_));
  row->addWidget(to_);
  row->addWidget(new QLabel(tr("step"), speed_range_));
  row->addWidget(step_);
  row->addWidget(method_);
  row->addStretch(1);
  return speed_range_;
}

void BatchStudyDialog::fillList(QListWidget* list, const QStringList& items, int checked_first) {
  list->clear();
  for (qsizetype i = 0; i < items.size(); ++i) {
    auto* item = new QListWidgetItem(items[i], list);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(i < checked_first ? Qt::Checked : Qt::Unchecked);
  }
}

void BatchStudyDialog::setChoices(const BatchStudyChoices& choices) {
  setWindowTitle(tr("Batch study - %1").arg(choices.project_name));
  fillList(tools_, choices.tools, static_cast<int>(choices.tools.size()));
  fillList(materials_, choices.materials, 1);
  fillList(machines_, choices.machines, 1);
  jobs_->setRange(1, std::max(1, choices.max_jobs));
  jobs_->setValue(std::max(1, choices.max_jobs));
  updateButtons();
}

QStringList BatchStudyDialog::checkedItems(const QListWidget* list) {
  QStringList out;
  for (int i = 0; i < list->count(); ++i)
    if (list->item(i)->checkState() == Qt::Checked) out << list->item(i)->text();
  return out;
}

BatchStudySettings BatchStudyDialog::settings() const {
  BatchStudySettings s;
  s.computation = computation_->currentData().toString();
  s.tools = checkedItems(tools_);
  s.materials = checkedItems(materials_);
  s.machines = checkedItems(machines_);
  s.from_rpm = from_->value();
  s.to_rpm = to_->value();
  s.step_rpm = step_->value();
  s.method = method_->currentData().toString();
  s.jobs = jobs_->value();
  return s;
}

void BatchStudyDialog::setSettings(const BatchStudySettings& s) {
  computation_->setCurrentIndex(std::max(0, computation_->findData(s.computation)));
  for (QListWidget* list : {tools_, materials_, machines_}) {
    const QStringList& checked = list == tools_ ? s.tools : list == materials_ ? s.materials : s.machines;
    for (int i = 0; i < list->count(); ++i)
      list->item(i)->setCheckState(checked.contains(list->item(i)->text()) ? Qt::Checked : Qt::Unchecked);
  }
  from_->setValue(s.from_rpm);
  to_->setValue(s.to_rpm);
  step_->setValue(s.step_rpm);
  method_->setCurrentIndex(std::max(0, method_->findData(s.method)));
  jobs_->setValue(s.jobs);
}

void BatchStudyDialog::addMachines(const QStringList& labels) {
  for (const QString& label : labels) {
    if (!machines_->findItems(label, Qt::MatchExactly).isEmpty()) continue;
    auto* item = new QListWidgetItem(label, machines_);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(Qt::Checked);
  }
  updateButtons();
}

// A study needs a tool, a material and a machine; nothing is started twice.
void BatchStudyDialog::updateButtons() {
  const bool complete =
      !checkedItems(tools_).isEmpty() && !checkedItems(materials_).isEmpty() && !checkedItems(machines_).isEmpty();
  save_->setEnabled(complete && !running_);
  run_->setEnabled(complete && !running_);
  cancel_->setEnabled(running_);
  open_->setEnabled(!running_);
  const QString incomplete = tr("Check at least one tool, one material and one machine.");
  if (!complete && !running_)
    setStatus(incomplete);
  else if (status_->text() == incomplete)
    setStatus({});
}

void BatchStudyDialog::setRunning(bool running) {
  running_ = running;
  updateButtons();
}

void BatchStudyDialog::setProgress(qint64 done, qint64 total) {
  progress_->setRange(0, static_cast<int>(std::max<qint64>(total, 1)));
  progress_->setValue(static_cast<int>(std::min(done, total)));
}

void BatchStudyDialog::setStatus(const QString& text) {
  status_->setText(text);
}

QString BatchStudyDialog::columnTitle(const QString& key) {
  for (const auto& [k, title] : kColumnTitles)
    if (key == QLatin1String(k)) return tr(title);
  return key;
}

void BatchStudyDialog::setResults(const QStringList& columns, const std::vector<QStringList>& rows) {
  results_->setSortingEnabled(false);
  results_->clear();
  results_->setColumnCount(static_cast<int>(columns.size()));
  QStringList titles;
  for (const QString& c : columns) titles << columnTitle(c);
  results_->setHorizontalHeaderLabels(titles);
  results_->setRowCount(static_cast<int>(rows.size()));
  std::vector<bool> used(static_cast<std::size_t>(columns.size()), false);
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (qsizetype c = 0; c < rows[r].size() && c < columns.size(); ++c) {
      results_->setItem(static_cast<int>(r), static_cast<int>(c), new ResultItem(columns[c], rows[r][c]));
      if (!rows[r][c].isEmpty()) used[static_cast<std::size_t>(c)] = true;
    }
  // A computation fills only its own columns (lobes: no depth or feed; rank: no b_lim): the others hide.
  for (qsizetype c = 0; c < columns.size(); ++c)
    results_->setColumnHidden(static_cast<int>(c), !rows.empty() && !used[static_cast<std::size_t>(c)]);
  results_->setSortingEnabled(true);
}

}  // namespace mx::widgets

#include "start_screen.h"

#include <QFileInfo>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace mx::widgets {

namespace {
constexpr int kPathRole = Qt::UserRole;  // an entry's absolute path
constexpr int kContentWidth = 1040;      // the page's width at most, centred over a wide chart

QLabel* note(const QString& text, QWidget* parent) {
  auto* label = new QLabel(text, parent);
  label->setWordWrap(true);
  label->setStyleSheet("color: #555555;");
  return label;
}
}  // namespace

StartScreen::StartScreen(QWidget* parent)
    : QWidget(parent),
      examples_(new QListWidget(this)),
      description_(new QLabel(this)),
      recent_(new QListWidget(this)),
      no_recent_(new QLabel(tr("No recent projects yet."), this)) {
  setObjectName("startScreen");
  setAutoFillBackground(true);  // over the chart: opaque
  auto* page = new QWidget;
  page->setMaximumWidth(kContentWidth);
  auto* title = new QLabel(tr("MillExpert"), page);
  QFont big = title->font();
  big.setPointSizeF(big.pointSizeF() * 2.0);
  big.setBold(true);
  title->setFont(big);
  auto* columns = new QHBoxLayout;
  columns->addWidget(buildActions(), 1);
  columns->addWidget(buildExamples(), 1);
  auto* layout = new QVBoxLayout(page);
  layout->addWidget(title);
  layout->addWidget(note(tr("Stability lobes, chatter simulation, expert tool and cutting-parameter selection, force "
                            "and supervisory control. This project has no tool yet: open an example, or bring the "
                            "tool data of your own machine."),
                         page));
  layout->addLayout(columns, 1);
  layout->addWidget(note(tr("Help > User guide (F1) explains every view. Shift+F1, then a click on a symbol "
                            "(ROS, \u0394N_s, q*, q**, \u03b7, J_c), explains that symbol."),
                         page));

  auto* area = new QScrollArea(this);
  area->setFrameShape(QFrame::NoFrame);
  area->setWidgetResizable(true);
  auto* centring = new QWidget;
  auto* row = new QHBoxLayout(centring);
  row->addStretch(0);
  row->addWidget(page, 1);
  row->addStretch(0);
  area->setWidget(centring);
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  outer->addWidget(area);
  setRecentFiles({});
}

// Left column: the imports, Open, and the recent projects.
QWidget* StartScreen::buildActions() {
  auto* box = new QGroupBox(tr("Start"), this);
  auto* layout = new QVBoxLayout(box);
  const struct {
    const char* name;
    QString text;
    QString detail;
    void (StartScreen::*signal)();
  } actions[] = {
      {"startImportTapTest", tr("Import a tap test..."),
       tr("A measured FRF of the tool tip (UFF 58/58b or CSV): fit its modes and see the lobes they give."),
       &StartScreen::tapTestImportRequested},
      {"startImportToolLibrary", tr("Import a tool library..."),
       tr("Tools from Fusion 360, FreeCAD, LinuxCNC, or a CSV or JSON library."),
       &StartScreen::toolLibraryImportRequested},
      {"startAddTool", tr("Add a tool"),
       tr("A tool typed in by hand in the tool library: teeth, diameter and the modes of a tap test."),
       &StartScreen::addToolRequested},
      {"startOpenProject", tr("Open a project..."), tr("A MillExpert project file (.mxproj)."),
       &StartScreen::openProjectRequested},
  };
  for (const auto& a : actions) {
    auto* button = new QPushButton(a.text, box);
    button->setObjectName(a.name);
    button->setToolTip(a.detail);
    connect(button, &QPushButton::clicked, this, a.signal);
    layout->addWidget(button);
    layout->addWidget(note(a.detail, box));
  }
  layout->addSpacing(8);
  layout->addWidget(new QLabel(tr("Recent projects:"), box));
  recent_->setObjectName("startRecent");
  recent_->setToolTip(tr("Click a project to open it"));
  recent_->setAlternatingRowColors(true);
  recent_->setMaximumHeight(8 * (recent_->fontMetrics().lineSpacing() + 6) + 2 * recent_->frameWidth());  // 8 kept
  connect(recent_, &QListWidget::itemClicked, this,
          [this](QListWidgetItem* item) { emit projectChosen(item->data(kPathRole).toString()); });
  connect(recent_, &QListWidget::itemActivated, this,
          [this](QListWidgetItem* item) { emit projectChosen(item->data(kPathRole).toString()); });
  layout->addWidget(recent_);
  layout->addWidget(no_recent_);
  layout->addStretch(1);
  return box;
}

// Right column: the bundled examples, the selected one's description, and the button that opens it.
QWidget* StartScreen::buildExamples() {
  auto* box = new QGroupBox(tr("Example projects"), this);
  auto* layout = new QVBoxLayout(box);
  examples_->setObjectName("startExamples");
  examples_->setToolTip(tr("The example projects shipped with MillExpert: double-click one to open it"));
  examples_->setWordWrap(true);  // long names wrap instead of scrolling sideways: rows tell entries apart
  examples_->setAlternatingRowColors(true);
  examples_->setSpacing(1);
  examples_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  description_->setObjectName("startExampleDescription");
  description_->setWordWrap(true);
  description_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  description_->setMinimumHeight(4 * description_->fontMetrics().height());
  open_example_ = new QPushButton(tr("Open an example project"), box);
  open_example_->setObjectName("startOpenExample");
  open_example_->setToolTip(tr("Open the selected example project"));
  connect(open_example_, &QPushButton::clicked, this, &StartScreen::openSelectedExample);
  connect(examples_, &QListWidget::itemActivated, this, &StartScreen::openSelectedExample);
  connect(examples_, &QListWidget::currentRowChanged, this, &StartScreen::showDescription);
  layout->addWidget(examples_, 1);
  layout->addWidget(description_);
  layout->addWidget(open_example_);
  return box;
}

void StartScreen::setExamples(const QVector<StartEntry>& examples) {
  examples_->clear();
  for (const StartEntry& e : examples) {
    auto* item = new QListWidgetItem(e.title.isEmpty() ? QFileInfo(e.path).fileName() : e.title, examples_);
    item->setData(kPathRole, e.path);
    item->setData(Qt::WhatsThisRole, e.description);
    item->setToolTip(QFileInfo(e.path).fileName());
  }
  if (!examples.isEmpty()) examples_->setCurrentRow(0);
  showDescription();
}

void StartScreen::setRecentFiles(const QStringList& paths) {
  recent_->clear();
  for (const QString& path : paths) {
    if (!QFileInfo::exists(path)) continue;
    auto* item = new QListWidgetItem(QFileInfo(path).fileName(), recent_);
    item->setData(kPathRole, path);
    item->setToolTip(path);
  }
  recent_->setVisible(recent_->count() > 0);
  no_recent_->setVisible(recent_->count() == 0);
}

QPushButton* StartScreen::button(const QString& object_name) const {
  return findChild<QPushButton*>(object_name);
}

void StartScreen::openSelectedExample() {
  if (const QListWidgetItem* item = examples_->currentItem()) emit projectChosen(item->data(kPathRole).toString());
}

void StartScreen::showDescription() {
  const QListWidgetItem* item = examples_->currentItem();
  description_->setText(item ? item->data(Qt::WhatsThisRole).toString() : tr("No example projects were found."));
  open_example_->setEnabled(item != nullptr);
}

}  // namespace mx::widgets

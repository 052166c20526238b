#include "help_feature.h"

#include <QAction>
#include <QApplication>
#include <QEvent>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QWhatsThis>

#include "example_projects.h"
#include "guide_window.h"
#include "mx_version.h"

// Q_INIT_RESOURCE names a global function: outside the namespace. The resource lives in the static
// millexpert_gui_core, which no executable references otherwise.
static void initHelpResource() {
  Q_INIT_RESOURCE(help);
}

namespace mx::gui {

HelpFeature::HelpFeature(QMainWindow* window)
    : WindowFeature(window), window_(window), start_(new widgets::StartScreen(window)), examples_(exampleProjects()) {
  setObjectName("helpFeature");
  initHelpResource();
  start_->setExamples(examples_);
  start_->hide();
  connect(start_, &widgets::StartScreen::projectChosen, this, &HelpFeature::projectOpenRequested);
  connect(start_, &widgets::StartScreen::openProjectRequested, this, &HelpFeature::openProjectRequested);
  connect(start_, &widgets::StartScreen::tapTestImportRequested, this, &HelpFeature::tapTestImportRequested);
  connect(start_, &widgets::StartScreen::toolLibraryImportRequested, this, &HelpFeature::toolLibraryImportRequested);
  connect(start_, &widgets::StartScreen::addToolRequested, this, &HelpFeature::addToolRequested);
  if (QWidget* host = window->centralWidget()) host->installEventFilter(this);
}

QUrl HelpFeature::guideUrl() {
  initHelpResource();
  return QUrl(QStringLiteral("qrc:/help/user-guide.md"));
}

QString HelpFeature::aboutText() {
  return tr("<p><b>MillExpert %1</b></p>"
            "<p>Milling stability lobes, chatter simulation, expert tool and cutting-parameter selection, force "
            "and supervisory control, after Rubio, De la Sen &amp; Ibeas (2006) and the companion papers the user "
            "guide cites.</p>"
            "<p>Built with Qt %2 (LGPL v3, The Qt Company) and QCustomPlot (GPL v3, Emanuel Eichhammer), "
            "used under their licenses.</p>")
      .arg(QString::fromLatin1(app::kVersion), QString::fromLatin1(qVersion()));
}

void HelpFeature::projectChanged(const app::Project& project, Features /*recompute*/) {
  showStartScreen(project.tools.empty());
}

void HelpFeature::addHelpActions(QMenu* help) {
  QAction* guide = help->addAction(tr("&User guide"));
  guide->setObjectName("userGuideAction");
  guide->setShortcut(QKeySequence::HelpContents);
  guide->setStatusTip(tr("Open the user guide beside the window"));
  connect(guide, &QAction::triggered, this, &HelpFeature::showGuide);

  QAction* whats_this = QWhatsThis::createAction(help);
  whats_this->setObjectName("whatsThisAction");
  whats_this->setStatusTip(tr("Click a symbol (ROS, \u0394N_s, q*, q**, \u03b7, J_c) or a field to see what it is"));
  help->addAction(whats_this);

  QMenu* examples = help->addMenu(tr("&Examples"));
  examples->setObjectName("examplesMenu");
  for (const widgets::StartEntry& e : examples_) {
    QAction* a = examples->addAction(e.title, this, [this, path = e.path] { emit projectOpenRequested(path); });
    a->setStatusTip(e.description);
    a->setToolTip(e.description);
    a->setData(e.path);
  }
  examples->setEnabled(!examples_.isEmpty());

  help->addSeparator();
  QAction* about = help->addAction(tr("&About MillExpert"));
  about->setObjectName("aboutAction");
  connect(about, &QAction::triggered, this,
          [this] { QMessageBox::about(window_, tr("About MillExpert"), aboutText()); });
  help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

widgets::GuideWindow* HelpFeature::showGuide() {
  if (!guide_) guide_ = new widgets::GuideWindow(guideUrl(), window_);
  guide_->show();
  guide_->raise();
  guide_->activateWindow();
  return guide_;
}

void HelpFeature::showStartScreen(bool shown) {
  if (shown == startScreenShown()) return;
  if (shown) {
    start_->setRecentFiles(QSettings().value("recentFiles").toStringList());
    if (QWidget* host = window_->centralWidget()) start_->setGeometry(host->geometry());
    start_->raise();
  }
  start_->setVisible(shown);
}

bool HelpFeature::eventFilter(QObject* watched, QEvent* event) {
  if ((event->type() == QEvent::Resize || event->type() == QEvent::Move) && watched == window_->centralWidget())
    start_->setGeometry(window_->centralWidget()->geometry());
  return WindowFeature::eventFilter(watched, event);
}

}  // namespace mx::gui

// Scenario "monkey": a copy of the project in a temporary folder, opened in the real window (not quiet:
// refused edits raise their message boxes, which the monkey answers); then random actions on a random
// region each, chosen uniformly among the docks and the central widget so that a small dock gets as
// many as the chart, a dock behind a tab raised by a click on its tab first. Afterwards Ctrl+S, the
// document reader on the saved file, and a second window on it.
#include "e2e_monkey.h"

#include <QApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QStatusBar>
#include <QTemporaryDir>

#include "document/project.h"
#include "e2e_async_input.h"
#include "e2e_driver.h"
#include "e2e_gap_probe.h"
#include "e2e_monkey_actions.h"
#include "e2e_monkey_dialogs.h"
#include "e2e_screen_scan.h"
#include "e2e_window.h"
#include "lobes_feature.h"
#include "support/window_features.h"

namespace mx::e2e {

namespace {

constexpr int kComputeMs = 120000 * MX_TIMING_SCALE;  // the first lobes (and the second window's)
constexpr int kGapLimitMs = 250 * MX_TIMING_SCALE;
constexpr int kScanEvery = 25;  // actions between two looks for nan and inf on screen
constexpr int kFocusMs = 2000;

QString counts(const QMap<QString, int>& map) {
  QStringList parts;
  for (auto it = map.begin(); it != map.end(); ++it) parts << QString("%1 %2").arg(it.key()).arg(it.value());
  return parts.join(", ");
}

class Monkey {
 public:
  Monkey(Report& report, AsyncXInput& input, gui::MainWindow& window, const MonkeyOptions& options,
         const QString& log_path)
      : report_(report),
        input_(input),
        window_(window),
        options_(options),
        dice_(options.seed),
        log_(log_path),
        closer_(dice_, log_, [this] { return clock_.elapsed(); }),
        regions_(regionsOf(window)) {}

  void run();
  void report();

 private:
  void step();
  void perform(const PlannedAction& planned);
  void ensureFocus();
  void scanScreen();

  Report& report_;
  AsyncXInput& input_;
  gui::MainWindow& window_;
  const MonkeyOptions& options_;
  QElapsedTimer clock_;
  Dice dice_;
  ActionLog log_;
  GapProbe probe_;
  DialogCloser closer_;
  std::vector<Region> regions_;
  QString longest_gap_action_;
  QStringList non_finite_;
  int skipped_ = 0, focus_losses_ = 0;
};

void Monkey::run() {
  report_.require("monkey.log", log_.isOpen(), "the action log " + log_.path());
  report_.note(QString("monkey: seed %1, %2 s, %3 regions, action log %4")
                   .arg(options_.seed)
                   .arg(options_.seconds)
                   .arg(regions_.size())
                   .arg(log_.path()));
  clock_.start();
  probe_.start();
  qint64 longest_seen = 0;
  while (clock_.elapsed() < qint64(options_.seconds) * 1000) {
    step();
    if (probe_.longestMs() > longest_seen) {  // the action in progress during the longest gap so far
      longest_seen = probe_.longestMs();
      longest_gap_action_ = log_.last();
    }
    if (log_.count() % kScanEvery == 0) scanScreen();
  }
  closer_.closeAll();
  spin(300);
  probe_.stop();
  scanScreen();
}

void Monkey::step() {
  probe_.pause();  // choosing is the driver's own work
  const Region& region = regions_[static_cast<std::size_t>(dice_.below(int(regions_.size())))];
  if (!region.shown()) {
    const std::optional<PlannedAction> raise = planRaise(window_, region);
    if (!raise) {
      ++skipped_;
      probe_.resume();
      spin(5);
      return;
    }
    perform(*raise);
    spin(dice_.between(20, 60));
    probe_.pause();
    if (!region.shown()) return;
  }
  const ActionKind kind = drawKind(dice_);
  const std::optional<PlannedAction> planned = planAction(kind, region, dice_);
  if (!planned) {
    ++skipped_;
    log_.note(QString("no target for a %1 in %2").arg(kindName(kind), region.name), clock_.elapsed());
    probe_.resume();
    spin(5);
    return;
  }
  perform(*planned);
  spin(dice_.between(0, 60));
}

void Monkey::perform(const PlannedAction& planned) {
  log_.record(planned.action, clock_.elapsed());
  if (planned.needs_focus) {
    probe_.resume();
    ensureFocus();
    probe_.pause();
  }
  input_.run(planned.xdotool, [this] { probe_.resume(); });
}

// Key events go to the X input focus: give it back to the window when a closed dialog took it.
void Monkey::ensureFocus() {
  if (QApplication::activeWindow() == &window_ || QApplication::activeModalWidget() ||
      QApplication::activePopupWidget())
    return;
  ++focus_losses_;
  log_.note("the window gets the input focus back", clock_.elapsed());
  window_.activateWindow();
  QElapsedTimer waited;
  waited.start();
  while (QApplication::activeWindow() != &window_ && waited.elapsed() < kFocusMs) spin(10);
}

void Monkey::scanScreen() {
  probe_.pause();
  for (const QString& text : nonFiniteTexts(window_, nonFiniteUserStrings(app::projectToJson(*window_.project())))) {
    const QString entry = QString("after action #%1: %2").arg(log_.count()).arg(text);
    if (non_finite_.size() < 20 && !non_finite_.contains(text)) {
      non_finite_ << text;
      log_.note("non-finite on screen: " + text, clock_.elapsed());
      report_.note(entry);
    }
  }
  probe_.resume();
}

void Monkey::report() {
  report_.note(QString("monkey: %1 actions in %2 s: %3")
                   .arg(log_.count())
                   .arg(clock_.elapsed() / 1000.0, 0, 'f', 1)
                   .arg(counts(log_.perKind())));
  report_.note("monkey: actions per region: " + counts(log_.perRegion()));
  report_.note(QString("monkey: %1 dialogs and %2 popups closed, %3 focus repairs, %4 draws without a target")
                   .arg(closer_.dialogsClosed())
                   .arg(closer_.popupsClosed())
                   .arg(focus_losses_)
                   .arg(skipped_));
  report_.note(QString("monkey: longest event-loop gap %1 ms (limit %2 ms), during %3; the driver's longest own "
                       "pause %4 ms (not counted)")
                   .arg(probe_.longestMs())
                   .arg(kGapLimitMs)
                   .arg(longest_gap_action_.isEmpty() ? QString("the start") : longest_gap_action_)
                   .arg(probe_.longestPauseMs()));
  report_.note(QString("monkey: the longest single event took %1 ms: %2")
                   .arg(probe_.longestEventMs())
                   .arg(probe_.longestEvent()));
  report_.check("monkey.actions", log_.count() >= options_.seconds,
                QString("%1 actions in %2 s (at least one a second)").arg(log_.count()).arg(options_.seconds));
  QStringList untouched;
  for (const Region& region : regions_)
    if (log_.perRegion().value(region.name) == 0) untouched << region.name;
  report_.check("monkey.every_region", untouched.isEmpty() || options_.seconds < 20,
                untouched.isEmpty() ? QString("all %1 regions had actions").arg(regions_.size())
                                    : "no action on " + untouched.join(", "));
  report_.check("monkey.event_loop_gap", probe_.longestMs() <= kGapLimitMs,
                QString("longest %1 ms, limit %2 ms").arg(probe_.longestMs()).arg(kGapLimitMs));
  report_.check("monkey.no_nonfinite_text", non_finite_.isEmpty(),
                non_finite_.isEmpty() ? "no nan or inf on screen" : non_finite_.join(" | "));
  const QStringList open = closer_.openNow();
  report_.check("monkey.no_dialog_left", open.isEmpty(), open.isEmpty() ? "none open" : open.join(", "));
}

// The status bar's message and labels (the engine's state, an error).
QStringList statusTexts(gui::MainWindow& window) {
  QStringList texts{window.statusBar()->currentMessage()};
  for (const QLabel* label : window.statusBar()->findChildren<QLabel*>())
    if (!label->text().isEmpty()) texts << label->text();
  return texts;
}

// Ctrl+S onto the copy (its time stamp set back a day, so the save must renew it).
void saveWithCtrlS(Report& report, AsyncXInput& input, gui::MainWindow& window, const QString& path) {
  {
    QFile file(path);
    report.require("save.touch", file.open(QIODevice::ReadWrite), path);
    file.setFileTime(QDateTime::currentDateTime().addDays(-1), QFileDevice::FileModificationTime);
  }
  const QDateTime before = QFileInfo(path).lastModified();
  report.require("save.same_file", window.document()->filePath() == path,
                 QString("the window's file is '%1'").arg(window.document()->filePath()));
  activate(&window);
  input.run({"key", "ctrl+s"}, {});
  waitFor([&] { return !window.document()->isDirty() && QFileInfo(path).lastModified() > before; }, 10000,
          "Ctrl+S to save the project");
  report.check("save.written", true, "Ctrl+S renewed the file and left the document clean");
}

void reloadAndCompare(Report& report, gui::MainWindow& window, const QString& path) {
  const QJsonObject shown = app::projectToJson(*window.project());
  QJsonObject saved;
  try {
    saved = app::projectToJson(app::loadProject(path));
    report.check("reload.valid", true, "the saved file parses and validates");
  } catch (const std::exception& e) {
    report.check("reload.valid", false, QString("the saved file is refused: %1").arg(e.what()));
    return;
  }
  report.check("reload.equal", saved == shown, "the saved file reads back as the window's project");

  std::unique_ptr<gui::MainWindow> second = showWindow();
  QSignalSpy lobes(test::lobesOf(*second), &gui::LobesFeature::lobesShown);
  report.require("reload.second_window_opens", second->openProject(path), path);
  report.check("reload.second_window_equal", app::projectToJson(*second->project()) == shown,
               "a second window on the saved file holds the same project");
  if (second->project()->tools.empty()) {  // the monkey removed every tool: nothing to compute
    report.note("the saved project has no tools left: no lobes to compute");
    return;
  }
  const bool computed = lobes.count() > 0 || lobes.wait(kComputeMs);
  report.check("reload.second_window_lobes", computed,
               computed ? QString("the second window computes the lobes of the saved project")
                        : "no lobes; the status bar says: " + statusTexts(*second).join(" | "));
}

}  // namespace

void runMonkey(Report& report, const QString& xdotool, const MonkeyOptions& options, const QString& log_path) {
  QTemporaryDir folder;
  report.require("temporary_folder", folder.isValid(), folder.errorString());
  const QString path = folder.filePath("project.mxproj");
  report.require("copy_project", QFile::copy(options.project, path), options.project + " -> " + path);
  QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
  QDir::setCurrent(folder.path());  // a dialog answered by stray keys writes here, nowhere else

  AsyncXInput input(xdotool);
  std::unique_ptr<gui::MainWindow> window = showWindow();
  QSignalSpy lobes(test::lobesOf(*window), &gui::LobesFeature::lobesShown);
  report.require("open", window->openProject(path), path);
  waitBeyond(lobes, 0, kComputeMs, "the lobes of the project");
  window->setQuiet(false);  // as a user has it: refused edits raise message boxes
  activate(window.get());
  {
    Monkey monkey(report, input, *window, options, log_path);
    monkey.run();
    monkey.report();
  }
  window->setQuiet(true);
  report.check("alive", true, "the window survived the monkey");
  saveWithCtrlS(report, input, *window, path);
  reloadAndCompare(report, *window, path);
}

}  // namespace mx::e2e

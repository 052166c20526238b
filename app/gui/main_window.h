#pragma once
// MillExpert main window: opens a project and shows the stability lobes of its tools.
#include <QLabel>
#include <QListWidget>
#include <QMainWindow>
#include <QProgressBar>
#include <optional>

#include "engine_runner.h"
#include "lobe_chart_view.h"
#include "project/project.h"

namespace mx::gui {

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);

  bool openProject(const QString& path);  // false (and a message box unless quiet) on a bad file
  const std::optional<app::Project>& project() const { return project_; }
  widgets::LobeChartView* lobeChart() const { return chart_; }
  EngineRunner* engine() const { return engine_; }
  void setQuiet(bool quiet) { quiet_ = quiet; }

 signals:
  void lobesShown();

 private slots:
  void onOpen();
  void onLobesReady(const mx::gui::LobeJobResult& result);
  void onExportChart();

 private:
  void buildMenus();
  void recomputeLobes();
  void showError(const QString& title, const QString& message);

  widgets::LobeChartView* chart_;
  QListWidget* tool_list_;
  QLabel* status_label_;
  QProgressBar* progress_;
  EngineRunner* engine_;
  std::optional<app::Project> project_;
  QString project_path_;
  bool quiet_ = false;
};

}  // namespace mx::gui

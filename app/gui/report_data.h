#pragma once
// The expert report's content (app::computeReportData) with its three figures rendered offscreen as
// PNG files. Plain data: the builder (ReportBuilder) and the writer (ReportWriter) only read it.
#include <QString>
#include <array>
#include <optional>

#include "services/report_data.h"
#include "shop_units.h"

namespace mx::gui {

using ReportData = app::ReportData;

struct ReportOptions {
  std::optional<std::array<double, 3>> c;  // overrides the project's c (must lie on the simplex)
  QString image_dir;                       // existing directory for the figures
  double sweep_step = 0.025;
  int image_width = 1200;
  int image_height = 675;
  widgets::ShopUnits units;  // of the figures' axes (the window's shop units; metric by default)
};

// Throws what app::computeReportData throws, or std::runtime_error when a figure cannot be written.
// Needs a QApplication for the figures.
ReportData collectReportData(const QString& project_path, const ReportOptions& options);

}  // namespace mx::gui

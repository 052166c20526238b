#pragma once
// Figures 9-13 of the 2006 paper from a project's "control" section, rendered offscreen through the
// control view (millexpert-plot --control, docs/make-plots.sh): the closed loop for one beta
// (responses, tracking error, control law) and the J_c(beta) sweep.
#include <QString>

namespace mx::gui {

// Returns "" on success, else the error (bad project, failed run, unwritable file).
QString renderControlResponse(const QString& project_path, double beta, const QString& out_png);
QString renderControlJc(const QString& project_path, double from, double to, double step, const QString& out_png);

}  // namespace mx::gui

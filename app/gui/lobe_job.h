#pragma once
// The lobe job: inputs copied from the project, computed on the engine thread.
#include <QMetaType>
#include <QString>
#include <QVector>
#include <atomic>
#include <memory>

#include "lobe_chart_view.h"
#include "model/milling_setup.h"

namespace mx::gui {

struct LobeJobInput {
  std::vector<MillingSetup> tools;
  std::vector<double> speeds_rev_per_s;
  double delta_per_s = 0.0;
  double alpha = 1.0;
  double max_depth_m = 0.02;
};

struct LobeJobResult {
  quint64 generation = 0;
  QVector<widgets::ToolLobeSeries> series;
  QString error;  // empty on success
};

// Nominal and margined zeroth-order lobes of every tool; polls `cancel` between tools.
LobeJobResult runLobeJob(const LobeJobInput& input, quint64 generation, const std::atomic<bool>& cancel);

}  // namespace mx::gui

Q_DECLARE_METATYPE(mx::gui::LobeJobResult)

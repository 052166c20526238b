#pragma once
// The lobe job: inputs copied from the project, computed on the engine thread. The result is an
// immutable snapshot (per tool: setup, nominal and margined lobes) that the GUI thread queries for
// readouts without recomputing anything.
#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QVector>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>

#include "document/project.h"
#include "lobe_chart_view.h"
#include "model/milling_setup.h"
#include "stability/lobe_computation.h"
#include "stability/lobe_diagram.h"

namespace mx::gui {

using LobeMethod = StabilityMethod;  // the engine's ZOA / semi-discretization switch

// A tool with a tap-test FRF (frf_x, frf_y): the FRF is read on the engine thread from `project`, a
// snapshot with absolute paths, and its ZOA lobes (delta = 0) are drawn beside the modal ones; without
// modes on an FRF axis they are the tool's only lobes.
struct LobeFrfSource {
  std::shared_ptr<const app::Project> project;
  bool has_modes = true;
};

struct LobeJobInput {
  std::vector<MillingSetup> tools;
  std::vector<std::optional<LobeFrfSource>> frfs;  // aligned with tools, or empty: no FRFs
  std::vector<double> speeds_rev_per_s;
  LobeMethod method = LobeMethod::ZeroOrder;
  int sdm_steps = kAutoSdmSteps;  // autoSdmSteps per speed
  double delta_per_s = 0.0;
  double alpha = 1.0;
  double max_depth_m = 0.02;
};

struct ToolLobes {
  MillingSetup setup;
  LobeDiagram nominal;                  // delta = 0
  LobeDiagram margined;                 // the delta-lobes (alpha is applied by the consumers)
  std::optional<LobeDiagram> measured;  // ZOA on the tap-test FRF, delta = 0
  bool measured_only = false;           // no modes: nominal and margined are the measured lobes
  bool fitted_modes = false;            // the modes were fitted to a tap test (the tool has an FRF)
};

struct LobeSnapshot {
  LobeMethod method = LobeMethod::ZeroOrder;
  double delta_per_s = 0.0;
  double alpha = 1.0;
  std::vector<ToolLobes> tools;
  QStringList warnings;  // a tool's FRF that could not be read while its modes gave the lobes
  QVector<widgets::ToolLobeSeries> series() const;  // for the chart, in rpm and mm
};

struct LobeJobResult {
  quint64 generation = 0;
  std::shared_ptr<const LobeSnapshot> snapshot;  // null on error or cancel
  QString error;                                 // empty on success
  bool cancelled = false;
};

// Nominal and margined lobes of every tool. Polls `cancel` between speeds/lobes; reports the
// fraction done through `progress`.
LobeJobResult runLobeJob(const LobeJobInput& input, quint64 generation, const std::atomic<bool>& cancel,
                         const std::function<void(double)>& progress = {});

}  // namespace mx::gui

Q_DECLARE_METATYPE(mx::gui::LobeJobResult)

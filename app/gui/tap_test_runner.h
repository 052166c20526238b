#pragma once
// The tap-test jobs of the GUI, on the engine thread: reading a tap-test file (UFF 58/58b or CSV) and
// fitting modes to one receptance, with progress and an atomic cancel. Results come back through
// queued signals tagged with a generation id: every load answers (until forgetLoads), a newer fit makes
// the older fit stale.
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <atomic>
#include <memory>
#include <optional>
#include <set>

#include "engine_channel.h"
#include "frf/frf_dataset.h"
#include "frf/receptance_conversion.h"
#include "modal_fit/modal_fit.h"
#include "tap_test_panel.h"

namespace mx::gui {

struct TapTestFile {
  QString path;  // absolute
  std::optional<FrfQuantity> quantity;
  FrfFile file;
};

struct TapTestFit {
  QString direction;
  bool at_poles = false;  // fitted at poles chosen on the diagram: keep the diagram shown
  ModalFitResult result;
};

class TapTestRunner : public QObject {
  Q_OBJECT
 public:
  explicit TapTestRunner(QThreadPool* engine_pool, QObject* parent = nullptr);

  // Reads `path` (quantity: required for CSV, checked for UFF); loaded() or failed().
  quint64 load(const QString& path, std::optional<FrfQuantity> quantity);
  // Fits modes to `receptance` as the panel's request says; fitted() or failed(). Cancels a running fit.
  quint64 fit(const Receptance& receptance, const widgets::TapTestFitRequest& request);
  void cancel();
  void forgetLoads();                         // the running loads' results are dropped (another project is loaded)
  bool busy() const { return running_ > 0; }  // a fit is running (reading a file is not "busy")

 signals:
  void loaded(quint64 generation, const mx::gui::TapTestFile& file);
  void fitted(quint64 generation, const mx::gui::TapTestFit& fit);
  void failed(quint64 generation, const QString& message);
  void cancelled(quint64 generation);
  void progress(double fraction);
  void busyChanged(bool busy);  // fits only

 private:
  void started();
  void stopped();

  QThreadPool* pool_;
  EngineChannel channel_;
  std::shared_ptr<std::atomic<bool>> cancel_;
  quint64 generation_ = 0;
  quint64 fit_generation_ = 0;
  std::set<quint64> loads_;
  int running_ = 0;
};

}  // namespace mx::gui

Q_DECLARE_METATYPE(mx::gui::TapTestFile)
Q_DECLARE_METATYPE(mx::gui::TapTestFit)

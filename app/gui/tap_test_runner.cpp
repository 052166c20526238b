#include "tap_test_runner.h"

#include "core/cancellation.h"
#include "services/frf_import.h"

namespace mx::gui {

TapTestRunner::TapTestRunner(QThreadPool* engine_pool, QObject* parent)
    : QObject(parent), pool_(engine_pool), channel_(this), cancel_(std::make_shared<std::atomic<bool>>(false)) {
  qRegisterMetaType<mx::gui::TapTestFile>();
  qRegisterMetaType<mx::gui::TapTestFit>();
}

void TapTestRunner::started() {
  if (running_++ == 0) emit busyChanged(true);
}

void TapTestRunner::stopped() {
  if (--running_ == 0) emit busyChanged(false);
}

quint64 TapTestRunner::load(const QString& path, std::optional<FrfQuantity> quantity) {
  const quint64 generation = ++generation_;
  loads_.insert(generation);
  channel_.start(pool_, [this, path, quantity, generation](const EngineReply& reply) {
    TapTestFile out{path, quantity, {}};
    QString error;
    try {
      out.file = app::loadFrfFile(path, quantity);
      if (out.file.datasets.empty()) error = tr("%1: the file holds no FRF dataset (function type 4)").arg(path);
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    reply([this, out = std::move(out), error, generation] {
      if (loads_.erase(generation) == 0) return;  // forgotten (forgetLoads)
      if (error.isEmpty()) {
        emit loaded(generation, out);
      } else {
        emit failed(generation, error);
      }
    });
  });
  return generation;
}

quint64 TapTestRunner::fit(const Receptance& receptance, const widgets::TapTestFitRequest& request) {
  cancel();
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  const quint64 generation = ++generation_;
  fit_generation_ = generation;
  started();
  channel_.start(pool_, [this, receptance, request, generation, cancel = cancel_](const EngineReply& reply) {
    const JobControl job{cancel.get(), [reply, this](double f) { reply([this, f] { emit progress(f); }); }};
    TapTestFit out{request.direction, !request.poles.empty(), {}};
    QString error;
    bool was_cancelled = false;
    try {
      ModalFitSettings settings;
      settings.max_modes = request.max_modes;
      settings.modes = request.modes;
      settings.method = request.peak ? ModalFitSettings::Method::Peak : ModalFitSettings::Method::Lscf;
      if (out.at_poles) {
        settings.from_hz = request.from_hz;
        settings.to_hz = request.to_hz;
        out.result = fitModesAtPoles(receptance.frequency_hz, receptance.h_m_per_n, settings, request.poles, job);
      } else {
        out.result = app::fitFrfModes(receptance, request.from_hz, request.to_hz, settings, job);
      }
    } catch (const Cancelled&) {
      was_cancelled = true;
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    reply([this, out = std::move(out), error, was_cancelled, generation] {
      stopped();
      if (generation != fit_generation_) return;  // a newer fit was asked for
      if (was_cancelled) {
        emit cancelled(generation);
      } else if (error.isEmpty()) {
        emit fitted(generation, out);
      } else {
        emit failed(generation, error);
      }
    });
  });
  return generation;
}

void TapTestRunner::cancel() {
  cancel_->store(true);
}

void TapTestRunner::forgetLoads() {
  loads_.clear();
}

}  // namespace mx::gui

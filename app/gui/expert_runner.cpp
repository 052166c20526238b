#include "expert_runner.h"

#include "services/expert_request.h"

namespace mx::gui {

ExpertRunner::ExpertRunner(QThreadPool* engine_pool, QObject* parent)
    : QObject(parent), pool_(engine_pool), channel_(this) {
  qRegisterMetaType<mx::gui::RefinementOutcome>();
}

ExpertRunner::~ExpertRunner() {
  build_cancel_->store(true);
}

void ExpertRunner::dropPending() {
  build_cancel_->store(true);
  ++build_generation_;
  ++refine_generation_;
}

void ExpertRunner::started() {
  if (running_++ == 0) emit busyChanged(true);
}

void ExpertRunner::stopped() {
  if (--running_ == 0) emit busyChanged(false);
}

quint64 ExpertRunner::build(std::vector<MillingSetup> tools, const ExpertSettings& settings,
                            const QStringList& tool_ids) {
  auto request = std::make_shared<Request>(Request{std::move(tools), settings, tool_ids, {}, {}});
  return startBuild([request] { return std::move(*request); });
}

quint64 ExpertRunner::build(const app::Project& project) {
  return startBuild([project] {
    app::ExpertRequest request = app::expertRequestFromProject(project);
    app::applyExpertDynamics(project, request, std::nullopt, true);
    app::ExpertRules rules(project, request.tool_ids);
    rules.boundWeights(request.weights.c);  // ProjectError now when the fired bounds leave no weights
    return Request{std::move(request.tools), request.settings, request.tool_ids, request.tool_force_limits_n,
                   std::move(rules)};
  });
}

quint64 ExpertRunner::startBuild(std::function<Request()> make_request) {
  const quint64 generation = ++build_generation_;
  ++refine_generation_;  // refinements of the old session are stale
  build_cancel_->store(true);
  build_cancel_ = std::make_shared<std::atomic<bool>>(false);
  started();
  channel_.start(pool_, [this, make_request = std::move(make_request), generation,
                         cancel = build_cancel_](const EngineReply& reply) {
    ExpertOutcome outcome;
    outcome.generation = generation;
    try {
      Request request = make_request();
      outcome.tool_ids = request.tool_ids;
      outcome.session = std::make_shared<ExpertSession>(std::move(request.tools), request.settings,
                                                        request.tool_force_limits_n, JobControl{cancel.get(), {}});
      outcome.rules = request.rules;
      if (outcome.session->empty()) {
        outcome.error = QString::fromStdString("the admissible cutting-parameter space is empty: " +
                                               outcome.session->emptyReason());
      } else if (!outcome.rules.empty()) {
        outcome.rules.filter(*outcome.session);
        if (app::ExpertRules::excludeEverything(*outcome.session))
          outcome.error = "the operator rules exclude every admissible point of every tool";
      }
    } catch (const std::exception& e) {
      outcome.session.reset();
      outcome.error = QString::fromStdString(e.what());
    }
    reply([this, outcome = std::move(outcome)] {
      stopped();
      if (outcome.generation != build_generation_) return;  // stale
      session_ = outcome.session;
      tool_ids_ = outcome.tool_ids;
      rules_ = outcome.rules;
      emit sessionReady(outcome.error);
    });
  });
  return generation;
}

quint64 ExpertRunner::refine(const CostWeights& weights, const std::vector<ChatterReport>& reported) {
  const quint64 generation = ++refine_generation_;
  auto session = session_;
  if (!session || session->empty()) return generation;
  started();
  CostWeights bounded = weights;
  bounded.c = effectiveWeights(weights.c);
  channel_.start(pool_, [this, session, bounded, reported, generation](const EngineReply& reply) {
    RefinementOutcome outcome;
    outcome.generation = generation;
    try {
      outcome.result = session->run(bounded, true, reported);
    } catch (const std::exception& e) {
      outcome.error = QString::fromStdString(e.what());
    }
    reply([this, outcome = std::move(outcome)] {
      stopped();
      if (outcome.generation == refine_generation_) emit refined(outcome);
    });
  });
  return generation;
}

std::array<double, 3> ExpertRunner::effectiveWeights(const std::array<double, 3>& c) const {
  return rules_.boundWeights(c);
}

std::optional<Ranking> ExpertRunner::rank(const std::array<double, 3>& c) const {
  if (!session_ || session_->empty()) return std::nullopt;
  Ranking r = session_->rank(effectiveWeights(c));
  if (r.tools.empty()) return std::nullopt;
  return r;
}

}  // namespace mx::gui

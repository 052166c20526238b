#pragma once
// The expert system behind the GUI (2006, section 3). On the engine thread: the ExpertSession (lobes
// and admissible grids of every tool, once per project change) and the Rule 5-6 refinement
// (time-domain simulations, cached). On the GUI thread: re-ranking after a weight change, which is a
// pass over the session's cached arrays (milliseconds; nothing recomputed).
#include <QObject>
#include <QStringList>
#include <QThreadPool>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>

#include "document/project.h"
#include "engine_channel.h"
#include "expert/expert_session.h"
#include "services/expert_rules.h"

namespace mx::gui {

struct ExpertOutcome {
  quint64 generation = 0;
  std::shared_ptr<ExpertSession> session;  // null on error
  QStringList tool_ids;
  app::ExpertRules rules;  // the project's operator rules, installed on the session
  QString error;
};

struct RefinementOutcome {
  quint64 generation = 0;
  std::optional<ExpertResult> result;  // Rules 4-6 with simulation
  QString error;
};

class ExpertRunner : public QObject {
  Q_OBJECT
 public:
  ExpertRunner(QThreadPool* engine_pool, QObject* parent = nullptr);
  ~ExpertRunner() override;  // cancels a running build
  ExpertRunner(const ExpertRunner&) = delete;
  ExpertRunner& operator=(const ExpertRunner&) = delete;

  // Builds a session for these tools and settings on the engine thread; a newer build cancels the
  // running one (its result, stale, is dropped).
  quint64 build(std::vector<MillingSetup> tools, const ExpertSettings& settings, const QStringList& tool_ids);
  // The same from a project snapshot: its expert request, with the tools' tap-test FRFs (read on the
  // engine thread; `project` names them by absolute path), is made on the engine thread, and its
  // operator rules (Rule 18) bound c and filter the admissible points as in `millexpert-cli rank`.
  quint64 build(const app::Project& project);
  // Rules 4-6 with simulations for the current session and weights, on the engine thread; Rule 6 also
  // acts on the chatter reported at the machine (tools by index in toolIds()).
  quint64 refine(const CostWeights& weights, const std::vector<ChatterReport>& reported = {});
  // Cancels the running build and drops what the running build or refinement still delivers: the project
  // they were for has changed. The current session stays until the next build replaces it.
  void dropPending();

  const std::shared_ptr<ExpertSession>& session() const { return session_; }
  bool busy() const { return running_ > 0; }  // a build or a refinement is on the engine thread
  const QStringList& toolIds() const { return tool_ids_; }
  // Rule 4 on the GUI thread from the cached session, at effectiveWeights(c); nullopt without a session
  // or an admissible point.
  std::optional<Ranking> rank(const std::array<double, 3>& c) const;
  // c within the bounds the operator rules fired (c itself without rules).
  std::array<double, 3> effectiveWeights(const std::array<double, 3>& c) const;

 signals:
  void sessionReady(const QString& error);  // "" on success
  void refined(const mx::gui::RefinementOutcome& outcome);
  void busyChanged(bool busy);

 private:
  struct Request {
    std::vector<MillingSetup> tools;
    ExpertSettings settings;
    QStringList tool_ids;
    std::vector<double> tool_force_limits_n;  // empty: settings.limits.max_tool_force_n for every tool
    app::ExpertRules rules;
  };
  quint64 startBuild(std::function<Request()> make_request);
  void started();
  void stopped();

  QThreadPool* pool_;
  EngineChannel channel_;
  std::shared_ptr<ExpertSession> session_;
  QStringList tool_ids_;
  app::ExpertRules rules_;
  std::shared_ptr<std::atomic<bool>> build_cancel_ = std::make_shared<std::atomic<bool>>(false);
  quint64 build_generation_ = 0;
  quint64 refine_generation_ = 0;
  int running_ = 0;
};

}  // namespace mx::gui

Q_DECLARE_METATYPE(mx::gui::RefinementOutcome)

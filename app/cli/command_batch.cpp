// millexpert-cli batch MANIFEST.json --out RESULTS.jsonl [--shard I/N] [--shard-count N] [--jobs K]
// Runs one computation (lobes, rank, pareto, point) over the cases of a manifest (services/batch_cases.h,
// docs/shop-scale.md), this process's shard of them, and appends one JSON line per case to RESULTS:
//   {"case", "hash", "project", "tool", "machine", "material", "operation", "result"} (+ "error")
// "result" is what the single command prints for the case (null when it printed nothing); "error"
// ({"exit_code", "message"}) is what it would have exited with. A case already in RESULTS (same hash)
// is skipped, and a torn last line is cut off and its case redone. Prints {"cases", "shard",
// "shard_cases", "skipped", "computed", "failed", "out"}.
// Exit 2: a bad manifest, project, flag or option, or a listed tool a project lacks (before any case
// runs); exit 1: some case failed (its line says why; the other cases still ran).
#include <QProcessEnvironment>
#include <atomic>
#include <exception>
#include <thread>

#include "cli/batch_case_runner.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "services/batch_cases.h"
#include "services/batch_manifest.h"
#include "services/batch_results.h"
#include "services/batch_sections.h"
#include "services/batch_shard.h"

namespace mx::app {

namespace {

constexpr int kMaxJobs = 256;

struct BatchPlan {
  BatchManifest manifest;
  std::vector<Project> projects;
  BatchSections sections;
  std::vector<BatchCase> cases;  // this shard's
  qint64 total_cases = 0;
  BatchShard shard;
};

struct BatchTally {
  std::atomic<qint64> skipped{0};
  std::atomic<qint64> computed{0};
  std::atomic<qint64> failed{0};
};

std::vector<Project> loadProjects(const BatchManifest& manifest, const QString& out) {
  OutputPaths paths;
  paths.output("--out", out);
  std::vector<Project> projects;
  for (qsizetype i = 0; i < manifest.projects.size(); ++i)
    projects.push_back(paths.loadProject(manifest.projectPath(i)));
  return projects;
}

BatchPlan planBatch(const QCommandLineParser& parser, const QString& manifest_path, const QString& out) {
  BatchPlan plan;
  OutputPaths().input("MANIFEST", manifest_path).output("--out", out).check();
  plan.manifest = readBatchManifest(manifest_path);
  plan.projects = loadProjects(plan.manifest, out);
  checkListedTools(plan.manifest, plan.projects);
  plan.total_cases = countBatchCases(plan.manifest, plan.projects);
  plan.sections = readBatchSections(plan.manifest);
  std::optional<QString> shard_flag;
  if (parser.isSet("shard")) shard_flag = parser.value("shard");
  const std::optional<int> shard_count = integerOption(parser, "shard-count", 1, static_cast<int>(kMaxShards));
  plan.shard = batchShardFrom(shard_flag, shard_count, QProcessEnvironment::systemEnvironment());
  plan.cases = expandBatchCases(plan.manifest, plan.projects, [&](qint64 c) { return plan.shard.owns(c); });
  return plan;
}

QJsonValue orNull(const QJsonValue& value) {
  return value.isUndefined() ? QJsonValue() : value;
}

QJsonObject caseLine(const BatchPlan& plan, const BatchCase& c, const QJsonObject& inputs, const QString& hash,
                     const BatchCaseOutcome& outcome) {
  const QJsonObject document = inputs.value("document").toObject();
  QJsonObject line{{"case", c.index},
                   {"hash", hash},
                   {"project", plan.manifest.projects[c.project]},
                   {"tool", inputs.value("tool")},
                   {"machine", orNull(document.value("machine"))},
                   {"material", orNull(document.value("material"))},
                   {"operation", orNull(document.value("operation"))},
                   {"result", outcome.result ? QJsonValue(*outcome.result) : QJsonValue()}};
  if (outcome.error) line.insert("error", *outcome.error);
  return line;
}

// Computes the case unless its hash is done, and appends its line.
void runCase(const BatchPlan& plan, const BatchCaseRunner& runner, const BatchCase& c, const QSet<QString>& done,
             BatchResultsWriter& writer, BatchTally& tally) {
  const Project project =
      batchCaseProject(plan.manifest, plan.sections, plan.projects[static_cast<std::size_t>(c.project)], c);
  const QJsonObject inputs = batchCaseInputs(plan.manifest, c, project);
  const QString hash = batchCaseHash(inputs);
  if (done.contains(hash)) {
    ++tally.skipped;
    return;
  }
  const BatchCaseOutcome outcome = runner.run(project, c.tool);
  writer.append(caseLine(plan, c, inputs, hash, outcome));
  ++tally.computed;
  if (outcome.error) ++tally.failed;
}

// `jobs` threads take the cases in order; each case works on its own copy of its project. The first
// write failure stops every thread and is rethrown.
void runCases(const BatchPlan& plan, const BatchCaseRunner& runner, const QSet<QString>& done,
              BatchResultsWriter& writer, int jobs, BatchTally& tally) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    for (std::size_t i = next++; i < plan.cases.size() && !stop; i = next++) {
      try {
        runCase(plan, runner, plan.cases[i], done, writer, tally);
      } catch (...) {
        const std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        stop = true;
      }
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

int runBatchCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Run one computation over the cases of a batch manifest (docs/shop-scale.md).");
  parser.addHelpOption();
  parser.addOptions({
      {"out", "The results file (JSON Lines), appended; cases already in it are skipped.", "RESULTS.jsonl"},
      {"shard", "Run shard I of N: the cases c with c mod N = I (default: Slurm's or Kubernetes' index).", "I/N"},
      {"shard-count", "The shard count N of a Kubernetes Indexed Job (its completions); with JOB_COMPLETION_INDEX.",
       "N"},
      {"jobs", "Cases computed at once, 1-256 (default 1).", "K"},
  });
  const QString manifest_path = parseSubcommand(parser, arguments, "MANIFEST", "The batch manifest (JSON).");
  const QString out = requiredOption(parser, "out");
  const int jobs = integerOption(parser, "jobs", 1, kMaxJobs).value_or(1);
  const BatchPlan plan = planBatch(parser, manifest_path, out);
  const BatchCaseRunner runner(plan.manifest.computation, plan.manifest.options);
  const QSet<QString> done = resumeBatchResults(out);
  BatchResultsWriter writer(out);
  BatchTally tally;
  runCases(plan, runner, done, writer, jobs, tally);
  printJson(
      {{"cases", plan.total_cases},
       {"shard", QJsonObject{{"index", plan.shard.index}, {"count", plan.shard.count}, {"source", plan.shard.source}}},
       {"shard_cases", static_cast<qint64>(plan.cases.size())},
       {"skipped", tally.skipped.load()},
       {"computed", tally.computed.load()},
       {"failed", tally.failed.load()},
       {"out", out}});
  return tally.failed > 0 ? kExitComputationFailed : kExitOk;
}

}  // namespace mx::app

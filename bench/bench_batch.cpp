// Batch throughput (docs/shop-scale.md, docs/performance.md): cases per second of `millexpert-cli
// batch`, in-process as the command runs them, for lobes (one case per tool) and rank (one case per
// project, its 100 tools together, with the Rule 5 refinement) over a 1000-tool manifest: 10 projects
// of 100 tools (a project holds at most 100), the tools of projects/library-20-tools.mxproj repeated
// with their modes shifted 0.03 % per repetition. --jobs 1 and 2; each iteration runs one shard into a
// fresh results file.
#include <benchmark/benchmark.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>

#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "document/project.h"

namespace {

constexpr int kProjects = 10;
constexpr int kToolsPerProject = 100;

class ThousandTools {
 public:
  ThousandTools() {
    const mx::app::Project library = mx::app::loadProject(MX_PROJECTS_DIR "/library-20-tools.mxproj");
    QJsonArray projects;
    for (int p = 0; p < kProjects; ++p) {
      mx::app::Project project = library;
      project.tools.clear();
      for (int i = 0; i < kToolsPerProject; ++i) {
        const int k = p * kToolsPerProject + i;
        mx::app::ToolSpec tool = library.tools[static_cast<std::size_t>(k) % library.tools.size()];
        tool.id = QString("T%1").arg(k, 4, 10, QChar('0'));
        const double shift = 1.0 + 0.0003 * (k / static_cast<int>(library.tools.size()));
        for (auto* modes : {&tool.modes_x, &tool.modes_y})
          for (mx::app::ModeSpec& m : *modes) m.freq_Hz *= shift;
        project.tools.push_back(tool);
      }
      const QString name = QString("library-%1.mxproj").arg(p);
      mx::app::saveProject(project, dir_.filePath(name));
      projects.append(name);
    }
    writeManifest("lobes.json", {{"computation", "lobes"}, {"projects", projects}});
    writeManifest("rank.json", {{"computation", "rank"}, {"projects", projects}});
  }
  QString path(const QString& name) const { return dir_.filePath(name); }

 private:
  void writeManifest(const QString& name, const QJsonObject& manifest) {
    QFile f(dir_.filePath(name));
    if (!f.open(QIODevice::WriteOnly)) std::abort();
    f.write(QJsonDocument(manifest).toJson());
  }
  QTemporaryDir dir_;
};

const ThousandTools& manifests() {
  static const ThousandTools instance;
  return instance;
}

// One shard of the manifest: lobes 0/10 (100 cases), rank 0/5 (2 cases of 100 tools each).
void BM_Batch(benchmark::State& state, const char* computation, const char* shard, int cases_per_run) {
  const QString manifest = manifests().path(QString("%1.json").arg(computation));
  const QString out = manifests().path(QString("%1-out.jsonl").arg(computation));
  const QString jobs = QString::number(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    QFile::remove(out);
    state.ResumeTiming();
    mx::app::JsonCapture quiet;  // the summary line
    const int code =
        mx::app::runBatchCommand({"millexpert-cli", manifest, "--out", out, "--shard", shard, "--jobs", jobs});
    if (code != 0) state.SkipWithError("batch failed");
  }
  state.counters["cases_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * cases_per_run, benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK_CAPTURE(BM_Batch, lobes, "lobes", "0/10", 100)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_Batch, rank, "rank", "0/5", 2)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

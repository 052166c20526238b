// A real single-node Slurm cluster (docs/shop-scale.md, shared/notes/real-services.md): munged,
// slurmctld and slurmd started in the foreground on this machine, with a generated slurm.conf in a
// scratch folder. The shipped packaging/slurm/millexpert-batch.sbatch runs a 4-task array over a
// 40-case manifest; its merged table and its lines (sorted by case) must equal a single-process run's.
// Every daemon started is stopped by its process id, also on failure. A daemon that cannot start fails
// the test with its log's tail.
#include <signal.h>
#include <unistd.h>

#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRandomGenerator>
#include <QSysInfo>
#include <QThread>
#include <memory>

#include "support/batch_manifests.h"
#include "support/cli_runner.h"
#include "support/enterable_folders.h"
#include "support/loopback_port.h"
#include "test_registry.h"

namespace {

constexpr int kStartTimeoutMs = 20000;
constexpr int kJobTimeoutMs = 60000;

// The tail of a log file, for failure messages.
QString tail(const QString& path, qsizetype chars = 1500) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return QString("(%1: no log)").arg(path);
  return QString("%1:\n%2").arg(path, QString::fromUtf8(f.readAll().right(chars)));
}

QString slurmConf(const QString& s, const QString& host, const QList<int>& ports) {
  return QString(
             "ClusterName=mx\nSlurmctldHost=%2\nSlurmctldPort=%3\nSlurmdPort=%4\nSlurmUser=root\nSlurmdUser=root\n"
             "AuthType=auth/munge\nAuthInfo=socket=%1/munge/munge.socket\nCredType=cred/munge\n"
             "StateSaveLocation=%1/state\nSlurmdSpoolDir=%1/spool\nSlurmctldPidFile=%1/run/slurmctld.pid\n"
             "SlurmdPidFile=%1/run/slurmd.pid\nSlurmctldLogFile=%1/log/slurmctld.log\n"
             "SlurmdLogFile=%1/log/slurmd.log\nProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
             "SelectType=select/cons_tres\nSelectTypeParameters=CR_Core\nSchedulerType=sched/builtin\n"
             "ReturnToService=2\nMpiDefault=none\nJobAcctGatherType=jobacct_gather/none\n"
             "NodeName=%2 CPUs=2 RealMemory=2000 State=UNKNOWN\n"
             "PartitionName=debug Nodes=%2 Default=YES MaxTime=INFINITE State=UP\n")
      .arg(s, host)
      .arg(ports[0])
      .arg(ports[1]);
}

// 2 tools x 2 machines x 5 materials x 2 operations = 40 lobes cases on a coarse grid.
QJsonObject fortyCaseManifest() {
  QJsonObject manifest = mx::test::lobesManifest();
  QJsonArray materials;
  for (int i = 0; i < 5; ++i)
    materials.append(QJsonObject{{"name", QString("M%1").arg(i)}, {"Kt_N_mm2", 500 + 100 * i}, {"Kr", 0.3}});
  manifest["materials"] = materials;
  manifest["operations"] =
      QJsonArray{QJsonObject{{"milling", "down"}, {"radial_immersion", 0.5}, {"max_feed_per_tooth_mm", 0.15}},
                 QJsonObject{{"milling", "up"}, {"radial_immersion", 1.0}, {"max_feed_per_tooth_mm", 0.2}}};
  manifest["options"] = QJsonObject{{"from", 4000}, {"to", 18000}, {"step", 500}};
  return manifest;
}

// The daemons of the cluster, each a foreground child stopped by its pid.
class Cluster {
 public:
  explicit Cluster(const QString& folder) : s_(folder) {
    env_ = QProcessEnvironment::systemEnvironment();
    env_.insert("SLURM_CONF", s_ + "/slurm.conf");
  }
  ~Cluster() { stop(); }

  const QProcessEnvironment& environment() const { return env_; }
  QString path(const QString& name) const { return s_ + "/" + name; }

  // Starts a daemon; its stdout and stderr go to log/NAME.out.
  bool start(const QString& name, const QString& program, const QStringList& arguments) {
    auto p = std::make_unique<QProcess>();
    p->setProcessEnvironment(env_);
    p->setProcessChannelMode(QProcess::MergedChannels);
    p->setStandardOutputFile(path("log/" + name + ".out"));
    p->start(program, arguments);
    const bool started = p->waitForStarted(5000);
    daemons_.push_back(std::move(p));
    return started;
  }

  bool running() const {
    for (const auto& p : daemons_)
      if (p->state() != QProcess::Running) return false;
    return true;
  }

  // The last started first: slurmd, slurmctld, munged. True when every one has ended.
  bool stop() {
    bool ended = true;
    for (std::size_t i = daemons_.size(); i-- > 0;) {
      QProcess& p = *daemons_[i];
      if (p.state() == QProcess::NotRunning) continue;
      ::kill(static_cast<pid_t>(p.processId()), SIGTERM);
      if (!p.waitForFinished(5000)) {
        ::kill(static_cast<pid_t>(p.processId()), SIGKILL);
        ended = p.waitForFinished(2000) && ended;
      }
    }
    daemons_.clear();
    return ended;
  }

 private:
  QString s_;
  QProcessEnvironment env_;
  std::vector<std::unique_ptr<QProcess>> daemons_;
};

struct ToolRun {
  int code = -1;
  QString out;
};

ToolRun runTool(const QProcessEnvironment& env, const QString& program, const QStringList& arguments) {
  QProcess p;
  p.setProcessEnvironment(env);
  p.setProcessChannelMode(QProcess::MergedChannels);
  p.start(program, arguments);
  p.waitForFinished(15000);
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAll()).trimmed()};
}

QStringList missingPrograms() {
  QStringList missing;
  const QList<std::pair<const char*, const char*>> programs{
      {"munged", MX_MUNGED_PATH},  {"slurmctld", MX_SLURMCTLD_PATH}, {"slurmd", MX_SLURMD_PATH},
      {"sbatch", MX_SBATCH_PATH},  {"squeue", MX_SQUEUE_PATH},       {"sinfo", MX_SINFO_PATH},
      {"scancel", MX_SCANCEL_PATH}};
  for (const auto& [name, path] : programs)
    if (QString(path).isEmpty() || QString(path).endsWith("NOTFOUND")) missing.append(name);
  return missing;
}

}  // namespace

class TestBatchSlurm : public QObject {
  Q_OBJECT
 private slots:
  void jobArrayEqualsOneProcess() {
    QElapsedTimer clock;
    clock.start();
    const QStringList missing = missingPrograms();
    if (!missing.isEmpty())
      QFAIL(qPrintable(QString("not found at configure time: %1 (install slurm-wlm and munge, then re-run cmake)")
                           .arg(missing.join(", "))));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // slurmd and munged check the folders above their files; QTemporaryDir makes 0700.
    QVERIFY(QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner |
                                                  QFileDevice::ReadGroup | QFileDevice::ExeGroup |
                                                  QFileDevice::ReadOther | QFileDevice::ExeOther));
    mx::test::makeEnterableByAll(dir.path());  // and the folders above it (a 0700 TMPDIR)
    const QString s = dir.path();
    for (const char* sub : {"state", "spool", "log", "run", "munge", "results"}) QVERIFY(QDir(s).mkpath(sub));
    const QList<int> ports = [] {  // reserved together (two distinct ports), released for the daemons
      const mx::test::LoopbackPort controller, node;
      return QList<int>{controller.port(), node.port()};
    }();
    QVERIFY(ports[0] > 0 && ports[1] > 0);
    const QString host = QSysInfo::machineHostName().section('.', 0, 0);  // hostname -s
    mx::test::writeText(dir, "slurm.conf", slurmConf(s, host, ports).toUtf8());
    QFile key(dir.filePath("munge/munge.key"));
    QVERIFY(key.open(QIODevice::WriteOnly));
    QByteArray secret(1024, '\0');
    QRandomGenerator::system()->generate(secret.begin(), secret.end());
    key.write(secret);
    key.close();
    QVERIFY(key.setPermissions(QFileDevice::ReadOwner));

    Cluster cluster(s);
    const QString m = s + "/munge/";
    if (!cluster.start(
            "munged", MX_MUNGED_PATH,
            {"-F", "--key-file=" + m + "munge.key", "--socket=" + m + "munge.socket", "--pid-file=" + m + "munged.pid",
             "--log-file=" + m + "munged.log", "--seed-file=" + m + "seed"}))
      QFAIL(qPrintable("munged did not start\n" + tail(s + "/log/munged.out")));
    for (int i = 0; i < 50 && !QFile::exists(m + "munge.socket"); ++i) QThread::msleep(100);
    if (!QFile::exists(m + "munge.socket"))
      QFAIL(qPrintable("munged made no socket\n" + tail(s + "/log/munged.out") + "\n" + tail(m + "munged.log")));
    const QString conf = cluster.path("slurm.conf");
    if (!cluster.start("slurmctld", MX_SLURMCTLD_PATH, {"-D", "-f", conf}))
      QFAIL(qPrintable("slurmctld did not start\n" + tail(s + "/log/slurmctld.out")));
    if (!cluster.start("slurmd", MX_SLURMD_PATH, {"-D", "-f", conf}))
      QFAIL(qPrintable("slurmd did not start\n" + tail(s + "/log/slurmd.out")));

    QString state;
    for (QElapsedTimer wait; !wait.isValid() || wait.elapsed() < kStartTimeoutMs; QThread::msleep(250)) {
      if (!wait.isValid()) wait.start();
      state = runTool(cluster.environment(), MX_SINFO_PATH, {"-h", "-o", "%t"}).out;
      if (state == "idle" || !cluster.running()) break;
    }
    if (state != "idle")
      QFAIL(qPrintable(QString("the node is not idle (sinfo: '%1')\n%2\n%3\n%4\n%5")
                           .arg(state, tail(s + "/log/slurmctld.log"), tail(s + "/log/slurmd.log"),
                                tail(s + "/log/slurmctld.out"), tail(s + "/log/slurmd.out"))));

    mx::test::copyRubio(dir);
    const QString manifest = mx::test::writeManifest(dir, fortyCaseManifest());
    QProcessEnvironment job_env = cluster.environment();
    job_env.insert("MILLEXPERT_CLI", MX_CLI_PATH);
    const ToolRun submitted = runTool(job_env, MX_SBATCH_PATH,
                                      {"--parsable", "--array=0-3", "--cpus-per-task=1",
                                       "--output=" + s + "/log/%A_%a.log", MX_SLURM_SCRIPT, manifest, s + "/results"});
    QVERIFY2(submitted.code == 0, qPrintable(submitted.out));
    const QString job = submitted.out.section(';', 0, 0);
    bool finished = false;
    for (QElapsedTimer wait; !wait.isValid() || wait.elapsed() < kJobTimeoutMs; QThread::msleep(250)) {
      if (!wait.isValid()) wait.start();
      const ToolRun queue = runTool(cluster.environment(), MX_SQUEUE_PATH, {"-h", "-j", job});
      if (queue.code == 0 && queue.out.isEmpty()) {
        finished = true;
        break;
      }
    }
    if (!finished) {
      runTool(cluster.environment(), MX_SCANCEL_PATH, {job});
      QFAIL(qPrintable("the array did not finish within 60 s\n" + tail(s + "/log/slurmctld.log")));
    }

    QStringList shard_files;
    for (int task = 0; task < 4; ++task) {
      const QString file = QString("%1/results/results-%2.jsonl").arg(s).arg(task);
      const QString log = QString("%1/log/%2_%3.log").arg(s, job).arg(task);
      QVERIFY2(QFile::exists(file), qPrintable(tail(log)));
      QCOMPARE(mx::test::sortedLines(file).size(), 10);  // cases task, task + 4, ...
      for (const QJsonObject& line : mx::test::jsonLines(file)) QCOMPARE(line["case"].toInteger() % 4, qint64(task));
      shard_files.append(file);
    }

    const QString single = dir.filePath("single.jsonl");
    const mx::test::CliRun one = mx::test::runCli({"batch", manifest, "--out", single, "--jobs", "2"});
    QCOMPARE(one.code, 0);
    QCOMPARE(one.json["computed"].toInt(), 40);
    QStringList from_array;
    for (const QString& file : shard_files) from_array += mx::test::sortedLines(file);
    std::sort(from_array.begin(), from_array.end());
    const QStringList from_one = mx::test::sortedLines(single);
    QCOMPARE(from_array.size(), 40);
    for (qsizetype i = 0; i < from_one.size(); ++i) QCOMPARE(from_array[i], from_one[i]);

    const mx::test::CliRun merged =
        mx::test::runCli(QStringList{"batch-merge"} + shard_files + QStringList{"--out", dir.filePath("array.json")});
    QCOMPARE(merged.code, 0);
    QCOMPARE(mx::test::runCli({"batch-merge", single, "--out", dir.filePath("one.json")}).code, 0);
    const QJsonArray array_rows = mx::test::readJson(dir.filePath("array.json"))["rows"].toArray();
    const QJsonArray one_rows = mx::test::readJson(dir.filePath("one.json"))["rows"].toArray();
    QCOMPARE(array_rows.size(), 20);  // 2 machines x 5 materials x 2 operations
    for (qsizetype i = 0; i < one_rows.size(); ++i) QCOMPARE(array_rows[i].toObject(), one_rows[i].toObject());

    QVERIFY(cluster.stop());
    qInfo("Slurm test: %.1f s", static_cast<double>(clock.elapsed()) / 1000.0);
  }
};

MX_REGISTER_TEST(TestBatchSlurm)
#include "test_batch_slurm.moc"

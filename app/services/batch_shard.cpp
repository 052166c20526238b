#include "services/batch_shard.h"

#include "services/service_errors.h"

namespace mx::app {

namespace {

qint64 integerIn(const QString& name, const QString& text, qint64 min, qint64 max) {
  bool ok = false;
  const qint64 value = text.trimmed().toLongLong(&ok);
  if (!ok || value < min || value > max)
    throw InputError(QString("%1 = '%2': must be an integer in [%3, %4]").arg(name, text).arg(min).arg(max));
  return value;
}

BatchShard fromFlag(const QString& text) {
  const QStringList parts = text.split('/');
  if (parts.size() != 2) throw InputError(QString("--shard = '%1': must be I/N, shard I of N (0 <= I < N)").arg(text));
  const qint64 count = integerIn("--shard N", parts[1], 1, kMaxShards);
  return {integerIn("--shard I", parts[0], 0, count - 1), count, "--shard"};
}

BatchShard fromSlurm(const QProcessEnvironment& env) {
  const QString id = env.value("SLURM_ARRAY_TASK_ID");
  const QString min = env.value("SLURM_ARRAY_TASK_MIN", "0");
  const qint64 count = integerIn("SLURM_ARRAY_TASK_COUNT", env.value("SLURM_ARRAY_TASK_COUNT"), 1, kMaxShards);
  // ID - MIN numbers the tasks 0..COUNT-1 only for an array without a step (--array=A-B).
  const qint64 index = integerIn("SLURM_ARRAY_TASK_ID", id, 0, kMaxShards * 100) -
                       integerIn("SLURM_ARRAY_TASK_MIN", min, 0, kMaxShards * 100);
  if (index < 0 || index >= count)
    throw InputError(QString("SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN = %1: must be in [0, %2] "
                             "(SLURM_ARRAY_TASK_COUNT - 1); submit the array without a step, --array=0-%2")
                         .arg(index)
                         .arg(count - 1));
  return {index, count, "Slurm"};
}

BatchShard fromKubernetes(const QProcessEnvironment& env, qint64 count) {
  return {integerIn("JOB_COMPLETION_INDEX", env.value("JOB_COMPLETION_INDEX"), 0, count - 1), count, "Kubernetes"};
}

}  // namespace

BatchShard batchShardFrom(const std::optional<QString>& shard_flag, const std::optional<qint64>& shard_count,
                          const QProcessEnvironment& environment) {
  if (shard_flag && shard_count)
    throw InputError("--shard-count: only with JOB_COMPLETION_INDEX, not with --shard I/N");
  if (shard_flag) return fromFlag(*shard_flag);
  if (environment.contains("SLURM_ARRAY_TASK_ID") && !shard_count) return fromSlurm(environment);
  if (environment.contains("JOB_COMPLETION_INDEX")) {
    if (!shard_count)
      throw InputError("JOB_COMPLETION_INDEX is set: give the Indexed Job's completions as --shard-count N");
    return fromKubernetes(environment, *shard_count);
  }
  if (shard_count)
    throw InputError("--shard-count: JOB_COMPLETION_INDEX is not set (a Kubernetes Indexed Job sets it)");
  return {0, 1, "none"};
}

}  // namespace mx::app

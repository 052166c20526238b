#pragma once
// Which cases a batch process runs: case c belongs to shard c mod N. The shard comes from --shard I/N,
// else from the scheduler's environment: a Slurm job array (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN
// of SLURM_ARRAY_TASK_COUNT) or a Kubernetes Indexed Job (JOB_COMPLETION_INDEX of --shard-count N);
// else the whole manifest.
#include <QProcessEnvironment>
#include <QString>
#include <optional>

namespace mx::app {

struct BatchShard {
  qint64 index = 0;
  qint64 count = 1;
  QString source;  // "--shard", "Slurm", "Kubernetes" or "none", for messages
  bool owns(qint64 case_index) const { return case_index % count == index; }
};

inline constexpr qint64 kMaxShards = 1000000;

// Throws InputError naming the flag or the variable, its value and the allowed range.
BatchShard batchShardFrom(const std::optional<QString>& shard_flag, const std::optional<qint64>& shard_count,
                          const QProcessEnvironment& environment);

}  // namespace mx::app

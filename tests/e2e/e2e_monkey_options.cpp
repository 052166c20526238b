#include "e2e_monkey_options.h"

namespace mx::e2e {

namespace {
constexpr int kMaxSeconds = 24 * 3600;
const QString kDefaultProject = QStringLiteral(MX_PROJECTS_DIR "/rubio-pareto-case.mxproj");
}  // namespace

QString MonkeyOptions::replayCommand() const {
  QString command = QString("xvfb-run -a -s \"-screen 0 1920x1080x24\" millexpert-e2e monkey --seed %1 --seconds %2")
                        .arg(seed)
                        .arg(seconds);
  if (project != kDefaultProject) command += " --project " + project;
  return command;
}

MonkeyOptions parseMonkeyOptions(const QStringList& arguments) {
  MonkeyOptions options;
  options.project = kDefaultProject;
  for (qsizetype i = 0; i < arguments.size(); i += 2) {
    const QString& flag = arguments[i];
    if (i + 1 >= arguments.size()) {
      options.error = flag + " needs a value";
      return options;
    }
    const QString& value = arguments[i + 1];
    bool ok = false;
    if (flag == "--seed") {
      options.seed = value.toULongLong(&ok);
    } else if (flag == "--seconds") {
      options.seconds = value.toInt(&ok);
      ok = ok && options.seconds >= 1 && options.seconds <= kMaxSeconds;
    } else if (flag == "--project") {
      options.project = value;
      ok = !value.isEmpty();
    } else {
      options.error = "unknown flag " + flag;
      return options;
    }
    if (!ok) {
      options.error = QString("%1 %2: expected %3")
                          .arg(flag, value.left(80),
                               flag == "--seed"      ? "an unsigned 64-bit integer"
                               : flag == "--seconds" ? QString("1 to %1").arg(kMaxSeconds)
                                                     : "a project file");
      return options;
    }
  }
  return options;
}

}  // namespace mx::e2e

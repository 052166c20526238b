#include "cli/cli_application.h"

#include <QTextStream>
#include <exception>

#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "core/invalid_input.h"
#include "document/project.h"
#include "document/shortened_text.h"
#include "mx_version.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {
const char* kUsage =
    "usage: millexpert-cli <command> PROJECT [options]\n"
    "commands:\n"
    "  check     validate a project file\n"
    "  lobes     stability lobes of one tool (--tool ID [--method zoa|sdm] ...)\n"
    "  simulate  time-domain simulation of one cutting point (--tool ID --speed --depth --feed ...)\n"
    "  point     stability margin, Delta N_s, ROS, power and MRR of one operating point\n"
    "  rank      expert system: tool ranking, q* and q** ([--c c1,c2,c3] [--cr ...] [--no-simulation])\n"
    "  weights-sweep  minimum tool cost against the weights (--c3 V | --simplex STEP)\n"
    "  history   Rule 14 learning database, newest first ([--tool ID] [--db FILE] [--add-json JSON])\n"
    "  pareto    Pareto expert system ([--w tol,mrr,surf,ros] [--fine] [--require mrr_cm3_s=LO:HI] [--auto-weights])\n"
    "  sdnrp     Cus & Zuperl force/roughness control (--ra UM [--seconds 15] [--csv FILE] [--no-control])\n"
    "  override  optimise a G-code program: override PROGRAM.nc PROJECT --out OUT.nc [--csv FILE]\n"
    "  supervise supervisory control of face milling (--controller none|smc1|smc2 [--csv FILE]\n"
    "            [--time-constant-ms MS] [--reset-feed current|model])\n"
    "  control   adaptive force control under beta-FROH (--beta B [--csv FILE] | --sweep-beta FROM:TO:STEP |\n"
    "            --beta-study [--tau-c-ms LIST] [--sweep-beta FROM:TO:STEP])\n"
    "  frf-info  the FRF datasets of a tap-test file: frf-info FILE [--quantity Q]\n"
    "  frf-fit   modes fitted to one FRF of a tap-test file: frf-fit FILE [--modes N] [--method lscf|peak]\n"
    "  frf-export  a tool's FRF as UFF 58/58b or CSV (--tool ID --output FILE)\n"
    "  coefficients  cutting coefficients from test cuts: coefficients FORCES.csv --diameter MM --teeth N\n"
    "            --depth MM [--immersion A_D] [--milling up|down] [--speed RPM --feed MM_PER_TOOTH]\n"
    "            (a record: CSV time_s,Fx_N,Fy_N,Fz_N, or UFF 58 type 1 time responses of Fx, Fy, Fz)\n"
    "  materials the materials library [--library FILE]; --apply ID --into PROJECT copies an entry into\n"
    "            the project's material section\n"
    "  batch     one computation over a manifest's cases: batch MANIFEST.json --out RESULTS.jsonl\n"
    "            [--shard I/N] [--jobs K] [--shard-count N] (docs/shop-scale.md)\n"
    "  batch-merge  one table from batch results: batch-merge RESULTS.jsonl... --out SUMMARY.json\n"
    "            [--csv FILE] [--html FILE]\n"
    "An output (--csv, --out, --output, --db) is never an input of the command, another output, or an\n"
    "existing file that is not a regular file (device, FIFO, directory, socket): exit 2 before any work.\n"
    "Run 'millexpert-cli <command> --help' or 'millexpert-cli help <command>' for the options of a command.\n";

void printError(const QString& message) {
  QTextStream(stderr) << "millexpert-cli: " << message << Qt::endl;
}

// QCommandLineParser names the executable in its usage line; the command belongs there too.
QString commandUsage(const QString& command, const QString& help) {
  const qsizetype options = help.indexOf(" [options]");
  const qsizetype eol = help.indexOf('\n');
  if (!help.startsWith("Usage: ") || options < 0 || options > eol) return help;
  return "Usage: millexpert-cli " + command + help.mid(options);
}
}  // namespace

int runCli(const QStringList& arguments) {
  if (arguments.size() < 2 || arguments.at(1) == "--help" || arguments.at(1) == "-h") {
    QTextStream(arguments.size() < 2 ? stderr : stdout) << kUsage;
    return arguments.size() < 2 ? kExitBadInput : kExitOk;
  }
  if (arguments.at(1) == "--version") {
    QTextStream(stdout) << "millexpert-cli " << kVersion << Qt::endl;
    return kExitOk;
  }
  const bool help = arguments.at(1) == "help";  // "help COMMAND" is "COMMAND --help"
  if (help && arguments.size() < 3) {
    QTextStream(stdout) << kUsage;
    return kExitOk;
  }
  const QString& command = arguments.at(help ? 2 : 1);
  QStringList rest = arguments;
  rest.removeAt(1);  // keep argv[0] for QCommandLineParser
  if (help) rest = QStringList{arguments.at(0), QStringLiteral("--help")};
  try {
    const CliCommand* handler = findCommand(command);
    if (handler == nullptr)
      throw CliError(QString("unknown command %1\n%2").arg(quoted(command), kUsage), kExitBadInput);
    return handler->run(rest);
  } catch (const CliHelp& e) {
    QTextStream(stdout) << commandUsage(command, QString::fromStdString(e.what()));
    return kExitOk;
  } catch (const CliError& e) {
    printError(QString::fromStdString(e.what()));
    return e.code;
  } catch (const ProjectError& e) {
    printError(QString::fromStdString(e.what()));
    return e.exitCode();
  } catch (const InputError& e) {
    printError(QString::fromStdString(e.what()));
    return e.exitCode();
  } catch (const ComputationError& e) {
    printError(QString::fromStdString(e.what()));
    return e.exitCode();
  } catch (const InvalidInput& e) {
    printError(QString::fromStdString(e.what()));
    return kExitBadInput;
  } catch (const std::exception& e) {
    printError(QString("computation failed: %1").arg(e.what()));
    return kExitComputationFailed;
  }
}

}  // namespace mx::app

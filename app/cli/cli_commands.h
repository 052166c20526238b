#pragma once
// The registry of CLI subcommands. Each command parses its own flags and prints one JSON object.
#include <QString>
#include <QStringList>

namespace mx::app {

struct CliCommand {
  const char* name;
  const char* summary;
  int (*run)(const QStringList& arguments);  // arguments[0] is the program name
};

const CliCommand* findCommand(const QString& name);

int runCheckCommand(const QStringList& arguments);
int runLobesCommand(const QStringList& arguments);
int runSimulateCommand(const QStringList& arguments);
int runPointCommand(const QStringList& arguments);
int runRankCommand(const QStringList& arguments);
int runWeightsSweepCommand(const QStringList& arguments);
int runHistoryCommand(const QStringList& arguments);
int runParetoCommand(const QStringList& arguments);
int runControlCommand(const QStringList& arguments);
int runSdnrpCommand(const QStringList& arguments);
int runOverrideCommand(const QStringList& arguments);
int runSuperviseCommand(const QStringList& arguments);
int runFrfInfoCommand(const QStringList& arguments);
int runFrfFitCommand(const QStringList& arguments);
int runFrfExportCommand(const QStringList& arguments);
int runLibraryImportCommand(const QStringList& arguments);
int runLibraryExportCommand(const QStringList& arguments);
int runCoefficientsCommand(const QStringList& arguments);
int runMaterialsCommand(const QStringList& arguments);
int runBatchCommand(const QStringList& arguments);
int runBatchMergeCommand(const QStringList& arguments);

}  // namespace mx::app

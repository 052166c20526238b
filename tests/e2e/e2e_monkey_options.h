#pragma once
// The monkey's command line: millexpert-e2e monkey [--seed N] [--seconds S] [--project FILE].
// The seed fixes every random choice, so a failing run replays with the same arguments (the widgets'
// timing still varies with the machine: a replay takes the same path as long as the window does).
#include <QString>
#include <QStringList>
#include <QtGlobal>

namespace mx::e2e {

struct MonkeyOptions {
  quint64 seed = 1;
  int seconds = 30;
  QString project;  // a copy of it is driven; the bundled Pareto case by default
  QString error;    // why the arguments were refused ("" when they were not)

  QString replayCommand() const;  // the command line that runs this monkey again
};

// From the arguments after "monkey".
MonkeyOptions parseMonkeyOptions(const QStringList& arguments);

}  // namespace mx::e2e

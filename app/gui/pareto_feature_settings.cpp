// ParetoFeature: Settings > Learning database... The dialog edits the location; this host checks it
// with the services' rules, tests the connection on the learning client's pool (never on the GUI
// thread: an unreachable server takes its connect_timeout) and stores the choice.
#include <QAction>
#include <stdexcept>

#include "learning_client.h"
#include "learning_database_dialog.h"
#include "pareto_feature.h"
#include "services/learning_database.h"
#include "services/learning_location.h"

namespace mx::gui {

namespace {

// The dialog's Validator: the problem parseLearningLocation() names, "" when the location is valid.
QString learningLocationProblem(const QString& location) {
  try {
    app::parseLearningLocation(location);
    return {};
  } catch (const std::invalid_argument& e) {
    return QString::fromStdString(e.what());
  }
}

}  // namespace

void ParetoFeature::addSettingsActions(QMenu* settings) {
  QAction* a = settings->addAction(tr("&Learning database..."), this, [this] { openLearningDatabaseSettings(); });
  a->setObjectName("learningDatabaseAction");
  const QString tip =
      tr("Rule 14 learning database: an SQLite file or a shared PostgreSQL server, with a connection test");
  a->setToolTip(tip);
  a->setStatusTip(tip);
}

widgets::LearningDatabaseDialog* ParetoFeature::openLearningDatabaseSettings() {
  if (!learning_dialog_) {
    auto* parent = qobject_cast<QWidget*>(this->parent());
    learning_dialog_ =
        new widgets::LearningDatabaseDialog(app::LearningDatabase::defaultPath(), learningLocationProblem, parent);
    connect(learning_dialog_, &widgets::LearningDatabaseDialog::testRequested, learning_,
            [this](const QString& location) { learning_->testConnection(location); });
    connect(learning_, &LearningClient::tested, learning_dialog_,
            [this](quint64, bool ok, const QString& text) { learning_dialog_->showTestResult(ok, text); });
    connect(learning_dialog_, &QDialog::accepted, this, [this] {
      const QString location = learning_dialog_->location();
      // The default file is stored as "no choice", so it follows the default wherever that is.
      app::setConfiguredLearningDatabase(location == app::LearningDatabase::defaultPath() ? QString() : location);
      setLearningDatabasePath(location);
    });
  }
  learning_dialog_->setLocation(learningDatabasePath());
  learning_dialog_->open();
  return learning_dialog_;
}

}  // namespace mx::gui

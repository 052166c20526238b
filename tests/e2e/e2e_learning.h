#pragma once
// The learning-database pictures: the configured database (the default file in the scenario's private
// HOME) holding points of three machines, the history dock showing them, and Settings > Learning
// database with the answer of its Test connection.
class QDialog;

namespace mx::gui {
class MainWindow;
}

namespace mx::e2e {

class Report;

// Stores the same nine points of three machines (one unnamed) every time: their uids are fixed.
void seedLearningDatabase(Report& report);
// Waits until the history dock shows the seeded points.
void waitForLearningHistory(gui::MainWindow& window, int timeout_ms);
// Settings > Learning database... with its Test connection answered.
QDialog* learningDatabaseDialog(gui::MainWindow& window, int timeout_ms);

}  // namespace mx::e2e

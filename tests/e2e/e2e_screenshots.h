#pragma once
// Scenario "screenshots DIR [FILE...]": the README's and docs' pictures (e2e_screenshots.cpp).
#include <QString>
#include <QStringList>

namespace mx::e2e {

class Report;

// Writes every shot (or the named ones) into `folder`.
void runScreenshots(Report& report, const QString& folder, const QStringList& only);
QStringList screenshotNames();

}  // namespace mx::e2e

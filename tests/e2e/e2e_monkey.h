#pragma once
// Scenario "monkey": random clicks, drags, wheel turns, key presses, edits and combo changes on every
// dock and the central widget of the real window, for a bounded time from a fixed seed. It checks that
// the event loop never stalls, that no number shows as nan or inf, and that the project then saves and
// reads back as the window holds it (docs/testing.md, "Monkey test").
#include <QString>

#include "e2e_monkey_options.h"
#include "e2e_report.h"

namespace mx::e2e {

void runMonkey(Report& report, const QString& xdotool, const MonkeyOptions& options, const QString& log_path);

}  // namespace mx::e2e

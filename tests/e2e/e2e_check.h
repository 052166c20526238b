#pragma once
// Scenario "check", the CTest entry e2e.window (e2e_check.cpp).
namespace mx::e2e {

class Report;
class XInput;

void runCheck(Report& report, XInput& input);

}  // namespace mx::e2e

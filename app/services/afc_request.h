#pragma once
// Heidenhain AFC settings from the project, shared by `millexpert-cli override --afc` and the GUI's
// part-program panel: the chosen point is the project's operating_point (its tool, speed, depth and feed
// per tooth; the expert speed replaces its speed when given); the prediction there (model/cutting_force.h)
// gives AFC-LOAD and FMAX (engine/machining/afc_table.h); the tool number is the program's first
// TOOL CALL number, else the tool's place in the project (1-based).
#include <QString>
#include <optional>

#include "document/project.h"
#include "gcode/gcode_program.h"
#include "machining/afc_table.h"

namespace mx::app {

struct AfcOutcome {
  AfcTeachIn teach_in;
  QString tool;         // project tool id
  int tool_number = 0;  // T in the tool table
  OperatingPointSpec point;
};

// The AFC setting's name for a tool: "MX_" and the tool id, letters, digits and '_' only, cut to the
// table's 10 characters.
QString afcNameFor(const QString& tool_id);

// Throws ProjectError when the project has no operating_point, InputError for a program that is not
// Heidenhain or a bad OVLD, and what afcFromPrediction throws.
AfcOutcome afcFromProject(const Project& project, const GcodeProgram& program, std::optional<double> speed_rpm,
                          char ovld = 'E');

}  // namespace mx::app

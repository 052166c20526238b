#pragma once
// Modal interpretation of a Heidenhain Klartext program (GcodeInterpreter dispatches to it), giving the
// same per-block motions as the ISO interpreter:
//  - BEGIN PGM ... MM | INCH sets the units (INCH: coordinates in inch, F in inch/min);
//  - TOOL CALL ... S sets the spindle speed, its F the feed that "F AUTO" stands for;
//  - L: a straight move to X, Y, Z (absolute) or IX, IY, IZ (incremental); FMAX makes it a rapid for this
//    block only; F is modal;
//  - CC: the circle centre (X, Y or IX, IY from the current position; missing axes: the current one);
//  - C: an arc about CC to X, Y (Z: helix), DR- clockwise, DR+ counter-clockwise; C to the start: a
//    full circle;
//  - CR: an arc of radius R (R+ at most half a turn, R- more) to X, Y, direction DR;
//  - CT: the arc that leaves tangentially from the previous element to X, Y;
//  - RND and CHF round or chamfer the corner between two elements: no path of their own here (their
//    length is the corner's, a few tenths of a millimetre), and their F holds for the corner only.
// Blocks the reader marked as not modelled (cycle calls, APPR/DEP, polar LP/CP) give no motion.
#include "gcode/gcode_interpreter.h"

namespace mx {

GcodeRun interpretHeidenhain(const GcodeProgram& program, const GcodeInterpreterSettings& settings);

}  // namespace mx

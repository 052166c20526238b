#pragma once
// Heidenhain AFC (adaptive feed control) settings for a tool, from our prediction at the chosen point.
// The control learns a reference spindle power (AFC-LOAD, in the tool table; normally by a teach-in cut)
// and then scales the programmed feed so that the spindle power stays at it. A row of the table AFC.TAB
// holds the control setting the tool table's AFC column names. Fields, as the TNC user manual describes
// them (docs/part-programs.md, "Heidenhain AFC"):
//   NR    row number;
//   AFC   name of the control setting (the tool table's AFC column refers to it);
//   FMIN  feed [% of the programmed feed] at which the control reacts to an overload: below it the
//         overload reaction OVLD follows;
//   FMAX  highest feed [% of the programmed feed] the control may raise to in the material;
//   FIDL  feed [%] while the tool is not cutting (in the air);
//   FENT  feed [%] while the tool enters or leaves the material;
//   OVLD  reaction to an overload (spindle power above the reference while the feed is at FMIN for more
//         than a second): M machine maker's macro, S immediate NC stop, F NC stop once the tool is
//         retracted, E error message only, L lock the tool, - none;
//   POUT  spindle power [% of the reference] below which the control sees the tool leave the material;
//   SENS  sensitivity (aggressiveness) of the control loop [%], 50 slow to 200 very aggressive;
//   PLC   value passed to the PLC at the start of the machining step.
// What we set from the prediction: AFC-LOAD is the predicted mean spindle power at the point; FMAX is
// the largest feed the tool's chip-load limit and the spindle's available power allow (the peak power
// grows about linearly with the feed per tooth), at least 100 %. The others keep the manual's
// recommended values unless given: FMIN 50 %, FIDL and FENT 100 % (our override already sets the entry
// and air feeds), POUT 8 %, SENS 100 %, PLC 0.
#include <string>

namespace mx {

struct AfcSetting {
  int nr = 0;
  std::string name;  // at most kAfcNameLength characters
  double fmin_percent = 50.0;
  double fmax_percent = 100.0;
  double fidl_percent = 100.0;
  double fent_percent = 100.0;
  char ovld = 'E';
  double pout_percent = 8.0;
  double sens_percent = 100.0;
  int plc = 0;
};

inline constexpr std::size_t kAfcNameLength = 10;

struct AfcPrediction {
  double mean_power_W = 0.0;          // predicted mean spindle power at the point (AFC-LOAD)
  double peak_power_W = 0.0;          // predicted peak spindle power at the point
  double available_power_W = 0.0;     // the spindle's available power at the speed; <= 0: no limit
  double feed_per_tooth_m = 0.0;      // at the point
  double max_feed_per_tooth_m = 0.0;  // the tool's chip-load limit; <= 0: none
};

struct AfcTeachIn {
  AfcSetting setting;
  double afc_load_W = 0.0;      // AFC-LOAD, the reference spindle power
  std::string fmax_limited_by;  // "chip load", "spindle power", or "none" (FMAX left at 100 %)
};

// Throws InvalidInput for a prediction without a positive power or feed, an OVLD outside MSFEL-, or a
// name that is empty or longer than kAfcNameLength.
AfcTeachIn afcFromPrediction(const AfcPrediction& prediction, const std::string& name, char ovld = 'E');

// The AFC.TAB file with one row, in the control's table format (BEGIN line, column header, rows, [END]).
std::string afcTableText(const AfcSetting& setting);
// A tool-table excerpt (TOOL.TAB columns T, NAME, AFC, AFC-LOAD [kW]) for the tool.
std::string afcToolTableText(int tool_number, const std::string& tool_name, const AfcTeachIn& teach_in);

}  // namespace mx

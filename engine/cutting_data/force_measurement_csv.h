#pragma once
// Test-cut files for the cutting coefficients (coefficient_fit.h), comma-separated, one header line:
//   mean forces, one row per cut:  feed_mm_per_tooth,Fx_N,Fy_N,Fz_N
//   a dynamometer record of one cut: time_s,Fx_N,Fy_N,Fz_N   (times strictly increasing)
// Forces on the tool in the axes and signs of our force model (milling_setup.h: x along the feed, y
// normal to it in the plane, z along F_a). Line ends "\n" or "\r\n", blanks around fields, blank lines
// and a UTF-8 byte order mark are accepted. Errors are InvalidInput "<source>: line <n>: <what>".
#include <string>
#include <string_view>
#include <vector>

#include "cutting_data/coefficient_fit.h"

namespace mx {

inline constexpr std::string_view kMeanForcesHeader = "feed_mm_per_tooth,Fx_N,Fy_N,Fz_N";
inline constexpr std::string_view kForceRecordHeader = "time_s,Fx_N,Fy_N,Fz_N";

// The cuts of a mean-forces file, in SI (feed in m). A feed per tooth must be in [1e-6, 10] mm, a force
// finite and within 1e7 N.
std::vector<TestCut> readMeanForcesCsv(std::string_view bytes, const std::string& source_name);

// True when the first non-blank line starts with the field time_s: a record; else a mean-forces file.
bool isForceRecordCsv(std::string_view bytes);

struct ForceRecord {
  std::vector<double> t_s, fx_n, fy_n, fz_n;
};
// The bounds of a record's values, for every record format (force_record_uff.h too).
inline constexpr double kMaxTestCutForceN = 1e7;
inline constexpr double kMaxRecordTimeS = 1e6;

// A dynamometer record: at least two samples, times within ±1e6 s and strictly increasing, forces as above.
ForceRecord readForceRecordCsv(std::string_view bytes, const std::string& source_name);

// The mean forces of a record over the most whole spindle revolutions that fit from its first sample
// (trapezoidal rule, the end of the last revolution interpolated): the runout and the tooth-to-tooth
// differences average out only over whole revolutions. InvalidInput naming the record's length and the
// revolution when not even one fits, or for a speed outside (0, 1e6] rpm.
TestCut meanOverRevolutions(const ForceRecord& record, double spindle_rpm, double feed_per_tooth_m,
                            const std::string& source_name);

}  // namespace mx

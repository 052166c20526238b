#pragma once
// The project document (.mxproj, JSON). Field names are a fixed interface: scripts outside the repository read them.
// Values are kept in the file's shop units here; setupFor() converts one tool to the engine's SI.
#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>
#include <stdexcept>
#include <vector>

#include "document/process_sections.h"
#include "model/milling_setup.h"
#include "model/spindle_power.h"

namespace mx::app {

// A bad project or a request the project cannot serve. exitCode() is the CLI code (2 = bad input).
class ProjectError : public std::runtime_error {
 public:
  explicit ProjectError(const QString& message) : std::runtime_error(message.toStdString()) {}
  int exitCode() const { return 2; }
};

struct ModeSpec {
  double freq_Hz = 0.0;
  double damping_pct = 0.0;
  double stiffness_N_per_um = 0.0;
  QJsonObject unknown;  // the file's keys this build does not know; they stay with this mode
  bool operator==(const ModeSpec&) const = default;
};

// A tap-test FRF of one tool axis (docs/measured-dynamics.md): dataset `dataset` (0-based, among the
// file's FRF datasets) of `file`, a UFF 58/58b or CSV file.
struct FrfRefSpec {
  QString file;                     // as written: relative to the project file's folder, or absolute
  std::optional<int> dataset;       // default 0
  std::optional<QString> quantity;  // "receptance", "mobility", "accelerance"; required for CSV
  QJsonObject unknown;
  int datasetIndex() const { return dataset.value_or(0); }
  bool operator==(const FrfRefSpec&) const = default;
};

// A cutting preset of a CAM tool library (Fusion 360 start values): the recommended cut for one
// material. Informative: the ranking computes its own speeds and feeds.
struct CuttingPresetSpec {
  QString name;
  std::optional<double> speed_rpm;
  std::optional<double> surface_speed_m_min;
  std::optional<double> feed_per_tooth_mm;
  std::optional<double> feed_mm_min;
  std::optional<double> axial_depth_mm;
  std::optional<double> radial_depth_mm;
  QJsonObject unknown;
  bool operator==(const CuttingPresetSpec&) const = default;
};

// The tool's record in the CAM library it was imported from (docs/tool-libraries.md), kept whole so
// that an export back to that format returns what MillExpert does not map (holders, post-processor
// numbers, vendor data).
struct ToolOriginSpec {
  QString format;  // "fusion", "freecad" or "linuxcnc"
  QJsonObject data;
  bool operator==(const ToolOriginSpec&) const = default;
};

struct ToolSpec {
  QString id;
  int teeth = 0;
  double diameter_mm = 0.0;
  double helix_deg = 0.0;
  // Cutter geometry (tool_geometry.h): one angle between consecutive teeth per tooth, summing to 360;
  // one radial edge offset per tooth. Absent: uniform pitch, no runout.
  std::optional<std::vector<double>> pitch_deg;
  std::optional<std::vector<double>> runout_um;
  std::optional<double> Kt_N_mm2;  // overrides material.Kt_N_mm2
  std::optional<double> Kr;        // overrides material.Kr
  std::optional<double> Kte_N_mm;  // override the material's edge and axial coefficients
  std::optional<double> Kre_N_mm;
  std::optional<double> Ka_N_mm2;
  std::optional<double> Kae_N_mm;
  std::optional<double> radial_depth_mm;  // overrides the operation's radial engagement
  std::optional<double> max_force_N;      // F_allow: allowable peak resultant force (Rule 3, breakage)
  std::vector<ModeSpec> modes_x;
  std::vector<ModeSpec> modes_y;
  std::optional<FrfRefSpec> frf_x;  // measured dynamics; an axis may have modes, an FRF or both
  std::optional<FrfRefSpec> frf_y;
  // Geometry and cutting data from CAM tool libraries; shown and exported, not used by the models.
  std::optional<QString> type;  // "flat end mill", "ball end mill", ...
  std::optional<double> flute_length_mm;
  std::optional<double> overall_length_mm;
  std::optional<double> stickout_mm;
  std::optional<double> corner_radius_mm;
  std::vector<CuttingPresetSpec> cutting_data;
  std::optional<ToolOriginSpec> origin;
  QJsonObject unknown;  // the file's keys this build does not know; they stay with this tool
  bool hasFrf() const { return frf_x.has_value() || frf_y.has_value(); }
  bool operator==(const ToolSpec&) const = default;
};

// A row of the spindle's power curve (machine.spindle_curve).
struct SpindleCurveRowSpec {
  double speed_rpm = 0.0;
  double power_W = 0.0;
  QJsonObject unknown;  // the file's keys this build does not know; they stay with this row
  bool operator==(const SpindleCurveRowSpec&) const = default;
};

// The available spindle power is min(spindle_power_W, 2 pi N max_torque_Nm / 60, spindle_curve(N)).
struct MachineSpec {
  std::optional<QString> name;  // shown to operator rules as machine.name
  double spindle_power_W = 0.0;
  std::optional<double> max_spindle_rpm;  // no limit when absent
  std::optional<double> max_feed_mm_s;    // feed-drive limit; no limit when absent
  std::optional<double> max_torque_Nm;    // torque limit below the base speed; no limit when absent
  std::optional<std::vector<SpindleCurveRowSpec>> spindle_curve;  // >= 2 rows by increasing speed
  bool operator==(const MachineSpec&) const = default;
};

// The work material (docs/project-file.md, "material"): the cutting coefficients K_tc (Kt_N_mm2) and
// K_rc / K_tc (Kr) of the seeds, and optionally the edge and axial coefficients and the process damping
// C_i; absent ones are 0. `library` names the entry of resources/materials.json it was copied from.
struct MaterialSpec {
  QString name;
  double Kt_N_mm2 = 0.0;
  double Kr = 0.0;
  std::optional<double> Kte_N_mm;
  std::optional<double> Kre_N_mm;
  std::optional<double> Ka_N_mm2;
  std::optional<double> Kae_N_mm;
  std::optional<double> process_damping_N_per_m;
  std::optional<QString> library;
  bool operator==(const MaterialSpec&) const = default;
};

struct OperationSpec {
  MillingDirection milling = MillingDirection::Up;
  std::optional<double> radial_immersion;  // a/D in (0, 1]
  std::optional<double> radial_depth_mm;   // exactly one of the two is given
  double max_feed_per_tooth_mm = 0.0;
  bool operator==(const OperationSpec&) const = default;
};

struct ExpertGridSpec {
  double speed_from_rpm = 1000.0;
  double speed_to_rpm = 12000.0;
  double speed_step_rpm = 100.0;
  int depth_divisions = 10;
  double feed_step_mm = 0.01;
  std::optional<bool> modal_candidate_speeds;  // add the Rule 7.2 speeds; default true
  bool operator==(const ExpertGridSpec&) const = default;
};

// Chatter observed at the machine with one tool (expert.reported_chatter): the evidence of Rule 6.
struct ChatterReportSpec {
  QString tool;                   // a tool id of the project
  double speed_rpm = 0.0;         // where it chattered
  double depth_mm = 0.0;          // axial depth of cut
  std::optional<double> freq_Hz;  // the chatter frequency, when measured
  QJsonObject unknown;            // the file's keys this build does not know; they stay with this row
  bool operator==(const ChatterReportSpec&) const = default;
};

// The Rule 5 pattern search around q* (engine/expert/rule5_search.h); an absent step is derived from
// the grid (speed step / 4, depth step / 2, feed step / 2).
struct Rule5SearchSpec {
  std::optional<double> speed_step_rpm;  // (0, 1e5]
  std::optional<double> depth_step_mm;   // (0, 100]
  std::optional<double> feed_step_mm;    // (0, 10]
  std::optional<int> max_iterations;     // [0, 1000], default 20; 0: the best K points by C only
  bool operator==(const Rule5SearchSpec&) const = default;
};

struct ExpertSpec {
  double delta_per_s = 0.0;
  double alpha = 1.0;
  std::vector<double> c{0.2, 0.725, 0.075};
  std::vector<double> cr{0.8, 0.1, 0.1};
  std::vector<double> ct{0.5, 0.5};
  std::vector<double> cf{0.5, 0.5};
  std::optional<ExpertGridSpec> grid;
  std::optional<QString> method;                    // "zoa" (default) or "sdm"
  std::optional<int> simulated_points;              // K of Rule 5, [1, 1000], default 12
  std::optional<int> max_malfunction_iterations;    // bound of the Rule 6 loop, [0, 10000], default 200
  std::vector<ChatterReportSpec> reported_chatter;  // Rule 6 evidence; empty: none
  std::optional<Rule5SearchSpec> rule5_search;
  bool operator==(const ExpertSpec&) const = default;
};

// The operating point the project opens at (operating_point): the GUI writes its point and active tool
// here on save; the CLI's point and simulate take it for the flags left out.
struct OperatingPointSpec {
  QString tool;                    // a tool id of the project
  double speed_rpm = 0.0;          // (0, 1e5]
  double depth_mm = 0.0;           // axial depth of cut, (0, 1000]
  double feed_mm_per_tooth = 0.0;  // (0, 10]
  bool operator==(const OperatingPointSpec&) const = default;
};

struct Project {
  QString name;
  std::optional<MachineSpec> machine;
  std::optional<MaterialSpec> material;
  std::optional<OperationSpec> operation;
  std::vector<ToolSpec> tools;
  std::optional<ExpertSpec> expert;
  std::optional<ControlSection> control;
  std::optional<SdnrpSection> sdnrp;
  std::optional<ForceControlSection> force_control;
  std::optional<PartProgramSection> part_program;
  std::optional<SupervisorSection> supervisor;
  std::optional<ParetoSection> pareto;
  std::optional<QStringList> operator_rules;  // one rule per element (Rule 18)
  std::optional<OperatingPointSpec> operating_point;
  // The keys of the file this build does not know, per object, at every level but the elements of
  // arrays (tools, modes, depth steps, events, chart steps and transitions keep theirs in their
  // structs, so that they follow their element on reorder).
  QJsonObject document;
  // The absolute folder that relative FRF paths resolve against (the project file's folder; the
  // working directory when empty). Not written: saving to another folder rewrites the paths instead.
  QString folder;

  const ToolSpec* findTool(const QString& id) const;  // nullptr when absent
  // The engine description of one tool in this project's cut (SI). Throws ProjectError naming the
  // missing tool or section ("tool 'X' not found", "section 'material' is missing", ...).
  MillingSetup setupFor(const QString& toolId) const;
  // A tool's allowable peak resultant force F_allow [N] (Pareto Rules 3 and 7.1): its max_force_N, else
  // the control section's breakage limit safety_factor * breakage_force_N (the force reference's own
  // convention, control/force_reference.h), else +inf (no limit).
  double toolForceLimitN(const ToolSpec& tool) const;
  const MachineSpec& requireMachine() const;  // throws ProjectError if the section is absent
  const ExpertSpec& requireExpert() const;
};

// The machine's available spindle power P_av(N) in SI: spindle_power_W, max_torque_Nm and
// spindle_curve (rpm to rev/s); the limits a file leaves out are +inf.
SpindlePowerCurve spindlePowerOf(const MachineSpec& machine);
// P_av in W at speed_rpm of a project's machine; +inf without a machine section.
double availablePowerW(const std::optional<MachineSpec>& machine, double speed_rpm);

// Parse and validate; throws ProjectError whose message names the field path, the value and the
// allowed range, e.g. "tools[0].modes_x[0].damping_pct = 150: must be in (0, 100)".
Project projectFromJson(const QJsonObject& root);
// loadProject sets folder to the file's folder.
Project loadProject(const QString& path);
// The tools of a tool library: a JSON array of tools, or an object with a "tools" array (a project
// file). Throws ProjectError on a syntax error or naming the field path, as projectFromJson does.
std::vector<ToolSpec> toolsFromJson(const QByteArray& text);
// Back to JSON: the typed values, written over the unknown keys of each object.
QJsonObject projectToJson(const Project& project);
// One tool as an element of the project file's tools array, and back. toolFromJson checks the types
// (messages start with `path`), not the ranges: validateTools does.
QJsonObject toolToJson(const ToolSpec& tool);
ToolSpec toolFromJson(const QJsonObject& object, const QString& path);
// Atomic save (QSaveFile: write, then rename). Relative FRF paths are written relative to the new
// file's folder (withFrfPathsRelativeTo). Throws ProjectError on I/O failure.
void saveProject(const Project& project, const QString& path);

}  // namespace mx::app

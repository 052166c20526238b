// changedSections: an edit of each section gives exactly that section's flag (the weights, beta and
// the rest of their sections apart), several edits give their union, and a no-op gives none.
#include <QJsonObject>
#include <functional>

#include "document/project.h"
#include "document/project_changes.h"
#include "test_registry.h"

using namespace mx::app;

namespace {

using S = ProjectSection;

Project example(const char* name) {
  return loadProject(QString(MX_PROJECTS_DIR "/") + name);
}

// One project with every section: the Pareto case plus the other examples' process sections.
Project everySection() {
  Project p = example("rubio-pareto-case.mxproj");
  p.control = example("rubio2006-adaptive-control.mxproj").control;
  const Project cz = example("cus-zuperl-sdnrp.mxproj");
  p.sdnrp = cz.sdnrp;
  p.force_control = cz.force_control;
  p.part_program = cz.part_program;
  p.supervisor = example("landers-face-milling.mxproj").supervisor;
  p.operator_rules = QStringList{"IF tool.teeth >= 2 THEN speed_rpm <= 9000"};
  p.operating_point = OperatingPointSpec{p.tools[0].id, 3000.0, 1.0, 0.1};
  p.document.insert("x_note", "every section");
  return p;
}

struct Edit {
  const char* name;
  std::function<void(Project&)> apply;
  ProjectChanges expected;
};

const std::vector<Edit>& edits() {
  static const std::vector<Edit> table{
      {"name", [](Project& p) { p.name += " 2"; }, S::Name},
      {"tool teeth", [](Project& p) { p.tools[0].teeth = 2; }, S::Tools},
      {"tool mode", [](Project& p) { p.tools[0].modes_x[0].freq_Hz += 1.0; }, S::Tools},
      {"tool removed", [](Project& p) { p.tools.pop_back(); }, S::Tools},
      {"machine power", [](Project& p) { p.machine->spindle_power_W += 100.0; }, S::Machine},
      {"material Kt", [](Project& p) { p.material->Kt_N_mm2 += 10.0; }, S::Material},
      {"operation feed", [](Project& p) { p.operation->max_feed_per_tooth_mm += 0.01; }, S::Operation},
      {"expert alpha", [](Project& p) { p.expert->alpha = 0.9; }, S::Expert},
      {"expert c",
       [](Project& p) {
         p.expert->c = {0.5, 0.25, 0.25};
       },
       S::ExpertWeights},
      {"expert cf",
       [](Project& p) {
         p.expert->cf = {0.9, 0.1};
       },
       S::ExpertWeights},
      {"expert removed", [](Project& p) { p.expert.reset(); }, S::Expert | S::ExpertWeights},
      {"control rpm", [](Project& p) { *p.control->spindle_rpm += 100.0; }, S::Control},
      {"control beta", [](Project& p) { p.control->beta = 0.5; }, S::ControlBeta},
      {"sdnrp Ra", [](Project& p) { p.sdnrp->ra_um = 1.5; }, S::Sdnrp},
      {"force_control F_ref", [](Project& p) { p.force_control->reference_force_N = 321.0; }, S::ForceControl},
      {"part_program speed", [](Project& p) { p.part_program->speed_rpm = 4321.0; }, S::PartProgram},
      {"supervisor rpm", [](Project& p) { p.supervisor->spindle_rpm = 777.0; }, S::Supervisor},
      {"pareto taylor", [](Project& p) { p.pareto->taylor->K *= 2.0; }, S::Pareto},
      {"pareto weights",
       [](Project& p) {
         p.pareto->weights = std::vector<double>{0.1, 0.2, 0.3, 0.4};
       },
       S::ParetoWeights},
      {"operator rules", [](Project& p) { p.operator_rules->append("IF tool.teeth >= 4 THEN depth_mm <= 2"); },
       S::Rules},
      {"unknown key", [](Project& p) { p.document.insert("x_vendor", "ACME"); }, S::Unknown},
      {"operating point", [](Project& p) { p.operating_point->depth_mm = 1.5; }, S::OperatingPoint},
      {"operating point removed", [](Project& p) { p.operating_point.reset(); }, S::OperatingPoint},
      {"tools and machine",
       [](Project& p) {
         p.tools[0].diameter_mm += 1.0;
         p.machine->max_spindle_rpm = 9000.0;
       },
       S::Tools | S::Machine},
  };
  return table;
}

}  // namespace

class TestProjectChanges : public QObject {
  Q_OBJECT

 private slots:
  void eachEditFlagsItsSection_data() {
    QTest::addColumn<int>("row");
    for (std::size_t i = 0; i < edits().size(); ++i) QTest::newRow(edits()[i].name) << static_cast<int>(i);
  }
  void eachEditFlagsItsSection() {
    QFETCH(int, row);
    const Edit& e = edits()[static_cast<std::size_t>(row)];
    const Project before = everySection();
    Project after = before;
    e.apply(after);
    QCOMPARE(changedSections(before, after), e.expected);
    QCOMPARE(changedSections(after, before), e.expected);  // undo: the same sections
  }

  void aNoOpChangesNothing() {
    const Project p = everySection();
    Project same = p;
    same.tools[0].teeth = p.tools[0].teeth;
    QCOMPARE(changedSections(p, same), ProjectChanges());
    QCOMPARE(changedSections(Project(), Project()), ProjectChanges());
  }

  void aNewProjectDiffersInEverySectionItHas() {
    // Every flag is one of kAllSections (what load and new emit).
    const ProjectChanges all = changedSections(Project(), everySection());
    QCOMPARE(all & kAllSections, all);
    QCOMPARE(all, kAllSections);
  }
};

MX_REGISTER_TEST(TestProjectChanges)
#include "test_project_changes.moc"

// featuresToRecompute: which views re-run for which changed sections. The cut (tools, machine,
// material, operation) re-runs every view built on it; the weights and beta only re-rank, re-choose
// or re-run the closed loop; the name and unknown keys re-run nothing.
#include "feature_recompute.h"
#include "test_registry.h"

using namespace mx;
using app::ProjectSection;
using gui::Feature;
using gui::Features;

namespace {
// Every view that depends on the cut.
constexpr Features kCutViews = Feature::Editors | Feature::Lobes | Feature::Simulation | Feature::ExpertSession |
                               Feature::ParetoStudy | Feature::ControlSweep | Feature::ControlRun |
                               Feature::PartProgram | Feature::Supervisor | Feature::FiredRules;
}  // namespace

class TestFeatureRecompute : public QObject {
  Q_OBJECT

 private slots:
  void featuresOfChanges_data() {
    QTest::addColumn<uint>("changes");
    QTest::addColumn<uint>("features");
    auto row = [](const char* name, app::ProjectChanges c, Features f) {
      QTest::newRow(name) << uint(c.toInt()) << uint(f.toInt());
    };
    row("nothing", {}, {});
    row("tools", ProjectSection::Tools, kCutViews | Feature::TapTest);
    row("machine", ProjectSection::Machine, kCutViews);
    row("material", ProjectSection::Material, kCutViews);
    row("operation", ProjectSection::Operation, kCutViews);
    row("expert", ProjectSection::Expert, Feature::Lobes | Feature::ExpertSession | Feature::ParetoStudy);
    row("expert weights", ProjectSection::ExpertWeights, Feature::ExpertRerank);
    row("expert and its weights", ProjectSection::Expert | ProjectSection::ExpertWeights,
        Feature::Lobes | Feature::ExpertSession | Feature::ParetoStudy);
    row("pareto", ProjectSection::Pareto, Feature::ParetoStudy);
    row("pareto weights", ProjectSection::ParetoWeights, Feature::ParetoChoice);
    row("pareto and its weights", ProjectSection::Pareto | ProjectSection::ParetoWeights, Feature::ParetoStudy);
    // The control section's breakage limit bounds Q of a tool without max_force_N (Rule 3).
    row("control", ProjectSection::Control,
        Feature::ControlSweep | Feature::ControlRun | Feature::PartProgram | Feature::ExpertSession |
            Feature::ParetoStudy);
    row("control beta", ProjectSection::ControlBeta, Feature::ControlRun);
    row("sdnrp", ProjectSection::Sdnrp, Feature::SurfaceFinish);
    row("force control", ProjectSection::ForceControl, Feature::PartProgram);
    row("part program", ProjectSection::PartProgram, Feature::PartProgram);
    row("supervisor", ProjectSection::Supervisor, Feature::Supervisor);
    row("operator rules", ProjectSection::Rules, Feature::ExpertSession | Feature::ParetoStudy | Feature::FiredRules);
    row("name", ProjectSection::Name, {});
    row("unknown keys", ProjectSection::Unknown, {});
    row("operating point", ProjectSection::OperatingPoint, {});
    row("weights of both systems", ProjectSection::ExpertWeights | ProjectSection::ParetoWeights,
        Feature::ExpertRerank | Feature::ParetoChoice);
    row("everything (load)", app::kAllSections, kCutViews | Feature::SurfaceFinish | Feature::TapTest);
  }
  void featuresOfChanges() {
    QFETCH(uint, changes);
    QFETCH(uint, features);
    const Features got = gui::featuresToRecompute(app::ProjectChanges::fromInt(changes));
    QCOMPARE(uint(got.toInt()), features);
  }
};

MX_REGISTER_TEST(TestFeatureRecompute)
#include "test_feature_recompute.moc"

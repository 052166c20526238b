// The supervised run's request from a project (landers-face-milling.mxproj): the face-milling model's
// integration step follows the spindle speed, so every supervisor.spindle_rpm of the documented range
// (1, 1e5] gives a process the model accepts.
#include "document/project.h"
#include "services/supervisor_request.h"
#include "supervisor/face_milling_process.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::app;

namespace {
const QString kProject = QStringLiteral(MX_PROJECTS_DIR "/landers-face-milling.mxproj");
constexpr double kDefaultStepS = FaceMillingParameters{}.step_s;
}  // namespace

class TestSupervisorRequest : public QObject {
  Q_OBJECT

 private slots:
  void stepFollowsTheToothPeriod_data() {
    QTest::addColumn<double>("rpm");
    QTest::newRow("1 rpm") << 1.0;
    QTest::newRow("1500 rpm") << 1500.0;
    QTest::newRow("30000 rpm") << 30000.0;
    QTest::newRow("the top, 1e5 rpm") << 1e5;
  }
  void stepFollowsTheToothPeriod() {
    QFETCH(double, rpm);
    Project project = loadProject(kProject);
    project.supervisor->spindle_rpm = rpm;
    const SupervisorRequest request = supervisorRequestFromProject(project, "none");
    const FaceMillingParameters& p = request.scenario.process;
    const double tooth_period = 60.0 / rpm / p.teeth;
    QCOMPARE(p.step_s, std::min(kDefaultStepS, tooth_period / 8.0));
    validateFaceMillingParameters(p);  // throws InvalidInput past the model's own bound
  }
};

MX_REGISTER_TEST(TestSupervisorRequest)
#include "test_supervisor_request.moc"

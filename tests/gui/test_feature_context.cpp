// FeatureContext: the active tool changes only to a new, non-empty id (one signal per change); the
// readout of the point is kept and announced; the document and units are the window's.
#include <QSignalSpy>
#include <QThreadPool>

#include "feature_context.h"
#include "test_registry.h"

using namespace mx;

namespace {
struct Fixture {
  app::ProjectDocument doc;
  widgets::DisplayUnits units;
  QThreadPool pool;
  gui::FeatureContext context{doc, units, &pool, nullptr};
};
}  // namespace

class TestFeatureContext : public QObject {
  Q_OBJECT
 private slots:
  void activeToolChangesOncePerNewId() {
    Fixture f;
    gui::FeatureContext& context = f.context;
    QSignalSpy changed(&context, &gui::FeatureContext::activeToolChanged);
    context.setActiveTool("R1");
    context.setActiveTool("R1");
    context.setActiveTool("");
    QCOMPARE(changed.count(), 1);
    QCOMPARE(context.activeTool(), QString("R1"));
    context.setActiveTool("R2");
    QCOMPARE(changed.count(), 2);
    QCOMPARE(changed.last().at(0).toString(), QString("R2"));
  }

  void readoutIsKeptAndAnnounced() {
    Fixture f;
    gui::FeatureContext& context = f.context;
    QSignalSpy changed(&context, &gui::FeatureContext::readoutChanged);
    widgets::PointReadout r;
    r.peak_power_w = 512.5;
    r.mrr_mm3_per_s = 1250.0;
    r.valid = true;
    context.setReadout(r);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(context.readout().peak_power_w, 512.5);
    QCOMPARE(context.readout().mrr_mm3_per_s, 1250.0);
    QCOMPARE(&context.document(), &f.doc);
    QCOMPARE(context.units(), &f.units);
    QCOMPARE(context.enginePool(), &f.pool);
  }
};

MX_REGISTER_TEST(TestFeatureContext)
#include "test_feature_context.moc"

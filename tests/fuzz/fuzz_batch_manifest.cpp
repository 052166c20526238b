// Fuzz target of the batch manifest (batchManifestFromJson, docs/shop-scale.md): any JSON a shop
// hands to `millexpert-cli batch`. A refused manifest throws InputError naming the field; an accepted
// one has a known computation and at least one project, and written back (batchManifestJson) it reads
// to the same manifest.
#include <QJsonDocument>
#include <cstdint>

#include "fuzz_check.h"
#include "services/batch_manifest.h"
#include "services/batch_manifest_json.h"
#include "services/service_errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using mx::fuzz::require;
  const QJsonDocument doc =
      QJsonDocument::fromJson(QByteArray(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size)));
  if (!doc.isObject()) return 0;
  mx::app::BatchManifest m;
  try {
    m = mx::app::batchManifestFromJson(doc.object(), "/shop/studies");
  } catch (const mx::app::InputError& e) {
    require(e.what()[0] != '\0', "a refusal says why");
    return 0;
  }
  require(QStringList({"lobes", "rank", "pareto", "point"}).contains(m.computation), "a known computation");
  require(!m.projects.isEmpty(), "at least one project");
  try {
    const mx::app::BatchManifest again = mx::app::batchManifestFromJson(mx::app::batchManifestJson(m), m.folder);
    require(again.computation == m.computation && again.projects == m.projects && again.tools == m.tools &&
                again.machines == m.machines && again.materials == m.materials && again.operations == m.operations &&
                again.options == m.options,
            "the written manifest reads back to the same");
  } catch (const mx::app::InputError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    mx::fuzz::brokenPromise("the written manifest reads back");
  }
  return 0;
}

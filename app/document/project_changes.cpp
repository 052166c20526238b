#include "document/project_changes.h"

#include <array>

namespace mx::app {

namespace {

// The expert inputs a re-ranking takes without a new session: the weights and the Rule 6 evidence.
struct ExpertRerankInputs {
  std::array<std::vector<double>, 4> weights;
  std::vector<ChatterReportSpec> reported_chatter;
  bool operator==(const ExpertRerankInputs&) const = default;
};

std::optional<ExpertSpec> withoutWeights(std::optional<ExpertSpec> e) {
  if (e) {
    e->c = e->cr = e->ct = e->cf = {};
    e->reported_chatter.clear();
  }
  return e;
}

std::optional<ExpertRerankInputs> weightsOf(const std::optional<ExpertSpec>& e) {
  if (!e) return std::nullopt;
  return ExpertRerankInputs{{e->c, e->cr, e->ct, e->cf}, e->reported_chatter};
}

std::optional<ControlSection> withoutBeta(std::optional<ControlSection> c) {
  if (c) c->beta.reset();
  return c;
}

std::optional<double> betaOf(const std::optional<ControlSection>& c) {
  return c ? c->beta : std::nullopt;
}

std::optional<ParetoSection> withoutWeights(std::optional<ParetoSection> p) {
  if (p) p->weights.reset();
  return p;
}

std::optional<std::vector<double>> weightsOf(const std::optional<ParetoSection>& p) {
  return p ? p->weights : std::nullopt;
}

}  // namespace

ProjectChanges changedSections(const Project& a, const Project& b) {
  ProjectChanges f;
  auto mark = [&f](bool differs, ProjectSection s) {
    if (differs) f |= s;
  };
  mark(a.name != b.name, ProjectSection::Name);
  mark(a.tools != b.tools, ProjectSection::Tools);
  mark(a.machine != b.machine, ProjectSection::Machine);
  mark(a.material != b.material, ProjectSection::Material);
  mark(a.operation != b.operation, ProjectSection::Operation);
  mark(withoutWeights(a.expert) != withoutWeights(b.expert), ProjectSection::Expert);
  mark(weightsOf(a.expert) != weightsOf(b.expert), ProjectSection::ExpertWeights);
  mark(withoutBeta(a.control) != withoutBeta(b.control), ProjectSection::Control);
  mark(betaOf(a.control) != betaOf(b.control), ProjectSection::ControlBeta);
  mark(a.sdnrp != b.sdnrp, ProjectSection::Sdnrp);
  mark(a.force_control != b.force_control, ProjectSection::ForceControl);
  mark(a.part_program != b.part_program, ProjectSection::PartProgram);
  mark(a.supervisor != b.supervisor, ProjectSection::Supervisor);
  mark(withoutWeights(a.pareto) != withoutWeights(b.pareto), ProjectSection::Pareto);
  mark(weightsOf(a.pareto) != weightsOf(b.pareto), ProjectSection::ParetoWeights);
  mark(a.operator_rules != b.operator_rules, ProjectSection::Rules);
  mark(a.document != b.document, ProjectSection::Unknown);
  mark(a.operating_point != b.operating_point, ProjectSection::OperatingPoint);
  return f;
}

}  // namespace mx::app

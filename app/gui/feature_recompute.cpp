#include "feature_recompute.h"

#include <utility>

namespace mx::gui {

namespace {

using S = app::ProjectSection;

// The cut: every engine model of a tool reads these (MillingSetup, machine limits).
constexpr app::ProjectChanges kCut = S::Tools | S::Machine | S::Material | S::Operation;

// Feature <- the sections its inputs come from.
const std::pair<Feature, app::ProjectChanges> kInputs[] = {
    {Feature::Editors, kCut},
    {Feature::Lobes, kCut | S::Expert},  // delta, alpha and the speed grid
    {Feature::Simulation, kCut},
    // The breakage limit bounds Q without max_force_N; the operator rules bound c and filter Q (Rule 18).
    {Feature::ExpertSession, kCut | S::Expert | S::Control | S::Rules},
    {Feature::ExpertRerank, S::ExpertWeights},
    {Feature::ParetoStudy, kCut | S::Expert | S::Pareto | S::Rules | S::Control},  // Rules 18 and 3 bound Q
    {Feature::ParetoChoice, S::ParetoWeights},
    {Feature::ControlSweep, kCut | S::Control},
    {Feature::ControlRun, kCut | S::Control | S::ControlBeta},
    {Feature::SurfaceFinish, S::Sdnrp},
    {Feature::PartProgram, kCut | S::Control | S::ForceControl | S::PartProgram},
    {Feature::Supervisor, kCut | S::Supervisor},
    {Feature::FiredRules, kCut | S::Rules},
    {Feature::TapTest, S::Tools},
};

}  // namespace

Features featuresToRecompute(app::ProjectChanges changes) {
  Features out;
  for (const auto& [feature, inputs] : kInputs)
    if (changes & inputs) out |= feature;
  // A new session or study ranks and chooses with the project's weights anyway.
  if (out & Feature::ExpertSession) out &= ~Features(Feature::ExpertRerank);
  if (out & Feature::ParetoStudy) out &= ~Features(Feature::ParetoChoice);
  return out;
}

}  // namespace mx::gui

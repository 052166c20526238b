#include "control/sampled_reference_model.h"

namespace mx {

SampledReferenceModel::SampledReferenceModel(double damping_ratio, double natural_frequency_rad_s, double beta)
    : damping_ratio_(damping_ratio),
      natural_frequency_rad_s_(natural_frequency_rad_s),
      model_(referenceModel(damping_ratio, natural_frequency_rad_s)),
      beta_(beta) {}

double SampledReferenceModel::output() const {
  return model_.C * x_;
}

void SampledReferenceModel::advance(double u_k, double period_s, double natural_frequency_rad_s) {
  if (natural_frequency_rad_s != natural_frequency_rad_s_) {
    // x = (F_m, dF_m/dt) / wn^2 (referenceModel): rescale so that F_m and its slope carry over
    const double ratio = natural_frequency_rad_s_ / natural_frequency_rad_s;
    x_ *= ratio * ratio;
    natural_frequency_rad_s_ = natural_frequency_rad_s;
    model_ = referenceModel(damping_ratio_, natural_frequency_rad_s);
  }
  // x(T) = Phi x + Psi B u_k + Xi B slope, with Xi = int_0^T (T - s) e^{As} ds the response to the ramp
  const ZohBlocks z = zohBlocks(model_, period_s);
  const double slope = beta_ * (u_k - u_prev_) / period_s;
  x_ = z.Phi * x_ + z.Psi * model_.B * u_k + z.Xi * model_.B * slope;
  u_prev_ = u_k;
}

}  // namespace mx

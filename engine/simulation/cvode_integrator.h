#pragma once
// RAII wrapper around SUNDIALS 6.4 CVODE (Adams-Moulton with the fixed-point nonlinear solver, for the
// non-stiff reference integrations; or, on request, BDF with Newton and a dense direct linear solver with a
// difference-quotient Jacobian, for stiff systems such as the feed drive + cutting process of the adaptive force
// controller). Every SUNDIALS return flag is checked; a failure throws CvodeError naming the call and the flag.
// SUNDIALS types stay out of this header.
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

namespace mx {

class CvodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CvodeIntegrator {
 public:
  // dy/dt = rhs(t, y, ydot); exceptions thrown by rhs are reported as an unrecoverable RHS failure
  // and rethrown from advanceTo.
  using Rhs = std::function<void(double t, const double* y, double* ydot)>;
  enum class Method { Adams, Bdf };

  CvodeIntegrator(Rhs rhs, double t0, const std::vector<double>& y0, double rtol, const std::vector<double>& atol,
                  long max_steps_per_call = 1000000, Method method = Method::Adams);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  // Integrates to exactly t (stop time set, so the RHS is never evaluated beyond t).
  void advanceTo(double t);
  double time() const;
  const double* state() const;
  long steps() const;  // internal CVODE steps taken so far

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mx

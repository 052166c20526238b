#pragma once
// The beta-FROH study (2006 paper, section 4): for several cutting-process time constants tau_c (the paper gives
// none), the beta below which a zero of H_beta leaves the unit circle (the paper: "beta < -0.6") and J_c(beta) of
// eq. 34 under both readings of its interpolated "discrete response" (the paper's figure 13: minimum "for a beta
// about -0.3"), with the argmin per (tau_c, reading) and whether it lands near the paper.
#include <vector>

#include "control/beta_sweep.h"

namespace mx {

// Eq. 34: J_c = int |F_p(t) - F^m_{p,beta}(t)| dt, F^m_{p,beta} "the discrete response with a linear interpolation".
enum class JcReading {
  PlantSamples,    // the plant output's own samples F_p(kT): the ripple between samples (ClosedLoopMetrics::Jc_N_s)
  ReferenceModel,  // the reference model's samples F_m(kT), the output of H_m,beta (Jc_model_N_s)
};
inline constexpr JcReading kJcReadings[] = {JcReading::PlantSamples, JcReading::ReferenceModel};
const char* jcReadingName(JcReading reading);  // "plant_samples" | "reference_model"

struct BetaFrohStudySettings {
  std::vector<double> tau_c_s;                  // empty: betaFrohStudyTauC(T) of the first depth's spindle period
  BetaSweepSettings sweep{-1.0, 1.0, 0.05, 0};  // the beta grid, shared by every tau_c
  double paper_best_beta = -0.3;                // figure 13
  double best_beta_tolerance = 0.15;            // half the spacing of the paper's betas -0.3, 0, 0.3 (figures 9-11)
  double paper_threshold_beta = -0.6;           // section 4.B
  double threshold_tolerance = 0.05;            // -0.6 is printed to one decimal
  double isolated_ratio = 0.05;                 // BetaFrohReadingResult::isolated_minimum
};

struct BetaFrohReadingResult {
  JcReading reading = JcReading::PlantSamples;
  std::vector<double> Jc_N_s;  // per beta of the grid
  // argmin over the betas with stable zeros that completed the workpiece (figure 13 spans "the range of beta where
  // the system has stable zeros"); found false if none.
  double best_beta = 0.0, best_Jc_N_s = 0.0;
  bool found = false;
  bool near_paper = false;  // |best_beta - paper| <= tolerance and the row's threshold near the paper's
  // Both admissible grid neighbours of the argmin exceed it by more than isolated_ratio: a one-point dip (one
  // run's RLS history), not the basin figure 13 draws.
  bool isolated_minimum = false;
};

struct BetaFrohStudyRow {
  double tau_c_s = 0.0, tau_c_over_T = 0.0;
  double threshold_beta = -1.0;  // closedLoopZeroThreshold: -1 when no zero leaves the unit circle in [-1, 0]
  bool threshold_found = false;
  double first_order_threshold_beta = 0.0;  // -(1-a)/(2(1-c)), a = e^{-T/tau_c}, c = tau_c (1-a)/T (drive neglected)
  bool threshold_near_paper = false;
  std::vector<bool> unstable_zero, completed;   // per beta of the grid
  std::vector<BetaFrohReadingResult> readings;  // in the order of kJcReadings
};

struct BetaFrohStudyMatch {
  std::size_t row = 0;
  JcReading reading = JcReading::PlantSamples;
  bool isolated_minimum = false;
};

struct BetaFrohStudyResult {
  double sampling_period_s = 0.0;  // T of the first depth step
  double default_tau_c_s = 0.0;    // processTimeConstant of the settings (what a run without the study uses)
  std::vector<double> beta;        // the grid
  std::vector<BetaFrohStudyRow> rows;
  std::vector<BetaFrohStudyMatch> matches;  // every (tau_c, reading) near the paper; possibly empty
  // tau_c whose threshold is exactly the paper's -0.6, and the tau_c interval whose thresholds lie within the
  // tolerance of it (the threshold falls monotonically from -1/2 at tau_c -> 0 to -1 at tau_c -> infinity).
  double tau_c_at_paper_threshold_s = 0.0;
  double tau_c_near_paper_threshold_lo_s = 0.0, tau_c_near_paper_threshold_hi_s = 0.0;
};

// T/16, T/8 (half a tooth period with 4 teeth: the default), T/6 (about -0.6), T/5, T/4, T/3, T/2, T, 2T.
std::vector<double> betaFrohStudyTauC(double sampling_period_s);
// The first-order threshold of the reading notes for K/(tau s + 1) sampled at T under beta-FROH.
double firstOrderZeroThreshold(double tau_c_s, double sampling_period_s);
// The tau_c whose zero threshold (closedLoopZeroThreshold with the settings' drive) equals target_beta, by
// bisection on log tau_c; InvalidInput unless target_beta is in (-1, -0.5), the thresholds' range.
double tauCForZeroThreshold(const AdaptiveControlSettings& settings, double target_beta);

// One J_c sweep (sweepBeta, both readings) per tau_c. InvalidInput for an empty or non-positive tau_c or bad
// settings; Cancelled through `job`, whose progress covers the whole study.
BetaFrohStudyResult betaFrohStudy(const AdaptiveControlSettings& base, const BetaFrohStudySettings& study,
                                  const JobControl& job = {});

}  // namespace mx

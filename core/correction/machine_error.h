// Identify, then compensate: the machine error E (its actual axes minus the commanded ones) that
// made the measured face when `run` was commanded, by nonlinear least squares on the simulated
// face: minimise |face(run + E) - measured|² over E, with the analytic Jacobian (Eqs. 13-16) at
// the current estimate. It is the identification (identification.h) with one parameter block:
// E in the directions of the identifiable space (structural_null_space.h), each a machine step,
// taken where the measurement shows them above the probe noise (direction_decision.h), decided at
// E = 0 and again at the solution.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "correction_options.h"
#include "ground_face.h"
#include "identified_axes.h"
#include "least_squares_options.h"
#include "outcome.h"
#include "earlier_passes.h"
#include "sharpening_setup.h"
#include "structural_null_space.h"

namespace hobsharp {

struct MachineErrorEstimate {
  IdentifiableSpace space;
  AxisPolynomials error;  // E, coefficient by coefficient; zero where not identified
  Eigen::VectorXd coefficientError;  // E of space.coefficients, in their units
  // Covariance of coefficientError per unit probe variance (sigma = 1 µm): (J^T J)^-1 mapped to
  // the coefficients, at the solution. Times sigma² it is the covariance.
  Eigen::MatrixXd covariancePerNoise;
  // The face's normal sensitivities at the solution over space.coefficients (µm per unit), p x q,
  // and the columns of what was identified alongside (the wheel's directions taken), p x k: what
  // the face tells of each axis is judged from them (identified_axes.h).
  Eigen::MatrixXd jacobian, nuisance;
  // The face's information over the directions sought, decomposed once by the identification
  // (identified_axes.h, StepDecomposition): at E, where it decided its directions there
  // (identification.h, firstBlockAtSolution), and at the run face (E = 0, where it started:
  // firstBlockAtStart) where E was found from there and not sought over every coefficient. Empty
  // where none was made, and where E is sought over several faces.
  StepDecomposition atSolution, atRun;
  // With the wheel alongside (wheel_error.h): q x m, the axis changes (coefficient units) that make,
  // to first order, the face of each wheel shape the wheel left to the axes. The face cannot tell
  // such a shape from its axis change; the bound samples them (face_prediction.h).
  Eigen::MatrixXd mimicking;
  GroundFace face;            // face(run + E), with its sensitivities
  Eigen::MatrixXd explained;  // its normal deviation, µm
  Eigen::MatrixXd unexplained;  // measured - explained: noise and what no axis makes, µm
  // The singular values of the identifiable space's Jacobian at E = 0, in µm of face per machine
  // step, largest first, and which of them the measurement shows above the noise.
  Eigen::VectorXd singularValues;
  std::vector<bool> used;
  int withinNoise = 0;  // directions of the space the measurement does not show above the noise
  int amplifying = 0;   // directions left out because their step would be wild (spanAmplification)
  LeastSquaresSummary summary;
  // The earlier passes whose faces E explains together with this one (identifyMachineError with a
  // history), and, when there were earlier passes but E is this face's alone, why (a sentence).
  int passesJoined = 0;
  // The structural null space's combinations sought all the same, by the free search on this face
  // (structuralFreed) or over the pass history's faces (passesJoined): what one face does not show
  // to first order. space.structural is then empty (nothing left out).
  std::vector<UnobservableCombination> soughtAllTheSame;
  // The structural null space freed on this face alone: the identification over the identifiable
  // space did not explain the face to the noise, and E sought over every free coefficient from
  // there does (the second-order change shows those directions). The bound then samples what the
  // sensitivities at E do not show (face_prediction.h).
  bool structuralFreed() const { return passesJoined == 0 && !soughtAllTheSame.empty(); }
  // When joined: the sensitivities of every face at E (all their points x q), and the data E
  // explains there, linearised: every face's misfit left plus historyJacobian * E (µm). What is
  // read of each axis (identified_axes.h) rests on all the faces, as E does.
  Eigen::MatrixXd historyJacobian;
  Eigen::VectorXd historyLinearised;
  std::string historyLeftOut;  // when joined: which earlier passes were left out and why, or ""
  std::string historyNote;
};

// The error the run compensates, E0 = nominal - run, at the coefficients cs (their units): each
// pass proposes nominal - E, so a later pass's run is nominal - E of the pass before, and E0 is
// where its search for E starts (the history's here, the wheel's in wheel_error.h).
Eigen::VectorXd errorCompensated(const AxisPolynomials& nominal, const AxisPolynomials& run,
                                 const std::vector<Coefficient>& cs);

// On a grid, an identification that ends above the noise with a structural null space left out is
// sought once more over every free coefficient, started at its E, and kept when it converges
// (structuralFreed). With a `history` of earlier passes measured on the grid, E is then sought once more over every
// free coefficient (the structural null space too) so that it explains every pass's face together,
// started at E0 = history.nominal - run (the error the run compensates), then at this face's own
// E, then at E0 with the trust region in machine steps (machine_error.cpp); that E is kept when it
// explains all of them to the probe noise (a converged solve), else this face's own E stands and
// `historyNote` says why. The history's axes are those its faces were ground with, as `run` is.
Outcome<MachineErrorEstimate> identifyMachineError(const SharpeningSetup& setup, const AxisPolynomials& run,
                                                   const GroundFace& runFace, const Eigen::MatrixXd& measured,
                                                   const CorrectionOptions& options,
                                                   const PassHistory* history = nullptr);

}  // namespace hobsharp

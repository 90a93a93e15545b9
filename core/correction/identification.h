// The one identification (docs/method.md, "Correction"; issue 20, item 2): the values of parameter blocks
// (the machine's axis error; the wheel's deviation from the case's wheel; later index errors) that
// together made the measured face, by nonlinear least squares on the simulated face:
//   minimise |face(x_1 .. x_B) - measured|² over the blocks' values x_b,
// with the analytic Jacobian of each block at the current estimate (Eqs. 13-16 for the axes,
// wheel_offset_sensitivity.h for the wheel).
//
// Each block is sought only in the directions the measurement shows (direction_decision.h),
// decided on the linearisation at the current estimate, block by block in order, each off the face
// directions the blocks before it took: a later block holds only the shape the earlier ones cannot
// make. Then one Levenberg-Marquardt solve (levenberg_marquardt.h) over all decided directions, and
// the directions decided again at its solution (at most kDecisionRounds times). A trial step whose
// face cannot be ground is a rejected step; the best iterate comes back with its status.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "correction_options.h"
#include "direction_decision.h"
#include "ground_face.h"
#include "least_squares_options.h"
#include "outcome.h"

namespace hobsharp {

// How often the directions are decided: at the start, then at each solution while they change.
constexpr int kDecisionRounds = 3;

// One kind of unknown. Its value x (in its own units: the axes' coefficients in mm or rad per
// (rad or mm)^k, the wheel's offset at its knots in µm) is directions * z, where z is in the units
// the decision judges (a machine step of each identifiable direction; a µm of wheel).
struct ParameterBlock {
  Eigen::MatrixXd directions;  // n x m: the block's free directions, per unit of z
  Wild wild = Wild::TakenWhenNeeded;
  // The value (own units, n) the start face already holds, when the search starts at an estimate:
  // the directions are decided on what the whole error makes (the data linearised at the start plus
  // J times this), not on the misfit left at the start alone, of which a start near the solution
  // leaves little (a few directions taken, the rest "unseen" to the bound and the words). Empty: 0.
  Eigen::VectorXd startValue;

  static ParameterBlock free(int n, Wild wild) { return {Eigen::MatrixXd::Identity(n, n), wild, Eigen::VectorXd()}; }
};

// What the identification asks of the face; x holds each block's value in its own units.
struct FaceModel {
  // The face at x without sensitivities (a trial step needs only its deviations), or why not.
  std::function<Outcome<GroundFace>(const std::vector<Eigen::VectorXd>& x)> simulate;
  // Gives `face`, simulated at x, its sensitivities; false where its envelope equations are singular.
  std::function<bool(GroundFace& face, const std::vector<Eigen::VectorXd>& x)> addSensitivities;
  // Block b's Jacobian at `face` (which has its sensitivities): points x n, µm per unit of x_b.
  std::function<Eigen::MatrixXd(const GroundFace& face, int block)> jacobian;
};

// The words the summary uses for what the blocks make ("the axes", "the axes or the wheel") and
// for the gradient's sentence ("no identified axis direction").
struct IdentificationWords {
  std::string makers;
  std::string none;
};

struct BlockDirections {
  // The singular values of the block's columns off the earlier blocks' taken span, per unit of z
  // (µm of face per machine step, per µm of wheel), largest first; which were taken, and why not.
  Eigen::VectorXd singularValues;
  DirectionDecision decision;
  Eigen::MatrixXd taken;  // n x k: the taken directions in the block's own units (x = taken * theta)
};

// A block's columns decomposed (the SVD of the triangular factor of jacobian * directions).
struct BlockDecomposition {
  Eigen::VectorXd singularValues;  // µm of face per unit of z, largest first
  Eigen::MatrixXd V;               // n x m: the right singular vectors in the block's own units (directions * V)
  bool empty() const { return singularValues.size() == 0; }
};

struct Identification {
  std::vector<Eigen::VectorXd> value;  // per block, its own units; zero where nothing was taken
  std::vector<BlockDirections> blocks;  // as decided in the last round that was solved
  GroundFace face;                      // face(value); with its sensitivities unless stalled without them
  Eigen::VectorXd explained;            // its normal deviation per point, µm
  // Per block, its Jacobian at the solution (the last one formed when the solution has none):
  // points x n, µm per unit of x_b.
  std::vector<Eigen::MatrixXd> jacobian;
  // Covariance of the taken coordinates theta (the blocks' in order) per unit probe variance
  // (sigma = 1 µm): (J^T J)^-1 at the solution, J = [jacobian_b * taken_b]. Empty if none taken.
  Eigen::MatrixXd thetaCovariancePerNoise;
  // The first block's columns decomposed (the first block is decided off no other, so this is the
  // face's information over its directions, made once where the directions are decided): at the
  // start face (the first decision's; empty if the block has no directions), and at the solution,
  // where the directions were decided again at the face the solution is (a decision that stood);
  // empty where the last decision was made at another face.
  BlockDecomposition firstBlockAtStart, firstBlockAtSolution;
  LeastSquaresSummary summary;

  // Block b's covariance in its own units, per unit probe variance (the others free): n x n.
  Eigen::MatrixXd covariancePerNoise(int b) const;
};

// start: the face at x = 0, with its sensitivities; measured: per point, µm, in the face's order.
Outcome<Identification> identify(const FaceModel& model, const GroundFace& start, const Eigen::VectorXd& measured,
                                 const std::vector<ParameterBlock>& blocks, const CorrectionOptions& options,
                                 const IdentificationWords& words);

}  // namespace hobsharp

// What the face identifies of the machine error, axis by axis, in the engineer's words (docs/method.md,
// "Correction"; docs/conventions.md §What the engineer reads about the machine).
//
// The face does not see each axis alone: some combinations of axes grind nearly the same face (on
// a helical gash X and A exactly, on the paper's hob Y with Z, A and B nearly), and the identified
// error splits such a combination among its axes by the smallest machine move, not by what the
// machine did. So the axes are judged from the information the face holds about them, over every
// direction it shows (its Jacobian at the identified error; a wheel identified alongside taken out):
//   - unseen: the face does not move when the axis alone moves (a straight gash's X, Y and B);
//   - alone: the face tells the axis from any mix of the others (the multiple correlation of its
//     curve with theirs below AxisReadingOptions::maxCorrelation over the motion range, nothing of
//     it in a combination the face cannot see) and sharply (its standard uncertainty at most
//     maxUncertaintySteps machine steps): its error is read on its own, with its uncertainty;
//   - together: otherwise. The axes read together are grouped by their correlation (and the
//     combinations the face cannot see), and each group is read as the member that alone grinds the
//     face shown best ("Y-equivalent": the error of that axis alone that grinds what the face shows
//     of the group), with the proportion in which the others grind alike, and the value each other
//     member would take alone where it grinds the face as well to within the noise.
// The values read (alone, and each group's equivalent) come from one linear least-squares fit of
// those axes' curves to what the machine error makes (the caller's S and data: on one face, the
// measured change at the axes run with the run face's sensitivities), with the other axes held at
// zero: a fit with no decision in it, so its covariance is the spread the probe noise gives it
// (sigma² (J^T J)^-1), and the uncertainty is that per µm of noise times sigma.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "axis_polynomials.h"
#include "coefficient.h"
#include "correction_options.h"

namespace hobsharp {

enum class AxisReading { Alone, Together, Unseen, Locked };
const char* readingName(AxisReading r);  // "alone", "together", "unseen", "locked"

struct AxisIdentification {
  AxisReading reading = AxisReading::Locked;
  // Alone: the axis's error read on its own, its mean over the motion range, µm (X, Y, Z) or µrad
  // (A, B), and that value's standard uncertainty per µm of probe noise. 0 otherwise.
  double value = 0, perNoise = 0;
  // Alone: how far the error's second-order face may move the value (µm or µrad; 0 unless read
  // with a second-order part, identifiedAxes).
  double secondOrder = 0;
  // Over every direction the face shows: the standard deviation of the axis's curve per µm of
  // noise (largest over the range; of the part the face can see) and its multiple correlation with
  // the other axes' curves (largest over the range; 1 when part of it is a combination the face
  // cannot see).
  double spreadPerNoise = 0, correlation = 0;
};

struct AxisCombination {
  std::vector<Axis> axes;  // the first is the axis the combination is read as
  // Per +1 µm or µrad (constant) on the first axis: each other axis's curve that grinds nearly the
  // same face (its mean over the range, µm or µrad), and the share of that face they grind.
  std::vector<double> amounts;
  double alike = 0;
  // The first axis's error that alone grinds what the face shows of the group, its mean over the
  // range, and that value's standard uncertainty per µm of noise.
  double value = 0, perNoise = 0;
  double secondOrder = 0;  // how far the error's second-order face may move the value (as AxisIdentification's)
  // Per member, in the order of `axes`: the error of that axis alone that grinds what the face
  // shows of the group (its mean over the range) with its standard uncertainty per µm of noise, and
  // whether it grinds it as well as the first to within the noise (its misfit at most
  // significance² sigma² above): the sentence names those, what the face shows were the error on
  // that axis.
  std::vector<double> aloneValue, alonePerNoise, aloneSecondOrder;
  std::vector<bool> aloneListed;
  std::string sentence;
};

struct IdentifiedAxes {
  std::array<AxisIdentification, kAxisCount> axes{};
  std::vector<AxisCombination> combinations;
  std::vector<Axis> unseen;
  // One sentence per combination, then one for the unseen axes (if any).
  std::vector<std::string> sentences;
  // Per axis, the standard deviation of its curve per µm of noise over every direction the face
  // shows (the identified error and the change proposed have no part the face cannot see).
  std::array<double, kAxisCount> spreadPerNoise{};
};

// The face's sensitivities times the machine steps, decomposed over the directions sought (made
// already, by the identification): the singular values, largest first (µm of face per machine
// step), and the right singular vectors, q x m, orthonormal in machine steps.
struct StepDecomposition {
  Eigen::VectorXd singularValues;
  Eigen::MatrixXd directions;
  bool empty() const { return directions.cols() == 0; }
};

// Per axis, the standard deviation of its curve per µm of noise over every direction the face
// shows among those sought (the space `basis` spans; every coefficient without one), largest over
// [rangeMin, rangeMax]: the spread an error identified with the sensitivities S (at that error) has,
// where identifiedAxes reads the face with the run's (measured_face_correction.cpp). The arguments
// as identifiedAxes's; equal to its spreadPerNoise for the same S where the basis is whole
// coefficients (a straight gash's), or S shows nothing outside it.
std::array<double, kAxisCount> axisSpreadPerNoise(const std::vector<Coefficient>& coefficients, const Eigen::VectorXd& step,
                                                  const Eigen::MatrixXd& S, const Eigen::MatrixXd& nuisance,
                                                  double rangeMin, double rangeMax,
                                                  const Eigen::MatrixXd& basis = Eigen::MatrixXd());

// The same from a decomposition made already (MachineErrorEstimate::atSolution).
std::array<double, kAxisCount> axisSpreadPerNoise(const std::vector<Coefficient>& coefficients, const Eigen::VectorXd& step,
                                                  const StepDecomposition& made, double rangeMin, double rangeMax);

// coefficients: the free coefficients; step: each one's machine step (coefficientStep);
// S: p x q normal sensitivities (µm per coefficient unit): the run face's, or at the identified
// error; nuisance: p x k columns identified alongside (the wheel's), taken out first (k may be 0);
// data: what the machine error makes (µm): the measured face less the run face's, or linearised at
// the identified error (the misfit left plus S times the error); [rangeMin, rangeMax]: the motion
// range; probeNoise: sigma, µm; basis: the identifiable space's basis over the coefficients
// (IdentifiableSpace::basis), whose coefficients outside it (a straight gash's X, Y, B) the face
// does not show; empty: judged from S alone. made: S's decomposition over basis made already (no
// nuisance; MachineErrorEstimate::atRun), or null: S is decomposed here. secondOrder: the part of
// `data` the identified error's face holds beyond its first order (µm per point: the face at E less
// the run face less S E), or null: each value read also reads it, and twice that is how far the
// error's second order may move the value (the values' secondOrder fields).
IdentifiedAxes identifiedAxes(const std::vector<Coefficient>& coefficients, const Eigen::VectorXd& step,
                              const Eigen::MatrixXd& S, const Eigen::MatrixXd& nuisance, const Eigen::VectorXd& data,
                              double rangeMin, double rangeMax, double probeNoise, const CorrectionOptions& options,
                              const Eigen::MatrixXd& basis = Eigen::MatrixXd(), const StepDecomposition* made = nullptr,
                              const Eigen::VectorXd* secondOrder = nullptr);

// The sentence after the unseen axes' where the proposal changes them at all: their change (µm or
// µrad, largest over the motion range) only takes the run back to the nominal axes, which the face
// neither asks for nor shows. `changed`: the unseen axes whose change is above half a machine step
// and whose proposal is the nominal motion; "" when there are none.
std::string backToNominalSentence(const std::vector<Axis>& changed, const std::array<double, kAxisCount>& change);

}  // namespace hobsharp

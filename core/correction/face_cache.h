// The face at the solver's parameters x, for the identification's Levenberg-Marquardt residuals
// (machine_error.cpp, wheel_error.cpp): simulated once per x, since the solver asks for the
// residual and then the Jacobian at the same x. A face the wheel cannot grind is counted and
// gives a residual so large that the trial step is always rejected (the trust region shrinks).
#pragma once

#include <optional>
#include <utility>

#include <Eigen/Core>

#include "face_vectors.h"
#include "ground_face.h"

namespace hobsharp {

constexpr double kUnsolvableResidual = 1e12;  // µm

struct FaceCache {
  Eigen::VectorXd lastX;
  std::optional<GroundFace> lastFace;
  int evaluations = 0, unsolvable = 0;

  // simulate(x) -> Outcome<GroundFace>; nullptr when the wheel cannot grind the face at x.
  template <class Simulate>
  const GroundFace* at(const Eigen::VectorXd& x, Simulate simulate) {
    if (lastFace && lastX.size() == x.size() && lastX == x) return &*lastFace;
    ++evaluations;
    auto f = simulate(x);
    lastX = x;
    if (!f) {
      ++unsolvable;
      lastFace.reset();
      return nullptr;
    }
    lastFace = std::move(f).value();
    return &*lastFace;
  }
};

// The residual face(x) - measured, µm, or the rejecting constant where there is no face.
inline void faceResidual(const GroundFace* f, const Eigen::VectorXd& measured, Eigen::VectorXd& fvec) {
  if (f) fvec = faceNormal(*f) - measured;
  else fvec.setConstant(measured.size(), kUnsolvableResidual);
}

}  // namespace hobsharp

#include "measured_face.h"

#include <cmath>
#include <utility>

#include "grid_words.h"
#include "grid_input.h"
#include "number_text.h"

namespace hobsharp {

const char* sourceName(FaceSource s) {
  switch (s) {
    case FaceSource::Measured: return "measured";
    case FaceSource::MeasuredPoints: return "measuredPoints";
    case FaceSource::Simulated: return "simulated";
  }
  return "simulated";
}

MeasuredFace MeasuredFace::onGrid(Eigen::MatrixXd measured) {
  MeasuredFace f;
  f.source = FaceSource::Measured;
  f.grid = std::move(measured);
  return f;
}

Outcome<void> checkMeasured(const Eigen::MatrixXd& m, const FaceGrid& grid, const std::string& name) {
  if (m.rows() != grid.rows() || m.cols() != grid.cols())
    return Error{name, gridWords(name) + ": needs " + std::to_string(grid.rows()) + " rows (the radial grid lines) of " +
                           std::to_string(grid.cols()) + " values (the axial grid lines); got " + std::to_string(m.rows()) +
                           " x " + std::to_string(m.cols()) + ".",
                 ErrorCode::InvalidInput};
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j)
      if (!std::isfinite(m(i, j)) || std::abs(m(i, j)) > kMaxDeviation)
        return Error{name + "[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                     gridRowWords(name, i) + " (r = " + numberText(grid.r[i]) + " mm), value " + std::to_string(j + 1) +
                         " (x = " + numberText(grid.x[j]) + " mm): " +
                         (std::isfinite(m(i, j)) ? "must lie within ±" + numberText(kMaxDeviation) + " µm (10 mm); got " +
                                                       exactText(m(i, j)) + " µm."
                                                 : std::string("must be a finite number.")),
                     ErrorCode::InvalidInput};
  return success();
}

Outcome<MeasuredFace> measuredFace(const std::optional<Eigen::MatrixXd>& measured,
                                   const std::optional<std::vector<MeasuredPoint>>& measuredPoints, const FaceGrid& grid,
                                   const PointRegion& region) {
  MeasuredFace face;
  if (measured) {
    if (auto r = checkMeasured(*measured, grid, "measured"); !r) return r.error();
    face = MeasuredFace::onGrid(*measured);
  }
  if (!measuredPoints) return face;
  if (measured) return refusePoints("measuredPoints", "give the measurement as a grid or as points, not both.");
  if (auto ok = checkPoints(*measuredPoints, region); !ok) return ok.error();
  face.source = FaceSource::MeasuredPoints;
  if (auto m = gridFromPoints(*measuredPoints, grid, kGridTolerance)) {
    face.grid = std::move(m);  // the points are the grid's positions (docs/measured-points.md)
  } else {
    face.probes = probePointsOf(*measuredPoints);
    face.deviations = deviationsOf(*measuredPoints);
  }
  return face;
}

}  // namespace hobsharp

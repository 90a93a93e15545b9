// Shared helpers of the native tests: the paper's example and its pieces.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "case_json.h"
#include "evaluation.h"
#include "sharpening_job.h"

namespace hobsharp::test {

inline std::string readFile(const std::string& name) {
  std::ifstream f(std::string(HOBSHARP_TEST_DATA) + "/" + name);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// The case of Tab. 1 as printed (E_t = 69.446, gamma_m = 12.626 deg), read from its file.
inline CaseInput paperCase() {
  auto c = parseCase(readFile("tab1.json"));
  EXPECT_TRUE(c.ok()) << (c.ok() ? "" : c.error().message);
  return c.value();
}

// A changed hob takes its setup from itself: the setting angle and the centre distance derived
// (Tab. 1's printed values fit only the paper's hob).
inline CaseInput withDerivedSetup(CaseInput c) {
  c.settingAngle.reset();
  c.centerDistance.reset();
  return c;
}

// The paper's hob with a straight gash (no gash lead), its setup derived.
inline CaseInput straightGashCase() {
  CaseInput c = paperCase();
  c.hob.gash = GashKind::Straight;
  c.hob.gashLead.reset();
  return withDerivedSetup(c);
}

inline SharpeningJob jobOf(const CaseInput& c) {
  auto j = resolveJob(c);
  EXPECT_TRUE(j.ok()) << (j.ok() ? "" : j.error().message);
  return j.value();
}

inline GroundFace groundFaceOf(const SharpeningJob& job, const AxisPolynomials& axes) {
  auto f = simulateGroundFace(job.setup, axes, job.grid);
  EXPECT_TRUE(f.ok()) << (f.ok() ? "" : f.error().message);
  return f.value();
}

inline Topography topographyFor(const SharpeningJob& job, const AxisPolynomials& axes) {
  return topographyOf(groundFaceOf(job, axes));
}

}  // namespace hobsharp::test

// The paper's example, Tab. 1 (the same case as tests/data/tab1.json; a test keeps them equal).
var HOBSHARP_PAPER_CASE = {
  "format": "hobsharp-case/1",
  "hob": {
    "normalModule": 7.0,
    "normalPressureAngle": 20.0,
    "outerDiameter": 80.0,
    "pitchDiameter": 62.5,
    "gashDepth": 21.0,
    "length": 140.0,
    "rakeOffset": 0.0,
    "gash": "helical",
    "hand": "right",
    "gashLead": 876.56
  },
  "wheel": {
    "outerDiameter": 100.0
  },
  "setup": {
    "tilt": 15.0,
    "settingAngle": 12.626,
    "centerDistance": 69.446
  },
  "machine": {
    "K1": 100.0,
    "K2": 10.0
  },
  "degree": 4,
  "grid": {
    "radial": 5,
    "axial": 9,
    "rMin": 19.0,
    "rMax": 40.0,
    "xMin": -70.0,
    "xMax": 70.0
  }
};

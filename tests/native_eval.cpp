// The native side of the native-versus-WebAssembly comparison (tests/js/module.test.mjs):
// evaluates a case file with the native build and prints the result as JSON, one line, in the
// JS API's names and shapes (core/result_model.h). On bad input: the message on stderr, exit 1.
#include <fstream>
#include <iostream>
#include <sstream>

#include "result_model.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: hobsharp_native_eval case.json\n";
    return 2;
  }
  std::ifstream f(argv[1]);
  if (!f) return std::cerr << argv[1] << ": no such file\n", 1;
  std::stringstream text;
  text << f.rdbuf();
  auto e = hobsharp::evaluateCase(text.str());
  if (!e) return std::cerr << e.error().message << "\n", 1;
  std::cout << hobsharp::resultJson(*e) << "\n";
  return 0;
}

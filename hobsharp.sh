#!/usr/bin/env bash
# HobSharp's one entry point. On a fresh Debian 12 machine:
#   ./hobsharp.sh serve   install what is missing, build, and serve the calculator on localhost
#   ./hobsharp.sh test    install what is missing, build everything, and run every test
#                         (what CI runs, .ci/run)
#   ./hobsharp.sh test --quick
#                         a developer's quicker loop: the same, without the sanitizer build, the
#                         tests under ASan + UBSan and the fuzzing (docs/testing.md)
#   ./hobsharp.sh bench   build and run the benchmarks
#   ./hobsharp.sh validate [--scenarios N] [--seed S] [--docs] [--index I [--cases DIR]]
#                         the validation campaign on random hobs (docs/validation.md); --docs
#                         writes its table, JSON and plot into docs/validation/
#   ./hobsharp.sh validate --calibration [--hobs H] [--seed S] [--error-scale K] [--offsets-only] [--bootstrap B] [--docs]
#                         the calibration of the values read about the machine (calibration.json)
set -euo pipefail
cd "$(dirname "$0")"
ROOT=$PWD
BUILD=$ROOT/build/native
JOBS=$(nproc)

BUILD_WASM=$ROOT/build/wasm
SITE=$BUILD_WASM/site

APT_PACKAGES=(cmake g++ make libeigen3-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev python3
              emscripten chromium poppler-utils
              clang-14 libclang-rt-14-dev)  # the sanitizer build and libFuzzer (in libclang-rt-14-dev)

# The sanitizer build: Debian's clang with ASan + UBSan, the native tests and the case fuzzer.
BUILD_SANITIZE=$ROOT/build/sanitize
FUZZ_SECONDS=${FUZZ_SECONDS:-60}


as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

install_missing() {
  local missing=()
  for p in "${APT_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  command -v node >/dev/null && command -v npm >/dev/null || missing+=(nodejs npm)
  if [ ${#missing[@]} -gt 0 ]; then
    echo "== installing: ${missing[*]}"
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
  fi
}

install_npm() {
  # A node_modules that is a link belongs to another work tree: npm ci would empty it under that tree.
  if [ -L node_modules ] && [ -d node_modules/plotly.js ] && [ -d node_modules/esbuild ] && [ -d node_modules/playwright-core ]; then
    return
  fi
  if [ ! -d node_modules/plotly.js ] || [ ! -d node_modules/esbuild ] || [ ! -d node_modules/playwright-core ] ||
     [ package-lock.json -nt node_modules/.package-lock.json ]; then
    echo "== npm ci"
    npm ci --no-audit --no-fund
  fi
}

build_wasm() {
  emcmake cmake -S "$ROOT" -B "$BUILD_WASM" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$BUILD_WASM" -j"$JOBS"
}

build_native() {
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$BUILD" -j"$JOBS"
}

build_sanitize() {
  cmake -S "$ROOT" -B "$BUILD_SANITIZE" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DHOBSHARP_SANITIZE=ON -DHOBSHARP_FUZZ=ON >/dev/null
  cmake --build "$BUILD_SANITIZE" -j"$JOBS" --target hobsharp_tests hobsharp_validation_tests hobsharp_oracle_tests fuzz_case
}

# Halt at the first report of either sanitizer, with a stack; leaks count too.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}

# libFuzzer on a copy of the seed corpus (the repository is not written). Any crash, sanitizer
# report, broken check in tests/fuzz/fuzz_case.cpp, or input slower than 30 s fails the run.
run_fuzzer() {
  local dir=$BUILD_SANITIZE/fuzz
  rm -rf "$dir" && mkdir -p "$dir/artifacts" && cp -r tests/fuzz/corpus "$dir/corpus"
  if "$BUILD_SANITIZE/tests/fuzz/fuzz_case" -dict=tests/fuzz/case.dict -max_len=16384 -timeout=30 \
       -max_total_time="$FUZZ_SECONDS" -print_final_stats=1 -artifact_prefix="$dir/artifacts/" \
       "$dir/corpus" >"$dir/log" 2>&1; then
    grep -E '^Done [0-9]+ runs|^stat::(new_units_added|peak_rss_mb)' "$dir/log"
  else
    tail -n 80 "$dir/log"
    echo "FAILED: the fuzzer found an input that breaks the case reader; it is in $dir/artifacts/" >&2
    return 1
  fi
}

# Runs a step and says how long it took.
timed() {
  local start=$SECONDS
  "$@" || return
  echo "   ($(( SECONDS - start )) s)"
}

case "${1:-}" in
  serve)
    install_missing
    install_npm
    build_wasm
    PORT=${PORT:-8080}
    echo "== HobSharp at http://localhost:$PORT/ (Ctrl-C stops it)"
    # With a desktop, open it in Chromium (installed above) once the server answers.
    if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && command -v chromium >/dev/null; then
      (sleep 1; chromium "http://localhost:$PORT/" >/dev/null 2>&1 &)
    fi
    exec python3 -m http.server "$PORT" --bind 127.0.0.1 --directory "$SITE"
    ;;
  test)
    QUICK=
    case "${2:-}" in
      "") ;;
      --quick) QUICK=1 ;;
      *) echo "usage: $0 test [--quick]" >&2; exit 2 ;;
    esac
    install_missing
    install_npm
    timed build_native
    timed build_wasm
    echo "== native tests (GoogleTest via CTest)"
    (cd "$BUILD" && timed ctest --output-on-failure -j"$JOBS")
    echo "== module and command-line tests (node --test)"
    timed node --test tests/js/
    echo "== browser tests (playwright-core, Debian's Chromium; screenshots in test-output/browser/)"
    timed node --test tests/browser/
    if [ -n "$QUICK" ]; then
      echo "== --quick: no sanitizer build, no tests under ASan + UBSan, no fuzzing (./hobsharp.sh test runs them)"
      exit 0
    fi
    echo "== sanitizer build (clang, ASan + UBSan) in build/sanitize"
    timed build_sanitize
    echo "== native tests under ASan + UBSan (halt at the first report)"
    (cd "$BUILD_SANITIZE" && timed ctest --output-on-failure -j"$JOBS")
    echo "== fuzzing the case reader for ${FUZZ_SECONDS} s (libFuzzer, ASan + UBSan; a finding fails)"
    timed run_fuzzer
    ;;
  bench)
    install_missing
    install_npm
    build_native
    build_wasm
    cmake --build "$BUILD_WASM" -j"$JOBS" --target hobsharp-bench_module
    "$BUILD/tests/hobsharp_bench" --benchmark_out="$BUILD/bench-native.json" --benchmark_out_format=json
    node tests/benchmark-wasm.mjs "$BUILD/bench-native.json"
    node tests/benchmark-page.mjs
    ;;
  validate)
    shift
    install_missing
    cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$BUILD" -j"$JOBS" --target hobsharp_validate
    OUT=$ROOT/build/validation
    ARGS=()
    for a in "$@"; do
      if [ "$a" = --docs ]; then OUT=$ROOT/docs/validation; else ARGS+=("$a"); fi
    done
    "$BUILD/tests/hobsharp_validate" --out "$OUT" "${ARGS[@]}"
    # --index I: one scenario's record, printed; --calibration: the values read, calibration.json.
    # No table, no plot.
    case " ${ARGS[*]} " in *" --index "* | *" --calibration "*) exit 0 ;; esac
    # The plot beside the table: Plotly from node_modules in Debian's Chromium (playwright-core).
    install_npm
    node tests/validation/plot.mjs "$OUT/validation.json"
    ;;
  *)
    echo "usage: $0 serve|test [--quick]|bench|validate" >&2
    exit 2
    ;;
esac

#!/usr/bin/env bash
# HobSharp's one entry point. On a fresh Debian 12 machine:
#   ./hobsharp.sh serve   install what is missing, build, and serve the calculator on localhost
#   ./hobsharp.sh test    install what is missing, build everything, and run every test
#   ./hobsharp.sh bench   build and run the benchmarks
set -euo pipefail
cd "$(dirname "$0")"
ROOT=$PWD
BUILD=$ROOT/build/native
JOBS=$(nproc)

BUILD_WASM=$ROOT/build/wasm
SITE=$BUILD_WASM/site

APT_PACKAGES=(cmake g++ make libeigen3-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev python3
              emscripten chromium)


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
    install_missing
    install_npm
    build_native
    build_wasm
    echo "== native tests (GoogleTest via CTest)"
    (cd "$BUILD" && ctest --output-on-failure -j"$JOBS")
    echo "== module and command-line tests (node --test)"
    node --test tests/js/
    echo "== browser tests (playwright-core, Debian's Chromium; screenshots in test-output/browser/)"
    node --test tests/browser/
    ;;
  bench)
    install_missing
    install_npm
    build_native
    build_wasm
    "$BUILD/tests/hobsharp_bench" --benchmark_out="$BUILD/bench-native.json" --benchmark_out_format=json
    node tests/benchmark-wasm.mjs "$BUILD/bench-native.json"
    node tests/benchmark-page.mjs
    ;;
  *)
    echo "usage: $0 serve|test|bench" >&2
    exit 2
    ;;
esac

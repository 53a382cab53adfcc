#!/usr/bin/env bash
# One entry point for newcomers and CI.
#   ./dev.sh demo            install what is missing, build, run the default study
#   ./dev.sh test            install what is missing, build, run the whole test suite
#   ./dev.sh test --sanitize the same under AddressSanitizer + UBSan (build-asan/)
#   ./dev.sh build           install + build only
#   ./dev.sh fuzz [SECONDS]  libFuzzer over every YAML input path for SECONDS (default 60),
#                            clang + ASan/UBSan in build-fuzz/ (docs/input_limits.md)
# Re-running is fast: packages already present are not touched, builds are incremental.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

PACKAGES=(build-essential cmake pkg-config libnlopt-cxx-dev coinor-libipopt-dev libeigen3-dev
          libgsl-dev libyaml-cpp-dev libsqlite3-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev gnuplot-nox)

# Only for ./dev.sh fuzz: clang and its libFuzzer runtime.
FUZZ_PACKAGES=(clang libclang-rt-14-dev)

install_missing() {  # install_missing [extra packages...]
  local missing=()
  for p in "${PACKAGES[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "dev.sh: installing ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}

JOBS=$(nproc 2>/dev/null || echo 2)

build() {  # build DIR [cmake args...]
  local dir=$1; shift
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRACKOPT_WERROR=ON "$@" >/dev/null
  cmake --build "$dir" -j "$JOBS" >&2
}

cmd=${1:-demo}; shift || true
case "$cmd" in
  build)
    install_missing; build build ;;
  demo)
    install_missing; build build
    ./build/rackopt run studies/rack_railway_sizing.yaml --out out/rack_railway_sizing --resume "$@" ;;
  test)
    install_missing
    if [ "${1:-}" = "--sanitize" ]; then
      build build-asan -DRACKOPT_SANITIZE=ON -DRACKOPT_BENCHMARKS=OFF
      ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        ctest --test-dir build-asan --output-on-failure -j "$JOBS"
    else
      build build
      ctest --test-dir build --output-on-failure -j "$JOBS"
    fi ;;
  fuzz)
    # Builds only the fuzz target (and the libraries it needs) with clang,
    # then fuzzes for a bounded time from the shipped problems and studies
    # (used in place, never copied). New inputs go to build-fuzz/corpus;
    # crashes to build-fuzz/artifacts (make each a file in
    # tests/fuzz/regressions/). A longer run: ./dev.sh fuzz 3600
    seconds=${1:-60}
    install_missing "${FUZZ_PACKAGES[@]}"
    CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRACKOPT_FUZZ=ON \
      -DRACKOPT_BENCHMARKS=OFF >/dev/null
    cmake --build build-fuzz -j "$JOBS" --target rackopt_input_fuzzer >&2
    mkdir -p build-fuzz/corpus build-fuzz/artifacts
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      ./build-fuzz/rackopt_input_fuzzer -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 \
        -timeout=10 -dict=tests/fuzz/input.dict -artifact_prefix=build-fuzz/artifacts/ \
        build-fuzz/corpus problems studies </dev/null ;;
  *)
    echo "usage: ./dev.sh demo|test [--sanitize]|build|fuzz [SECONDS]" >&2; exit 2 ;;
esac

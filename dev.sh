#!/usr/bin/env bash
# One entry point for newcomers and CI.
#   ./dev.sh demo            install what is missing, build, run the default study
#   ./dev.sh test            install what is missing, build, run the whole test suite
#   ./dev.sh test --sanitize the same under AddressSanitizer + UBSan, built with clang
#                            (build-asan/), then 60 s of the input and writer fuzzers
#   ./dev.sh build           install + build only
#   ./dev.sh python          install, build, and make `import rackopt` work for
#                            /usr/bin/python3 (a rackopt.pth in its user site;
#                            docs/python.md)
#   ./dev.sh fuzz [SECONDS]  libFuzzer over every YAML input path for SECONDS (default 600),
#                            clang + ASan/UBSan in build-asan/ (docs/input_limits.md)
# Re-running is fast: packages already present are not touched, builds are incremental.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

PACKAGES=(build-essential cmake pkg-config libnlopt-cxx-dev coinor-libipopt-dev libeigen3-dev
          libgsl-dev libyaml-cpp-dev libsqlite3-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev gnuplot-nox
          libgmsh-dev gmsh calculix-ccx libpagmo-dev openmpi-bin libopenmpi-dev libcli11-dev
          libcmark-gfm-dev libcmark-gfm-extensions-dev libfftw3-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
          chromium)
# chromium: only for the test that opens a study's report.html in a browser
# (ReportHtmlInChromium, about 4 s; skipped without it); 81 MB to download,
# about 300 MB installed, once (docs/output.md, "report.html").

# Only for the sanitizer build and ./dev.sh fuzz: clang and its libFuzzer runtime.
SANITIZE_PACKAGES=(clang libclang-rt-14-dev)

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

# -O2 with line tables only (-g1): backtraces, profilers and sanitizer-style
# reports keep file:line, and the build takes about a third less time than
# with full debug info (docs/performance.md, "CI"). For a debugger session
# with variables, configure a folder of your own with -DCMAKE_BUILD_TYPE=Debug.
# CMAKE_TARGET=name builds that target (and what it needs) only.
build() {  # build DIR [cmake args...]
  local dir=$1; shift
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
    -DRACKOPT_WERROR=ON "$@" >/dev/null
  cmake --build "$dir" -j "$JOBS" ${CMAKE_TARGET:+--target "$CMAKE_TARGET"} >&2
}

# The sanitizer build uses clang: it also builds the libFuzzer target, which
# shares its objects. It leaves out the MPI executor: OpenMPI's own
# allocations at MPI_Init read as leaks to LeakSanitizer; the plain build
# runs the MPI tests (two ranks against a serial run). -O1 with line tables only (the sanitizers' advice):
# reports keep file:line, and it builds faster than full debug info at -O2
# (docs/performance.md, "CI").
build_sanitized() {
  CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRACKOPT_WERROR=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
    -DRACKOPT_SANITIZE=ON -DRACKOPT_FUZZ=ON -DRACKOPT_BENCHMARKS=OFF -DRACKOPT_MPI=OFF >/dev/null
  cmake --build build-asan -j "$JOBS" ${CMAKE_TARGET:+--target "$CMAKE_TARGET"} >&2
}

# fuzz SECONDS: two thirds of the time the input fuzzer from the shipped
# problems and studies (read in place, never copied), one third the writer
# fuzzer (user text into plot scripts, report.md, report.html) from
# tests/fuzz/writer_corpus; a fixed seed so a CI failure repeats. New inputs
# go to build-asan/fuzz-corpus and build-asan/writer-corpus, crashes to
# build-asan/fuzz-artifacts (make each a file in tests/fuzz/regressions/ or
# tests/fuzz/writer_corpus/).
fuzz() {
  local writer_seconds=$(( $1 / 3 ))
  local input_seconds=$(( $1 - writer_seconds ))
  cmake --build build-asan -j "$JOBS" --target rackopt_writer_fuzzer >&2
  mkdir -p build-asan/fuzz-corpus build-asan/writer-corpus build-asan/fuzz-artifacts
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ./build-asan/rackopt_input_fuzzer -seed=1 -max_total_time="$input_seconds" -max_len=65536 -rss_limit_mb=2048 \
      -timeout=10 -dict=tests/fuzz/input.dict -artifact_prefix=build-asan/fuzz-artifacts/ \
      -print_final_stats=1 build-asan/fuzz-corpus problems studies </dev/null
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ./build-asan/rackopt_writer_fuzzer -seed=1 -max_total_time="$writer_seconds" -max_len=4096 -rss_limit_mb=2048 \
      -timeout=10 -artifact_prefix=build-asan/fuzz-artifacts/writer- \
      -print_final_stats=1 build-asan/writer-corpus tests/fuzz/writer_corpus </dev/null
}

cmd=${1:-demo}; shift || true
case "$cmd" in
  build)
    install_missing; build build ;;
  demo)
    # The program only (and the pagmo module it opens): the tests, benchmarks
    # and Python module are most of a full build and the demo runs none of them.
    install_missing; CMAKE_TARGET=rackopt_cli build build
    ./build/rackopt run studies/rack_railway_sizing.yaml --out out/rack_railway_sizing --resume "$@" ;;
  test)
    install_missing
    if [ "${1:-}" = "--sanitize" ]; then
      install_missing "${SANITIZE_PACKAGES[@]}"
      build_sanitized
      # Left to the plain build (./dev.sh test), where they also run:
      #  - the study acceptance tests re-solve whole shipped studies (minutes
      #    under ASan); the study, runner and CLI tests cover their code;
      #  - three FE tests whose time is CalculiX's own (not instrumented): the
      #    whole-span rack, the CLI's real solve and the small-drive position.
      #    The FE code they run is the same deck, placement and result reading
      #    that FeShapeAndExtendedContact and MeshPositionFe.AMissedLoad...
      #    run under the sanitizers here;
      #  - the browser's look at report.html: its time is Chromium's own; the
      #    page it opens is built by the ReportHtml tests that run here.
      ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        ctest --test-dir build-asan --output-on-failure -j "$JOBS" \
          -E '^(StudyAcceptance\.|RackOnSupportsFe\.MeshPositionOnTheSupportsAtMidSpan$|FeCli\.RealSolvesOnTheGantryDriveAtLevelZero$|MeshPositionFe\.SmallDriveInvariantsAndTheAnalyticModel$|ReportHtmlInChromium\.)'
      fuzz 60
    else
      build build
      # The long CalculiX solves (label long_fe) run last, on their own: under
      # the load of the rest of the suite they would take several times their
      # idle minutes.
      ctest --test-dir build --output-on-failure -j "$JOBS" -LE long_fe
      echo "dev.sh: the rest passed; now the long FE solves (label long_fe, about 5 min on an idle 2-core machine)" >&2
      ctest --test-dir build --output-on-failure -j "$JOBS" -L long_fe
    fi ;;
  python)
    install_missing; build build
    # The build folder on the system interpreter's path, through its user
    # site: every later rebuild is picked up, and deleting the file undoes it.
    site=$(/usr/bin/python3 -m site --user-site)
    mkdir -p "$site"
    echo "$PWD/build/python" > "$site/rackopt.pth"
    /usr/bin/python3 -c 'import rackopt; print("import rackopt works: rackopt", rackopt.__version__, "from", rackopt.__file__)' ;;
  fuzz)
    install_missing "${SANITIZE_PACKAGES[@]}"
    CMAKE_TARGET=rackopt_input_fuzzer build_sanitized
    fuzz "${1:-600}" ;;
  *)
    echo "usage: ./dev.sh demo|test [--sanitize]|build|python|fuzz [SECONDS]" >&2; exit 2 ;;
esac
